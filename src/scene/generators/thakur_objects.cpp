// The test objects of Thakur, Cheng & Miura's RE-loops paper, each over a ground plane under
// a point light placed to show its case: the twice-coiled loop (Figs. 2b / 3), the object
// with a hole (Figs. 13 / 25) and the hole-like object (Figs. 26 / 27).
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "builtin_scenes.h"

namespace shadowkit::generators {
namespace {

// Walls between a ring of points and the same ring moved by \p e: for a ring counter-clockwise
// about e, quad (p_i, p_j, p_j + e, p_i + e) faces out (its normal is (p_j - p_i) x e).
// \p bottom is the index of the ring's first point; its points moved by e follow it.
void add_walls(PolygonSoup& soup, std::uint32_t bottom, std::uint32_t top, std::uint32_t n,
               bool reversed) {
  for (std::uint32_t i = 0; i < n; ++i) {
    std::uint32_t a = i, b = (i + 1) % n;
    if (reversed) std::swap(a, b);
    soup.add_face({bottom + a, bottom + b, top + b, top + a});
  }
}

// A solid: \p outline (counter-clockwise about \p e) swept along e.
void add_extruded_outline(PolygonSoup& soup, const std::vector<Vec3>& outline, Vec3 e) {
  const auto n = std::uint32_t(outline.size());
  const auto first = std::uint32_t(soup.positions.size());
  for (const Vec3& p : outline) soup.positions.push_back(p);
  for (const Vec3& p : outline) soup.positions.push_back(p + e);
  std::vector<std::uint32_t> bottom, top;
  for (std::uint32_t i = 0; i < n; ++i)
    bottom.push_back(first + n - 1 - i), top.push_back(first + n + i);
  soup.add_face(bottom);
  soup.add_face(top);
  add_walls(soup, first, first + n, n, false);
}

// A solid with a hole: the region between \p outer and \p inner (corresponding points, both
// counter-clockwise about \p e) swept along e; its top and bottom are quads between the rings.
void add_extruded_annulus(PolygonSoup& soup, const std::vector<Vec3>& outer,
                          const std::vector<Vec3>& inner, Vec3 e) {
  const auto n = std::uint32_t(outer.size());
  const auto o = std::uint32_t(soup.positions.size()), i = o + 2 * n;
  for (const Vec3& p : outer) soup.positions.push_back(p);
  for (const Vec3& p : outer) soup.positions.push_back(p + e);
  for (const Vec3& p : inner) soup.positions.push_back(p);
  for (const Vec3& p : inner) soup.positions.push_back(p + e);
  for (std::uint32_t a = 0; a < n; ++a) {
    const std::uint32_t b = (a + 1) % n;
    soup.add_face({o + n + a, o + n + b, i + n + b, i + n + a});  // top
    soup.add_face({o + b, o + a, i + a, i + b});                  // bottom
  }
  add_walls(soup, o, o + n, n, false);
  add_walls(soup, i, i + n, n, true);  // facing into the hole
}

// A square of half side \p half in the plane y = \p y, counter-clockwise about +y.
std::vector<Vec3> square_ring(double half, double y) {
  return {{-half, y, half}, {half, y, half}, {half, y, -half}, {-half, y, -half}};
}

// A tube of rectangular section (radial half width \p w, half height \p h) along a helix of
// radius \p radius about the vertical through the origin, from height \p y0 rising \p rise
// per turn, with end caps; \p per_turn segments a turn.
void add_helical_band(PolygonSoup& soup, double radius, double w, double h, double y0, double rise,
                      double turns, int per_turn) {
  const int segments = int(std::ceil(turns * per_turn));
  const auto first = std::uint32_t(soup.positions.size());
  for (int s = 0; s <= segments; ++s) {
    const double t = 2 * std::numbers::pi * turns * s / segments;
    const Vec3 out{std::cos(t), 0, std::sin(t)};  // radial; out x up is the tangent's way
    const Vec3 c = out * radius + Vec3{0, y0 + rise * t / (2 * std::numbers::pi), 0};
    // The section counter-clockwise about the tangent: inner-bottom, outer-bottom,
    // outer-top, inner-top.
    for (const Vec3 corner : {Vec3{-w, -h, 0}, Vec3{w, -h, 0}, Vec3{w, h, 0}, Vec3{-w, h, 0}}) {
      soup.positions.push_back(c + out * corner.x + Vec3{0, corner.y, 0});
    }
  }
  for (int s = 0; s < segments; ++s) {
    const std::uint32_t a = first + 4 * std::uint32_t(s), b = a + 4;
    for (std::uint32_t k = 0; k < 4; ++k) {
      const std::uint32_t l = (k + 1) % 4;
      if (k % 2 == 1) {  // the outer and inner walls: planar parallelograms
        soup.add_face({a + k, a + l, b + l, b + k});
        continue;
      }
      // The bottom and top are pieces of helicoids, not planar: two triangles each.
      soup.add_face({a + k, a + l, b + l});
      soup.add_face({a + k, b + l, b + k});
    }
  }
  const std::uint32_t last = first + 4 * std::uint32_t(segments);
  soup.add_face({first + 3, first + 2, first + 1, first});
  soup.add_face({last, last + 1, last + 2, last + 3});
}

SceneParts on_ground(GeneratedObject object, Vec3 light, Vec3 camera, Vec3 look_at) {
  SceneParts parts;
  parts.objects.push_back(std::move(object));
  parts.objects.push_back(ground_object(12));
  parts.lights.push_back(Light::point(light));
  parts.camera = camera_looking_at(camera, look_at);
  return parts;
}

}  // namespace

SceneParts coil_scene(const ParamReader& params) {
  params.allow_only({"turns"});
  const double turns = params.positive("turns", 1.6);
  if (turns > 20) params.fail("turns", "expected at most 20 turns");
  // The upper turn, nearer the light above the axis, projects larger than the one under it:
  // seen from the light the band's outline winds around twice and overlaps itself.
  GeneratedObject coil{"coil", {}};
  add_helical_band(coil.soup, 2, 0.45, 0.3, 1, 1.2, turns, 48);
  return on_ground(std::move(coil), {0.4, 10, 0.3}, {7, 8, 9}, {0, 1.2, 0});
}

SceneParts holed_scene(const ParamReader& params) {
  params.allow_only({});
  // A thick square frame; the light, off its axis, looks through the hole, whose walls
  // shadow each other (HREs) while the ground under the hole is partly lit.
  GeneratedObject frame{"holed", {}};
  add_extruded_annulus(frame.soup, square_ring(2, 1.2), square_ring(0.9, 1.2), {0, 0.6, 0});
  return on_ground(std::move(frame), {0.7, 9, 0.5}, {4, 9, 7}, {0, 0.6, 0});
}

SceneParts hole_like_scene(const ParamReader& params) {
  params.allow_only({});
  // A U standing on its base, its notch open to the light: the notch floor is lit through
  // what looks like a hole from the light but is not one. The camera's right axis is +x, so
  // the arms' flat tops are constant-theta edges: equal adjacent peaks of the RE loop.
  GeneratedObject u{"hole-like", {}};
  add_extruded_outline(u.soup,
                       {{-2, 0.3, 0},
                        {2, 0.3, 0},
                        {2, 2.3, 0},
                        {1, 2.3, 0},
                        {1, 0.9, 0},
                        {-1, 0.9, 0},
                        {-1, 2.3, 0},
                        {-2, 2.3, 0}},
                       {0, 0, 1.5});
  return on_ground(std::move(u), {2.5, 6.5, 3.5}, {0, 5.5, 9}, {0, 1, 0.75});
}

}  // namespace shadowkit::generators
