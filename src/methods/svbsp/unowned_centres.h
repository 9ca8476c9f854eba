#pragma once
// The pixel centres of a face that snapping its fragments' corners to the raster leaves to
// none of them, and their verdicts.
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/methods/shadow_method.h"
#include "svbsp_tree.h"

namespace shadowkit::svbsp {

/// The mask value of a covered pixel whose face has fragments of both verdicts, until one of
/// them owns its centre.
inline constexpr std::uint8_t kUnowned = 1;
static_assert(kUnowned != kMaskBackground && kUnowned != kMaskShadow && kUnowned != kMaskLit);

/// Gives every kUnowned pixel of \p mask a verdict. Such a centre lies within a pixel of its
/// face's outline, where a cut point on the outline snapped off it. The neighbours of the
/// same face that fragments own decide it where they agree; elsewhere, as the fragments
/// tile the face in object space, the fragment holding its visible point deepest. Among
/// \p fragments, \p candidates hold every fragment of each face with such pixels.
void resolve_unowned(const Scene& scene, const std::vector<Fragment>& fragments,
                     std::span<const std::uint32_t> candidates,
                     const VisibleSurfaceBuffer& surfaces, ShadowMask& mask);

}  // namespace shadowkit::svbsp
