#pragma once
// The lookup table of angular spans (discretized-shadow-volume paper, Secs. 3-5 and 7).
#include <tbb/combinable.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "light_frame.h"
#include "shadowkit/core/context.h"

namespace shadowkit {

/// \brief Two points of one table entry where shadow begins and ends (Sec. 3). The points
/// are where the entry's constant-theta plane crosses the edges of one triangle of a hidden
/// face, so the segment between them, whose ends the paper keeps as (phi, r), is that
/// triangle's cut; its depth at any phi inside the pair (Sec. 5) is the face's plane. The
/// triangle is kept (by id) so that the query can also be exact between entries.
struct AngularPair {
  double phi_begin = 0, phi_end = 0;
  double reach = 0;          ///< the largest phi_end of this and the earlier pairs of its entry
  std::uint32_t hidden = 0;  ///< index into AngularTable::hidden()
  std::uint32_t face = 0;    ///< global id of the hidden face
};

/// \brief A triangle of a hidden face in light-frame coordinates: its plane (the depth of
/// Sec. 5) and the three planes of light rays through its edges, each positive inside.
struct HiddenTriangle {
  FrameAffine plane;
  FrameAffine side[3];
  double light_side = 0;       ///< sign of the plane at the light: +1 or -1
  std::uint32_t triangle = 0;  ///< index into Scene::triangles()

  /// A light ray through \p p crosses the triangle (inclusive, so that neighbours leave no
  /// crack).
  bool covers(Vec3 p) const {
    return side[0].at(p) >= 0 && side[1].at(p) >= 0 && side[2].at(p) >= 0;
  }
  /// \p p lies beyond the plane, seen from the light, by more than \p tolerance.
  bool behind(Vec3 p, double tolerance) const { return plane.at(p) * light_side < -tolerance; }
};

/// The light-frame planes of a triangle with light-frame corners \p v.
HiddenTriangle hidden_triangle(const LightFrame& frame, const Vec3 (&v)[3], const Plane& plane);

/// \brief theta quantized to R integer entries (Sec. 3): entry k holds theta in
/// [theta_min + k step, theta_min + (k + 1) step) and is sampled at its centre.
struct ThetaQuantization {
  double theta_min = 0, step = 1;
  int resolution = 1;
  bool full_turn = false;  ///< point light whose spans go all around it (light in the scene)

  /// The unwrapped entry number of \p theta: -1 below the table, R above it.
  int index(double theta) const {
    return int(std::clamp(std::floor((theta - theta_min) / step), -1.0, double(resolution)));
  }
  /// The table entry of unwrapped index \p k; -1 when outside the table.
  int entry(int k) const;
  double lower(int k) const { return theta_min + k * step; }
  double centre(int k) const { return theta_min + (k + 0.5) * step; }
};

/// \brief Occluding ("hidden") faces for one light and the resolution choice.
struct AngularTableInput {
  std::vector<char> occluder;  ///< per global face
  int resolution = 0;          ///< R; 0: eq. 4
};

/// A pair and the entry it belongs to, while the table is built.
using EntryPair = std::pair<std::uint32_t, AngularPair>;

/// \brief The lookup table: per theta entry, pairs sorted by phi_begin (Sec. 7, step 1.7).
class AngularTable {
 public:
  static AngularTable build(const Scene& scene, const LightFrame& frame,
                            const AngularTableInput& input, const Context& ctx);

  const ThetaQuantization& theta() const { return theta_; }
  std::span<const AngularPair> entry(int k) const {
    if (k < 0) return {};
    return {pairs_.data() + start_[k], pairs_.data() + start_[k + 1]};
  }
  /// The wide pairs of entry \p k (longer than a sixteenth of the entry's extent, such as a
  /// ground plane's): scanned whole by every query.
  std::span<const AngularPair> wide(int k) const { return entry(k).first(wide_[k]); }
  /// The narrow pairs of entry \p k, sorted by phi_begin, from the first whose reach gets to
  /// \p phi: the ones before it all end before phi (a binary search instead of the paper's
  /// scan from the start of the entry).
  std::span<const AngularPair> narrow_from(int k, double phi) const;
  /// The narrow pair just before narrow_from(k, phi), whose reach is the largest end before
  /// phi; nullptr if none.
  const AngularPair* narrow_before(int k, double phi) const;
  const HiddenTriangle& hidden(std::uint32_t i) const { return hidden_[i]; }
  std::size_t pair_count() const { return pairs_.size(); }
  std::size_t memory_bytes() const {
    return pairs_.capacity() * sizeof(AngularPair) +
           (start_.capacity() + wide_.capacity()) * sizeof(std::uint32_t) +
           hidden_.capacity() * sizeof(HiddenTriangle);
  }

 private:
  void fill_entries(tbb::combinable<std::vector<EntryPair>>& pairs);
  void sort_entry(int k);

  ThetaQuantization theta_;
  std::vector<std::uint32_t> start_;  ///< R + 1 offsets into pairs_
  std::vector<std::uint32_t> wide_;   ///< per entry: its first wide_[k] pairs are wide
  std::vector<AngularPair> pairs_;
  std::vector<HiddenTriangle> hidden_;
};

/// The pair one triangle (light-frame corners \p v, sorted by vertex id so that a shared
/// edge is cut bit-identically) contributes to the constant-theta plane at \p theta, if it
/// crosses it. Exposed for tests.
bool cut_triangle(const LightFrame& frame, const Vec3 (&v)[3], double theta, AngularPair& out);

/// The pair of one triangle for entry \p k: the union of its cuts at the entry's centre and
/// both ends and of its corners inside the entry, widened by one entry's width, so that every
/// point of the triangle seen in the entry lies within it (the query's exact triangle test
/// then decides). False when the triangle misses the entry.
bool entry_span(const LightFrame& frame, const Vec3 (&v)[3], const ThetaQuantization& q, int k,
                AngularPair& out);

/// R by eq. 4, generalized: enough entries that one scan line's step at any scene vertex in
/// view stays within one entry, clamped to [height / 2, height] (Sec. 3: one entry per scan
/// line when the light is far). Queries are exact at any R
/// (the pairs hold whole triangles per entry), so R trades table size against pairs per entry.
int automatic_resolution(const Scene& scene, const LightFrame& frame, double theta_range);

}  // namespace shadowkit
