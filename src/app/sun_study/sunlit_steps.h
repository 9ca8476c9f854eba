#pragma once
// The heat map's data: per pixel of the scene camera, the number of steps in which the sun
// reaches the visible point. Counts, not hours, so that threads and shards add them in any
// order to the same result.
#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/methods/svbsp.h"
#include "shadowkit/raster/visible_surface.h"

namespace shadowkit::sun_study {

/// The counts' file in a study's folder, and the count of a pixel that sees no surface.
constexpr const char* kSunStepCounts = "sun_steps.u32";
constexpr std::uint32_t kBackgroundCount = 0xffffffffu;

class SunlitStepCounts {
 public:
  /// Scan-converts \p scene from its camera once, for every step.
  SunlitStepCounts(const Scene& scene, const Context& ctx);

  /// One step's lit areas (svbsp::SunlitAreas::lit_areas), counting the pixels it lights.
  /// Thread-safe: each thread counts on its own image.
  std::vector<double> lit_areas(const svbsp::SunlitAreas& sunlit, Vec3 toward_sun);

  /// Per pixel (row-major, top row first), the steps counted so far by every thread;
  /// kBackgroundCount where the camera sees no surface.
  std::vector<std::uint32_t> counts() const;
  const VisibleSurfaceBuffer& surfaces() const { return surfaces_; }

 private:
  struct Counter {
    ShadowMask mask;
    std::vector<std::uint32_t> counts;
  };
  VisibleSurfaceBuffer surfaces_;
  tbb::enumerable_thread_specific<Counter> counters_;
};

/// The counts as little-endian uint32, and back; InputError naming \p path when its size is
/// not \p pixels values.
void write_counts(const std::filesystem::path& path, const std::vector<std::uint32_t>& counts);
std::vector<std::uint32_t> read_counts(const std::filesystem::path& path, std::size_t pixels);
/// Adds \p more to \p sum pixel by pixel (counts of one camera: background where both are).
void add_counts(const std::vector<std::uint32_t>& more, std::vector<std::uint32_t>& sum);

}  // namespace shadowkit::sun_study
