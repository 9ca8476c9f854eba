#pragma once
/// \brief The sequential colour map of the false-colour outputs (sun hours): dark violet through
/// blue, teal and green to pale yellow, its lightness rising steadily from end to end.
#include "shadowkit/core/image.h"

namespace shadowkit {

/// The colour of \p t in [0, 1] (clamped; NaN gives the low end). D. A. Green's cubehelix
/// ("A colour scheme for the display of astronomical intensity images", Bull. Astr. Soc.
/// India 39, 289, 2011, eq. 2) with start 0.6, rotations -0.9, hue 1.8 and gamma 1, taken over
/// lightness 0.12 to 0.85: its lightness is monotonic, so it reads in grey print and to
/// colour-blind eyes, and its dark end stands apart from kBackground.
Rgb8 sequential_colour(double t);

}  // namespace shadowkit
