#pragma once
// Shadow polygons: the invisible boundary of the shadow volumes (Crow 1977, Sec. VII, Fig. 4).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "contour_edges.h"
#include "shadowkit/raster/scan_converter.h"
#include "shadowkit/raster/triangle_setup.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::volume {

/// \brief The region in which every counted crossing lies: the scene and the eye. It lies in
/// the ball of radius `limit` around a point light, or in the half-space
/// dot(x, direction) <= limit of a directional one; and in `box`.
struct Reach {
  double limit = 0;  ///< radius of the ball, or bound of the half-space
  Bounds3 box;       ///< the scene and the eye with a margin; empty: unbounded
  static Reach of(const Scene& scene, const Light& light);
};

/// \brief The corners of a shadow polygon in world space: a convex polygon of up to 4 corners,
/// plus one for each face of the reach's box clipping it. They serve once, to set the polygon
/// up on screen; the counting keeps only its ShadowPolygon.
struct PolygonCorners {
  std::array<raster::HomogeneousPoint, 10> points{};
  int count = 0;

  std::span<const raster::HomogeneousPoint> span() const {
    return {points.data(), std::size_t(count)};
  }
};

/// \brief One polygon of a shadow volume's boundary, with the plane test that places a
/// visible point in front of or behind it.
struct ShadowPolygon {
  Vec3 normal;  ///< plane with the eye on its negative side; zero normal, d = -1: at infinity
  double d = 0;
  int jump = 0;  ///< change of the count where a pixel ray crosses it, going away from the eye
  /// Depth-pass: counted when the crossing lies before the visible point. Depth-fail: when it
  /// lies behind it (the visible point's own face included, for a light cap).
  bool depth_fail = false;
  std::uint32_t face = kNoFace;  ///< the scene face of a light cap
  std::uint32_t sub_object = 0;  ///< the sub-object whose volume it bounds (SubObjects)
  /// A side polygon's first two faces along its contour edge (mesh face ids from
  /// side_polygon, global ones in the scene's polygon list; kNoFace where there are fewer)
  /// and the side of the polygon each lies on. Their points next to the edge are placed by
  /// this, not by a plane test that rounding can tip either way.
  std::array<std::uint32_t, 2> edge_faces{kNoFace, kNoFace};
  std::array<int, 2> edge_face_sides{};
};

/// The shadow polygon of a contour edge: the edge and the rays from the light through its
/// ends (parallel for a directional light), to infinity (homogeneous corners with w = 0).
/// Depth-pass polygons are clipped to the box of \p reach: crossings between the eye and a
/// visible point lie in it. Empty when the eye lies in its plane (no pixel ray crosses it) or
/// nothing of it is in the box; else its corners are in \p corners.
std::optional<ShadowPolygon> side_polygon(const Mesh& mesh, const ContourEdge& edge,
                                          const Light& light, const Reach& reach, Vec3 eye,
                                          bool depth_fail, PolygonCorners& corners);

/// The depth-fail caps of scene triangle \p t of sub-object \p sub_object: the triangle
/// itself (the light cap, where its face's shadow volume begins) and, for a point light, its
/// projection from the light onto the plane at infinity (the dark cap, where the volume
/// ends). Appended to \p out, their corners to \p corners.
void cap_polygons(const Scene& scene, std::uint32_t t, std::uint32_t sub_object, const Light& light,
                  Vec3 eye, std::vector<ShadowPolygon>& out, std::vector<PolygonCorners>& corners);

/// The plane of a side polygon, unit normal: the light and the edge lie in it.
Plane side_plane(const Mesh& mesh, const ContourEdge& edge, const Light& light);

/// Whether the side polygon of \p edge, to infinity, may pass within \p radius of point
/// \p p: false only when it surely does not.
bool side_polygon_near(const Mesh& mesh, const ContourEdge& edge, const Light& light, Vec3 p,
                       double radius);

}  // namespace shadowkit::volume
