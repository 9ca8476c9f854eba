#include "markup.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace shadowkit::sun_study {

std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string utc_offset_text(double hours) {
  const long minutes = std::lround(hours * 60);
  char text[16];
  std::snprintf(text, sizeof text, "%c%02ld:%02ld", minutes < 0 ? '-' : '+',
                std::labs(minutes) / 60, std::labs(minutes) % 60);
  return text;
}

}  // namespace shadowkit::sun_study
