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
/// fragments of a face tile it: each pixel centre is owned by exactly one of them. With
/// \p shadowed_only, \p fragments may hold the shadowed fragments alone (§6): pixels start
/// lit where condition 1 holds and the shadowed fragments are drawn over them: the same
/// mask but at the rare centres no fragment owns (a cut point on the face's outline snapped
/// off it), which this mode calls lit and the other shadowed.
void shade_fragments(const Scene& scene, const Light& light, const std::vector<Fragment>& fragments,
                     const VisibleSurfaceBuffer& surfaces, bool shadowed_only, ShadowMask& mask);

}  // namespace shadowkit::svbsp
