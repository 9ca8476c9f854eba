#include "shadowkit/app/progress.h"

#include <unistd.h>

#include <cstdio>

namespace shadowkit {

Progress::Progress() : enabled_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
  if (enabled_) std::fprintf(stderr, "\r\033[K");
}

void Progress::step(const std::string& what) {
  if (enabled_) std::fprintf(stderr, "\r\033[K%s", what.c_str());
}

}  // namespace shadowkit
