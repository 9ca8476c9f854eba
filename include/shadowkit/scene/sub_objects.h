#pragma once
// Crow's sub-objects (1977, Sec. VI): the parts of an object that bound shadow volumes of
// their own, each with its bounding box.
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief The scene's faces grouped into sub-objects: the edge-connected parts of each
/// object's mesh. No edge joins two sub-objects, so the shadow polygons of a sub-object's
/// contour edges, with its faces, close its own per-face volumes: a point outside them gets
/// nothing from that sub-object, whatever the rest of the scene does.
struct SubObjects {
  /// Sub-objects with more vertices than this are represented by their boxes' corners.
  static constexpr std::size_t kMaxCorners = 64;

  std::vector<std::uint32_t> of_face;  ///< sub-object per global face id
  std::vector<Bounds3> bounds;         ///< per sub-object, of its faces' vertices
  /// Per sub-object: closed (every edge has two faces) and convex (every face's plane has
  /// all its vertices on one side), with its vertices listed as its corners. Its shadow
  /// volume is then the region behind its light-facing faces and inside the planes of its
  /// contour edges' shadow polygons, which ShadowFrustum can hold exactly.
  std::vector<char> convex;

  static SubObjects of(const Scene& scene);
  std::size_t size() const { return bounds.size(); }
  std::size_t memory_bytes() const {
    return of_face.capacity() * sizeof(std::uint32_t) + bounds.capacity() * sizeof(Bounds3) +
           convex.capacity() +
           (face_start_.capacity() + face_ids_.capacity() + corner_start_.capacity()) *
               sizeof(std::uint32_t) +
           corners_.capacity() * sizeof(Vec3);
  }
  /// The global face ids of sub-object \p k.
  std::span<const std::uint32_t> faces(std::size_t k) const {
    return {face_ids_.data() + face_start_[k], face_start_[k + 1] - face_start_[k]};
  }
  /// Points whose convex hull holds sub-object \p k: its vertices, or its box's corners.
  std::span<const Vec3> corners(std::size_t k) const {
    return {corners_.data() + corner_start_[k], corner_start_[k + 1] - corner_start_[k]};
  }

 private:
  std::vector<std::uint32_t> face_start_, face_ids_;
  std::vector<std::uint32_t> corner_start_;
  std::vector<Vec3> corners_;
};

}  // namespace shadowkit
