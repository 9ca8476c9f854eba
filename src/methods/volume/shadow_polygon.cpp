#include "shadow_polygon.h"

#include <algorithm>
#include <cmath>

#include "segment_distance.h"

namespace shadowkit {
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

}  // namespace

Reach Reach::of(const Scene& scene, const Light& light) {
  Bounds3 box = scene.bounds();
  box.add(scene.camera.position);
  Reach r;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p{c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y,
                 c & 4 ? box.hi.z : box.lo.z};
    r.limit = std::max(r.limit, light.type == Light::Type::point ? length(p - light.position)
                                                                 : dot(p, light.direction));
  }
  if (light.type == Light::Type::directional) {
    r.limit = r.limit + 0.01 * box.diagonal() + 1e-300;  // strictly beyond every corner
  } else {
    r.limit *= 1.01;
  }
  return r;
}

Plane side_plane(const Mesh& mesh, const ContourEdge& edge, const Light& light) {
  const Vec3 a = mesh.vertices[edge.from], b = mesh.vertices[edge.to];
  const Vec3 n = normalize(cross(b - a, away_from_light(a, light)));
  return {n, -dot(n, a)};
}

std::optional<ShadowPolygon> side_polygon(const Mesh& mesh, const ContourEdge& edge,
                                          const Light& light, const Reach& reach, Vec3 eye,
                                          bool depth_fail) {
  const Vec3 a = mesh.vertices[edge.from], b = mesh.vertices[edge.to];
  const Vec3 da = away_from_light(a, light), db = away_from_light(b, light);
  ShadowPolygon poly;
  poly.depth_fail = depth_fail;
  if (depth_fail) {
    // To infinity: the rays meet the plane at infinity at (da, 0) and (db, 0); a directional
    // light's meet in one point, and the polygon is a triangle.
    poly.corners = {HomogeneousPoint{a, 1}, {b, 1}, {db, 0}, {da, 0}};
    poly.corner_count = light.type == Light::Type::point ? 4 : 3;
  } else if (light.type == Light::Type::point) {
    // Beyond T times the light's distance to the edge, every point of the polygon is farther
    // from the light than the reach.
    const double gap = segment_distance(light.position, a, b);
    if (gap == 0) return std::nullopt;
    const double t = std::max(1.0, reach.limit / gap);
    poly.corners = {
        HomogeneousPoint{a, 1}, {b, 1}, {light.position + db * t, 1}, {light.position + da * t, 1}};
    poly.corner_count = 4;
  } else {
    const Vec3 dir = light.direction;
    poly.corners = {HomogeneousPoint{a, 1},
                    {b, 1},
                    {b + dir * (reach.limit - dot(b, dir)), 1},
                    {a + dir * (reach.limit - dot(a, dir)), 1}};
    poly.corner_count = 4;
  }
  const Plane plane = side_plane(mesh, edge, light);
  if (!is_finite(plane.normal)) return std::nullopt;
  poly.normal = plane.normal;
  poly.d = plane.d;
  return oriented(poly, edge.weight, eye);
}

void cap_polygons(const Scene& scene, std::uint32_t t, const Light& light, Vec3 eye,
                  std::vector<ShadowPolygon>& out) {
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
  cap.corner_count = 3;
  for (int k = 0; k < 3; ++k) cap.corners[k] = {list.positions[list.triangles[t][k]], 1};
  cap.normal = side > 0 ? -plane.normal : plane.normal;
  cap.d = side > 0 ? -plane.d : plane.d;
  if (auto light_cap = oriented(cap, +1, eye)) out.push_back(*light_cap);
  if (light.type != Light::Type::point) return;  // parallel rays: no dark cap
  // Dark cap at infinity: every pixel ray whose direction lies in the face's cone from the
  // light leaves the volume there, after every finite point.
  ShadowPolygon dark = cap;
  dark.face = kNoFace;
  for (int k = 0; k < 3; ++k) dark.corners[k] = {cap.corners[k].xyz - light.position, 0};
  dark.normal = {};
  dark.d = -1;
  dark.jump = -1;
  out.push_back(dark);
}

}  // namespace shadowkit
