#pragma once
/// \brief Sun hours seen from a camera over a span of time: the sun study's heat map
/// (sun-study.md) for a view and span of the caller's, such as the viewer's sun mode.
#include <string>

#include "shadowkit/core/context.h"
#include "shadowkit/core/image.h"
#include "shadowkit/scene/scene.h"
#include "shadowkit/scene/sun_position.h"

namespace shadowkit {

/// \brief Steps of local standard time, as sun-study's --from, --to and --step give them.
struct SunSpan {
  std::string from, to;  ///< YYYY-MM-DDTHH:MM
  double step_minutes = 60;
};

/// The heat map `sun-study` draws (each visible point's sun hours in false colour, and the
/// legend to its right) of \p scene's camera over \p span at \p site, with the study's own
/// exact sunlit areas (svbsp). InputError, naming sun-study's option, when the span makes no
/// study; \p scene's lights are ignored, as the study ignores them.
Image<Rgb8> sun_hours_heat_map(const Scene& scene, const sun::Site& site, const SunSpan& span,
                               const Context& ctx);

}  // namespace shadowkit
