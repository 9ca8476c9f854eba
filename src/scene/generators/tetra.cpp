// Eric Haines's Standard Procedural Database "tetra": a recursive (Sierpinski) tetrahedron.
// Level L holds 4^L tetrahedra, 4^(L+1) triangles; with the two-triangle ground plane level 3
// and level 4 are Chin & Feiner's Tetra256 (258 input polygons) and Tetra1024 (1026).
#include <array>
#include <cstdint>

#include "builtin_scenes.h"
#include "primitives.h"

namespace shadowkit::generators {
namespace {

constexpr std::int64_t kMaxLevel = 7;
constexpr double kEdge = 4;
// The base floats above the ground: tetrahedra resting on it would put their bottom faces in
// the ground's plane, and coplanar overlapping faces make every method's answer arbitrary.
constexpr Vec3 kBaseCenter{0, 0.6, 0};
constexpr double kGroundSize = 14;

// Light high on the front left: the faces seen from the front right camera are lit and the
// holes' shadows fall onto the visible ground to the right.
constexpr Vec3 kCamera{3.9, 4.6, 8.2};
constexpr Vec3 kLookAt{0.6, 1.4, 0};
constexpr Vec3 kLight{-6.5, 9.5, 3.5};

Vec3 midpoint(Vec3 a, Vec3 b) {
  return (a + b) * 0.5;
}

/// Replaces a tetrahedron by the four half-size ones at its corners, \p level times.
/// Midpoints are computed the same way from both sides, so touching corners are equal bit
/// for bit and the welder merges them.
void add_sierpinski(PolygonSoup& soup, const std::array<Vec3, 4>& t, int level) {
  if (level == 0) {
    add_tetrahedron(soup, t);
    return;
  }
  for (int corner = 0; corner < 4; ++corner) {
    std::array<Vec3, 4> child;
    for (int j = 0; j < 4; ++j) child[j] = midpoint(t[corner], t[j]);
    add_sierpinski(soup, child, level - 1);
  }
}

}  // namespace

SceneParts tetra_scene(const ParamReader& params) {
  params.allow_only({"level"});
  const auto level = static_cast<int>(params.integer("level", 3, 0, kMaxLevel));

  GeneratedObject tetra{"tetra", {}};
  add_sierpinski(tetra.soup, regular_tetrahedron(kBaseCenter, kEdge), level);
  GeneratedObject ground{"ground", {}};
  add_horizontal_triangle_pair(ground.soup, {0, 0, 0}, kGroundSize);

  SceneParts parts;
  parts.objects.push_back(std::move(tetra));
  parts.objects.push_back(std::move(ground));
  parts.lights.push_back(Light::point(kLight));
  parts.camera = camera_looking_at(kCamera, kLookAt);
  return parts;
}

}  // namespace shadowkit::generators
