#include "shadow_polygon.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace shadowkit::volume {
namespace {

using raster::HomogeneousPoint;

// Orients the plane so that the eye is on its negative side; \p jump_to_positive is the
// change of the count when crossing from the negative to the positive side.
std::optional<ShadowPolygon> oriented(ShadowPolygon poly, int jump_to_positive, Vec3 eye) {
  const double eye_side = dot(poly.normal, eye) + poly.d;
  if (eye_side == 0) return std::nullopt;
  poly.jump = eye_side < 0 ? jump_to_positive : -jump_to_positive;
  if (eye_side > 0) poly.normal = -poly.normal, poly.d = -poly.d;
  return poly;
}

// Where edge (p, q) crosses a plane at signed values dp, dq: endpoints in a canonical order so
// that polygons sharing the edge get bit-identical points (as the raster's clipper).
HomogeneousPoint crossing(HomogeneousPoint p, double dp, HomogeneousPoint q, double dq) {
  if (std::tie(q.xyz.x, q.xyz.y, q.xyz.z, q.w) < std::tie(p.xyz.x, p.xyz.y, p.xyz.z, p.w))
    std::swap(p, q), std::swap(dp, dq);
  const double t = dp / (dp - dq);
  return {p.xyz + (q.xyz - p.xyz) * t, p.w + (q.w - p.w) * t};
}

// Clips \p poly to \p box (Sutherland-Hodgman on the six faces, homogeneous); false if
// nothing remains. Keeps depth-pass polygons from reaching past the receivers (Crow's volumes
// need not extend beyond the scene), which is most of their area on screen.
bool clip_to_box(PolygonCorners& poly, const Bounds3& box) {
  for (int face = 0; face < 6 && poly.count >= 3; ++face) {
    const int axis = face % 3;
    const double sign = face < 3 ? 1 : -1, bound = face < 3 ? box.lo[axis] : box.hi[axis];
    // Keeps sign (x[axis] - bound w) >= 0.
    std::array<double, 10> at;
    bool inside = true;
    for (int k = 0; k < poly.count; ++k) {
      const HomogeneousPoint& p = poly.points[k];
      at[k] = sign * (p.xyz[axis] - bound * p.w);
      inside &= at[k] >= 0;
    }
    if (inside) continue;  // most faces: only the far end reaches past the box
    std::array<HomogeneousPoint, 10> out;
    int n = 0;
    for (int k = 0; k < poly.count; ++k) {
      const int next = (k + 1) % poly.count;
      const double dp = at[k], dq = at[next];
      if (dp >= 0) out[n++] = poly.points[k];
      if ((dp >= 0) != (dq >= 0)) out[n++] = crossing(poly.points[k], dp, poly.points[next], dq);
    }
    poly.points = out;
    poly.count = n;
  }
  return poly.count >= 3;
}

}  // namespace

Reach Reach::of(const Scene& scene, const Light& light) {
  Bounds3 box = scene.bounds();
  box.add(scene.camera.position);
  Reach r;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = box.corner(c);
    r.limit = std::max(r.limit, light.type == Light::Type::point ? length(p - light.position)
                                                                 : dot(p, light.direction));
  }
  if (light.type == Light::Type::directional) {
    r.limit = r.limit + 0.01 * box.diagonal() + 1e-300;  // strictly beyond every corner
  } else {
    r.limit *= 1.01;
  }
  // A margin keeps the box's faces off the receivers lying on them (the ground).
  const Vec3 margin = Vec3{1, 1, 1} * (0.01 * box.diagonal() + 1e-300);
  r.box = {box.lo - margin, box.hi + margin};
  return r;
}

Plane side_plane(const Mesh& mesh, const ContourEdge& edge, const Light& light) {
  const Vec3 a = mesh.vertices[edge.from], b = mesh.vertices[edge.to];
  const Vec3 n = normalize(cross(b - a, away_from_light(a, light)));
  return {n, -dot(n, a)};
}

bool side_polygon_near(const Mesh& mesh, const ContourEdge& edge, const Light& light, Vec3 p,
                       double radius) {
  const Plane plane = side_plane(mesh, edge, light);
  if (!is_finite(plane.normal)) return true;  // no polygon: nothing to tell
  if (std::abs(plane.distance(p)) > radius) return false;
  // In its plane the polygon is convex, the intersection of three half-planes: beyond the
  // edge, and between the rays from its ends (which meet at a point light). A point more than
  // radius outside one of them is farther than that from the polygon.
  const Vec3 a = mesh.vertices[edge.from], b = mesh.vertices[edge.to];
  const Vec3 da = away_from_light(a, light), db = away_from_light(b, light);
  const auto outside = [&](Vec3 from, Vec3 along, Vec3 inner) {
    const Vec3 m = cross(plane.normal, along);
    const double inner_side = dot(inner - from, m), side = dot(p - from, m);
    return inner_side != 0 && (inner_side > 0 ? -side : side) > radius * length(m);
  };
  return !outside(a, b - a, a + da) && !outside(a, da, b) && !outside(b, db, a);
}

std::optional<ShadowPolygon> side_polygon(const Mesh& mesh, const ContourEdge& edge,
                                          const Light& light, const Reach& reach, Vec3 eye,
                                          bool depth_fail, PolygonCorners& corners) {
  const Vec3 a = mesh.vertices[edge.from], b = mesh.vertices[edge.to];
  const Vec3 da = away_from_light(a, light), db = away_from_light(b, light);
  ShadowPolygon poly;
  poly.depth_fail = depth_fail;
  // To infinity: the rays meet the plane at infinity at (da, 0) and (db, 0); a directional
  // light's meet in one point, and the polygon is a triangle. The far corners depend on the
  // vertex alone, so neighbouring polygons share their rays bit for bit and the fill rule
  // counts a pixel centre on a shared ray once.
  corners.points[0] = {a, 1};
  corners.points[1] = {b, 1};
  corners.points[2] = {db, 0};
  corners.points[3] = {da, 0};
  corners.count = light.type == Light::Type::point ? 4 : 3;
  if (!depth_fail && !reach.box.empty() && !clip_to_box(corners, reach.box)) return std::nullopt;
  const Plane plane = side_plane(mesh, edge, light);
  if (!is_finite(plane.normal)) return std::nullopt;
  poly.normal = plane.normal;
  poly.d = plane.d;
  std::optional<ShadowPolygon> seen = oriented(poly, edge.weight, eye);
  if (!seen) return seen;
  const MeshEdge& mesh_edge = mesh.edges[edge.edge];
  for (std::uint32_t k = 0; k < std::min(mesh_edge.use_count, 2u); ++k) {
    const EdgeUse& use = mesh.edge_uses[mesh_edge.first_use + k];
    seen->edge_faces[k] = use.face;
    seen->edge_face_sides[k] = face_side(mesh, mesh_edge, use, seen->normal);
  }
  return seen;
}

void cap_polygons(const Scene& scene, std::uint32_t t, std::uint32_t sub_object, const Light& light,
                  Vec3 eye, std::vector<ShadowPolygon>& out, std::vector<PolygonCorners>& corners) {
  const TriangleList& list = scene.triangles();
  const std::uint32_t face = list.triangle_face[t];
  const Plane& plane = scene.face_plane(face);
  const double side = light_side(plane, light);
  if (side == 0) return;  // a face in the light's plane casts no volume
  // Light cap: the face, with the light on the negative side; crossing it away from the
  // light enters the face's volume.
  ShadowPolygon cap;
  cap.depth_fail = true;
  cap.face = face;
  cap.sub_object = sub_object;
  PolygonCorners cap_corners;
  cap_corners.count = 3;
  for (int k = 0; k < 3; ++k) cap_corners.points[k] = {list.positions[list.triangles[t][k]], 1};
  cap.normal = side > 0 ? -plane.normal : plane.normal;
  cap.d = side > 0 ? -plane.d : plane.d;
  if (auto light_cap = oriented(cap, +1, eye)) {
    out.push_back(*light_cap);
    corners.push_back(cap_corners);
  }
  if (light.type != Light::Type::point) return;  // parallel rays: no dark cap
  // Dark cap at infinity: every pixel ray whose direction lies in the face's cone from the
  // light leaves the volume there, after every finite point.
  ShadowPolygon dark = cap;
  dark.face = kNoFace;
  for (int k = 0; k < 3; ++k) {
    cap_corners.points[k] = {cap_corners.points[k].xyz - light.position, 0};
  }
  dark.normal = {};
  dark.d = -1;
  dark.jump = -1;
  out.push_back(dark);
  corners.push_back(cap_corners);
}

}  // namespace shadowkit::volume
