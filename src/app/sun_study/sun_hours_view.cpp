#include <tbb/parallel_for.h>

#include "heat_map.h"
#include "shadowkit/app/commands.h"
#include "shadowkit/app/sun_hours.h"
#include "shadowkit/methods/svbsp.h"
#include "study_steps.h"
#include "sunlit_steps.h"

namespace shadowkit {

Image<Rgb8> sun_hours_heat_map(const Scene& scene, const sun::Site& site, const SunSpan& span,
                               const Context& ctx) {
  SunStudyOptions options;
  options.from = span.from;
  options.to = span.to;
  options.step_minutes = span.step_minutes;
  const sun_study::Steps steps = sun_study::study_steps(options, site.utc_offset_hours);
  const svbsp::SunlitAreas sunlit(scene);
  sun_study::SunlitStepCounts counts(scene, ctx);
  tbb::parallel_for(std::int64_t(0), steps.count, [&](std::int64_t k) {
    const sun::SunAngles sun = sun::sun_position(site, steps.at(k));
    if (sun.elevation_deg > 0) counts.lit_areas(sunlit, sun::toward_sun(sun, site.north_deg));
  });
  return sun_study::heat_map_image(sun_study::sun_hours_image(
      counts.counts(), scene.camera.width, scene.camera.height, steps.step_hours()));
}

}  // namespace shadowkit
