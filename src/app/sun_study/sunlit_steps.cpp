#include "sunlit_steps.h"

#include "contract_files.h"
#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {

SunlitStepCounts::SunlitStepCounts(const Scene& scene, const Context& ctx)
    : surfaces_(render_visible_surfaces(scene, ctx)) {}

std::vector<double> SunlitStepCounts::lit_areas(const svbsp::SunlitAreas& sunlit, Vec3 toward_sun) {
  Counter& counter = counters_.local();
  if (counter.counts.empty()) {
    counter.mask = ShadowMask(surfaces_.width, surfaces_.height);
    counter.counts.assign(counter.mask.pixels.size(), 0);
  }
  std::vector<double> areas = sunlit.lit_areas(toward_sun, surfaces_, counter.mask);
  for (std::size_t i = 0; i < counter.counts.size(); ++i) {
    counter.counts[i] += counter.mask.pixels[i] == kMaskLit;
  }
  return areas;
}

std::vector<std::uint32_t> SunlitStepCounts::counts() const {
  std::vector<std::uint32_t> sum(std::size_t(surfaces_.width) * surfaces_.height, 0);
  for (const Counter& counter : counters_) {
    for (std::size_t i = 0; i < counter.counts.size(); ++i) sum[i] += counter.counts[i];
  }
  for (std::size_t i = 0; i < sum.size(); ++i) {
    if (!surfaces_.covered(i)) sum[i] = kBackgroundCount;
  }
  return sum;
}

void write_counts(const std::filesystem::path& path, const std::vector<std::uint32_t>& counts) {
  std::string bytes;
  bytes.reserve(counts.size() * 4);
  for (const std::uint32_t c : counts) append_uint32_le(c, bytes);
  write_file(path, bytes);
}

std::vector<std::uint32_t> read_counts(const std::filesystem::path& path, std::size_t pixels) {
  const std::string bytes = read_file(path);
  if (bytes.size() != pixels * 4) {
    throw InputError(path.string(), "does not hold " + std::to_string(pixels) + " counts");
  }
  std::vector<std::uint32_t> counts(pixels);
  const auto* raw = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::size_t i = 0; i < pixels; ++i) counts[i] = read_uint32_le(raw + 4 * i);
  return counts;
}

void add_counts(const std::vector<std::uint32_t>& more, std::vector<std::uint32_t>& sum) {
  for (std::size_t i = 0; i < sum.size(); ++i) {
    if (sum[i] != kBackgroundCount) sum[i] += more[i];
  }
}

}  // namespace shadowkit::sun_study
