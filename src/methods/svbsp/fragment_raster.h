#pragma once
// The camera pass: the fragments drawn with the shared scan converter (the paper's "any
// polygon-based visible-surface algorithm").
#include <vector>

#include "shadowkit/methods/shadow_method.h"
#include "svbsp_tree.h"

namespace shadowkit::svbsp {

/// Writes the mask of \p light: a covered pixel is lit when its centre is owned by a lit
/// fragment of the face visible there and the camera sees that face from the light's side
/// (contract condition 1); otherwise it is in shadow. The shared fill rule makes the
/// fragments of a face tile it, but a cut point on the face's outline snaps off it on the
/// raster, and the rare centres beside it that no fragment owns take the verdict of the
/// fragment holding their visible point. With \p shadowed_only, \p fragments may hold the
/// shadowed fragments alone (§6): pixels start lit where condition 1 holds and the shadowed
/// fragments are drawn over them, which calls those rare centres lit.
void shade_fragments(const Scene& scene, const Light& light, const std::vector<Fragment>& fragments,
                     const VisibleSurfaceBuffer& surfaces, bool shadowed_only, ShadowMask& mask);

}  // namespace shadowkit::svbsp
