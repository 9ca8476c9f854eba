#pragma once
/// \brief The scene model: camera, lights and meshes in world space (scene-format.md).
#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "shadowkit/core/vec.h"
#include "shadowkit/scene/mesh.h"
#include "shadowkit/scene/outward_solids.h"
#include "shadowkit/scene/subdivision.h"
#include "shadowkit/scene/sun_position.h"

namespace shadowkit {

/// \brief Pinhole camera with the contract's pixel convention.
struct Camera {
  Vec3 position{0, 4, 12};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov_y_deg = 45;
  int width = 1920, height = 1080;

  /// Orthonormal frame: forward f, right r = normalize(f x up), true up u = r x f.
  Vec3 forward() const { return normalize(look_at - position); }
  Vec3 right() const { return normalize(cross(forward(), up)); }
  Vec3 true_up() const { return cross(right(), forward()); }
  double tan_half_fov() const;

  /// The contract's pixel rays as a grid: the ray through the centre of pixel (c, w) is
  /// forward + (x0 + c step) right + (y0 - w step) true_up, before normalisation.
  struct PixelGrid {
    double step, x0, y0;
  };
  PixelGrid pixel_grid() const;
  /// Unit ray direction through the centre of pixel (column, row), row 0 at the top.
  Vec3 pixel_ray(int column, int row) const;
  friend bool operator==(const Camera&, const Camera&) = default;
};

/// \brief A point light or a directional light (a light at infinity).
struct Light {
  enum class Type { point, directional };
  Type type = Type::point;
  Vec3 position;   ///< point lights
  Vec3 direction;  ///< directional lights: unit direction in which the light travels

  static Light point(Vec3 position) { return {Type::point, position, {}}; }
  /// \p direction: the way the light travels (need not be unit length).
  static Light directional(Vec3 direction) { return {Type::directional, {}, normalize(direction)}; }

  /// Unit vector from \p p toward the light.
  Vec3 direction_to(Vec3 p) const {
    return type == Type::point ? normalize(position - p) : -direction;
  }
  friend bool operator==(const Light&, const Light&) = default;
};

/// \brief What a viewer changes between frames: the camera and the lights.
struct SceneView {
  Camera camera;
  std::vector<Light> lights;
  friend bool operator==(const SceneView&, const SceneView&) = default;
};

/// \brief A mesh in world space and where its faces sit in the scene's face numbering.
struct SceneObject {
  std::string name;
  Mesh mesh;
  std::uint32_t first_face = 0;  ///< global id of the mesh's face 0
  /// Set when the object is a Catmull-Clark surface: `mesh` is then its crack-free
  /// tessellation, and methods that work on the limit surface itself (voxel) use this.
  std::shared_ptr<const SubdivisionSurface> subdivision;
  /// Where the object's input faces sit in the scene's description, for outputs that name
  /// a face as read (the sun-study contract's polygons): its entry in the scene file's
  /// `objects` (for a built-in scene, its place among the scene's objects) and the index,
  /// among that entry's faces, of its mesh's input face 0 (an entry whose generator makes
  /// several objects numbers their faces one after another). Mesh::input_faces goes on from
  /// there.
  std::uint32_t input_object = 0;
  std::uint32_t input_first_face = 0;
};

/// \brief Every face of every object, triangulated once for the scan converter and Embree.
/// \brief A scene's triangles in small, spatially compact groups with their bounds: what lets
/// a pass skip a whole group hidden behind nearer geometry. A group is at most kSize
/// triangles, consecutive in the Morton order of their centroids.
/// The clusters keep their own copies of their triangles' corners and faces, cluster after
/// cluster: a pass over a few clusters then reads them together, where the TriangleList, in
/// face order, would scatter them (a cache miss a triangle at a million triangles).
struct TriangleClusters {
  static constexpr std::uint32_t kSize = 16;
  std::vector<std::array<std::uint32_t, 3>> corners;  ///< per entry: a triangle's vertex ids
  std::vector<std::uint32_t> faces;                   ///< per entry: its global face id
  std::vector<Bounds3> bounds;                        ///< per cluster, of its triangles' corners

  std::size_t size() const { return bounds.size(); }
  /// The entries [first, last) of cluster \p c in corners and faces.
  std::pair<std::uint32_t, std::uint32_t> entries(std::size_t c) const {
    const auto first = std::uint32_t(c * kSize);
    return {first, std::min(std::uint32_t(faces.size()), first + kSize)};
  }
};

struct TriangleList {
  std::vector<Vec3> positions;  ///< all objects' vertices, concatenated
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> triangle_face;  ///< global face id per triangle
  TriangleClusters clusters;
};

/// Groups \p list's triangles into clusters (TriangleClusters); \p bounds holds them all.
TriangleClusters cluster_triangles(const TriangleList& list, const Bounds3& bounds);

/// \brief Where a scene's working coordinates sit in its world (the input's coordinates):
/// world = origin + scale * working.
///
/// Scenes read from files and generators are centred on their geometry and scaled by a
/// power of two (exact in floating point) to a size near 1, so that no method's result
/// depends on where the scene sits or on its units: a site in millimetres a thousand
/// kilometres from its origin is computed as precisely as a unit cube at the origin.
struct WorldFrame {
  Vec3 origin;
  double scale = 1;

  Vec3 to_world(Vec3 p) const { return origin + p * scale; }
  Vec3 to_working(Vec3 p) const { return (p - origin) / scale; }
  /// The frame centred on \p geometry with a power-of-two scale near its diagonal.
  static WorldFrame around(const Bounds3& geometry);
};

/// \brief The whole scene. Build it with finalize() after filling camera, lights, objects.
/// Every position in it is in working coordinates (WorldFrame).
struct Scene {
  std::string name;
  WorldFrame frame;
  Camera camera;
  std::vector<Light> lights;
  std::vector<SceneObject> objects;
  /// The scene file's `site`, which only the sun study reads. It is no position: the working
  /// frame, a translation and a positive uniform scale, turns no direction, so `north_deg`
  /// holds in working coordinates as in the scene's own.
  std::optional<sun::Site> site;
  std::string site_name;  ///< `site.name`: a label for the sun study's reports; may be empty

  /// Numbers faces globally, triangulates them and computes bounds.
  void finalize();

  std::uint32_t face_count() const { return std::uint32_t(face_object.size()); }
  const Plane& face_plane(std::uint32_t face) const { return face_planes_[face]; }
  std::uint32_t object_of_face(std::uint32_t face) const { return face_object[face]; }
  std::uint32_t local_face(std::uint32_t face) const {
    return face - objects[face_object[face]].first_face;
  }
  const Bounds3& bounds() const { return bounds_; }
  /// bounds() in world coordinates.
  Bounds3 world_bounds() const {
    return bounds_.empty() ? bounds_
                           : Bounds3{frame.to_world(bounds_.lo), frame.to_world(bounds_.hi)};
  }
  const TriangleList& triangles() const { return triangles_; }
  const OutwardSolids& outward_solids() const { return outward_solids_; }

  std::vector<std::uint32_t> face_object;  ///< object index per global face id

 private:
  Bounds3 bounds_;
  TriangleList triangles_;
  OutwardSolids outward_solids_;
  std::vector<Plane> face_planes_;  ///< copies of the meshes' planes, by global face id
};

/// Applies the contract's transform p' = T · Rz · Ry · Rx · S · p to every position.
void apply_transform(std::vector<Vec3>& positions, Vec3 scale, Vec3 rotate_deg, Vec3 translate);

}  // namespace shadowkit
