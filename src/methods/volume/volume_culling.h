#pragma once
// Crow's bounding-box tests (Sec. VI, Fig. 3), applied to whole shadow volumes.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "shadow_polygon.h"
#include "shadowkit/raster/view_frustum.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::volume {

/// \brief A convex region holding the shadow volume of anything inside a box, up to the
/// reach: the box swept away from the light (Crow's bounding box, Sec. VI). It is the space
/// behind the box's light-facing faces and inside the planes through the light and the
/// box's contour edges, cut further by planes that bound the volume of what the box holds.
/// The box is widened, and every plane moved out, by far more than their rounding, so the
/// tests below never miss a shadowed point.
class ShadowFrustum {
 public:
  ShadowFrustum() = default;  ///< empty, until assigned
  /// With \p view, whether the region can meet it is kept for reaches_view().
  ShadowFrustum(const Bounds3& box, const Light& light, const Reach& reach,
                const ViewFrustum* view = nullptr);

  /// Cuts the region by \p plane where it bounds the shadow volume of the convex hull of
  /// \p corners: all of them lie on one side of it, and the light does not lie strictly on
  /// that side (then every ray from the light through the hull stays there). For the planes
  /// of a sub-object's shadow polygons and faces, and its vertices, this makes the region
  /// the exact volume of a convex sub-object. Keeps at most kMaxPlanes planes in all: a cut
  /// takes the place of one of the box's planes when there is no room.
  void cut(std::span<const Vec3> corners, const Plane& plane);
  static constexpr int kMaxPlanes = 12;
  /// Declares the region the exact volume of a closed convex sub-object (SubObjects::convex)
  /// once the planes of all its faces and of the shadow polygons of all its contour edges
  /// were cut in (a light-facing face and a contour edge bound it; cut refuses a face turned
  /// away). It stays a bound only if some cut found no room or no plane. An exact region
  /// keeps only its cuts: the box's planes hold the volume anyway.
  void make_exact() {
    exact_ = !everywhere_ && !lost_;
    if (exact_) {
      for (int k = cuts_; k < plane_count_; ++k) set_plane(k, Plane{});
      plane_count_ = cuts_;
    }
  }
  /// The planes of an exact region as cut, inward normals, not moved out: the volume is
  /// the points on their positive side. Empty when the region is only a bound.
  std::span<const Plane> volume_planes() const {
    return {volume_planes_.data(), exact_ ? std::size_t(cuts_) : 0};
  }

  /// No point of \p receiver can lie in the region: nothing inside the box shadows it.
  bool misses(const Bounds3& receiver) const;
  /// Whether the region, within the reach, can meet the view given to the constructor.
  bool reaches_view() const { return reaches_view_; }

 private:
  bool everywhere_ = false;  ///< a point light inside the box
  bool lost_ = false;        ///< a plane of the volume was refused: the region is larger
  bool exact_ = false;       ///< the region is the shadow volume itself (make_exact)
  bool reaches_view_ = true;
  Light light_;
  double tolerance_ = 0;  ///< far above the rounding of distances to points in the reach
  std::array<Plane, kMaxPlanes> volume_planes_{};  ///< the cuts before they were moved out
  int plane_count_ = 0, cuts_ = 0;
  Bounds3 hull_box_;  ///< of the box's corners and the same pushed to the reach
  /// The planes by component, inward normals: the cuts, then the box's; the rest (and one
  /// to pad an odd count) a plane that misses nothing.
  alignas(16) std::array<double, kMaxPlanes> nx_{}, ny_{}, nz_{}, nd_{};
  Plane plane(int k) const {
    const auto i = std::size_t(k);
    return {{nx_[i], ny_[i], nz_[i]}, nd_[i]};
  }
  void set_plane(int k, const Plane& p) {
    const auto i = std::size_t(k);
    nx_[i] = p.normal.x, ny_[i] = p.normal.y, nz_[i] = p.normal.z, nd_[i] = p.d;
  }
};

/// \brief The shadow frusta of one light's casting sub-objects, by sub-object id. The others
/// (in the shadow of nearer ones, most of a dense scene's) have none: 896 bytes each, their
/// frusta would be most of a light's memory. Asked for one, they give an empty region.
class ShadowFrusta {
 public:
  /// Room for a frustum for each sub-object \p k with \p with[k], the others without.
  void assign(const std::vector<char>& with) {
    slot_.assign(with.size(), 0);
    std::uint32_t next = 1;  // slot 0: the empty region
    for (std::size_t k = 0; k < with.size(); ++k) slot_[k] = with[k] ? next++ : 0;
    frusta_.assign(next, ShadowFrustum{});
  }
  /// Sub-object \p k's frustum; only one given room may be assigned to.
  ShadowFrustum& operator[](std::size_t k) { return frusta_[slot_[k]]; }
  const ShadowFrustum& operator[](std::size_t k) const { return frusta_[slot_[k]]; }
  /// The sub-objects.
  std::size_t size() const { return slot_.size(); }
  std::size_t memory_bytes() const {
    return slot_.capacity() * sizeof(std::uint32_t) + frusta_.capacity() * sizeof(ShadowFrustum);
  }

 private:
  std::vector<std::uint32_t> slot_;
  std::vector<ShadowFrustum> frusta_;
};

}  // namespace shadowkit::volume
