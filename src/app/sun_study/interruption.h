#pragma once
// Ctrl-C (SIGINT) or SIGTERM during a study's steps: noticed between blocks of steps, so that
// the run stops with its temporary files removed instead of being killed mid-write.
#include <csignal>

namespace shadowkit::sun_study {

/// \brief While it lives, SIGINT and SIGTERM set a flag instead of ending the process; the
/// previous handlers come back when it goes.
class Interruption {
 public:
  Interruption();
  ~Interruption();
  Interruption(const Interruption&) = delete;
  Interruption& operator=(const Interruption&) = delete;

  /// Throws shadowkit::Interrupted when a signal came.
  void check() const;

 private:
  using Handler = void (*)(int);
  Handler previous_int_, previous_term_;
};

}  // namespace shadowkit::sun_study
