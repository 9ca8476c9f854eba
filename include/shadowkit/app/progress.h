#pragma once
// Progress lines on stderr, only when stderr is a terminal (never in logs or pipes).
#include <string>

namespace shadowkit {

class Progress {
 public:
  Progress();
  ~Progress();
  void step(const std::string& what);

 private:
  bool enabled_;
};

}  // namespace shadowkit
