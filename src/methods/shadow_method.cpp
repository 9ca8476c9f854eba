#include "shadowkit/methods/shadow_method.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "shadowkit/core/error.h"

namespace shadowkit {

double MethodOptions::number(const std::string& key, double fallback) const {
  const auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const std::string& s = it->second;
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) {
    throw InputError("option '" + method_ + "." + key + "'", "expected a number, got '" + s + "'");
  }
  return value;
}

std::string MethodOptions::text(const std::string& key, const std::string& fallback) const {
  const auto it = values_.find(key);
  return it == values_.end() ? fallback : it->second;
}

void MethodOptions::expect_only(std::string_view method,
                                const std::vector<std::string>& known) const {
  for (const auto& [key, value] : values_) {
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError("option '" + std::string(method) + "." + key + "'",
                       "unknown option for method " + std::string(method) +
                           (list.empty() ? " (it has none)" : " (it has: " + list + ")"));
    }
  }
}

void shade_each_pixel(const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                      const std::function<bool(std::size_t)>& classify) {
  tbb::parallel_for(0, surfaces.height, [&](int y) {
    for (int x = 0; x < surfaces.width; ++x) {
      const std::size_t i = surfaces.index(x, y);
      if (surfaces.covered(i)) mask.pixels[i] = classify(i) ? kMaskLit : kMaskShadow;
    }
  });
}

}  // namespace shadowkit
