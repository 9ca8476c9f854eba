#include "shadowkit/core/context.h"

#include <cstdio>

namespace shadowkit {

void Context::warning(const std::string& message) const {
  if (warn) {
    warn(message);
  } else {
    std::fprintf(stderr, "shadowkit: warning: %s\n", message.c_str());
  }
}

}  // namespace shadowkit
