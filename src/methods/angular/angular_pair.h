#pragma once
#include <cstdint>

namespace shadowkit::angular {

/// \brief Two (phi, r) points of one table entry where shadow begins and ends (Sec. 3). With
/// hidden edges inserted in duplicate (Sec. 5) every pair is the cut of one hidden face by
/// the entry's constant-theta plane, so its depth at any phi inside it is that face's plane.
struct AngularPair {
  double phi_begin = 0, phi_end = 0;
  double reach = 0;          ///< the largest phi_end of this and the earlier pairs of its entry
  std::uint32_t hidden = 0;  ///< index into AngularTable::hidden()
};

}  // namespace shadowkit::angular
