#include "markup.h"

#include <cmath>
#include <cstdlib>

namespace shadowkit::sun_study {

std::string utc_offset_text(double hours) {
  const long minutes = std::lround(hours * 60);
  const auto two_digits = [](long n) { return (n < 10 ? "0" : "") + std::to_string(n); };
  return std::string(minutes < 0 ? "-" : "+") + two_digits(std::labs(minutes) / 60) + ":" +
         two_digits(std::labs(minutes) % 60);
}

}  // namespace shadowkit::sun_study
