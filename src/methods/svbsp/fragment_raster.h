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
/// fragments of a face tile it: each pixel centre is owned by exactly one of them.
void shade_fragments(const Scene& scene, const Light& light, const std::vector<Fragment>& fragments,
                     const VisibleSurfaceBuffer& surfaces, ShadowMask& mask);

}  // namespace shadowkit::svbsp
