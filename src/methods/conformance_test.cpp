// The conformance table: the one place that says what "correct" means (docs/design.md, "What
// correct means"). Each row is {method, settings, scene, tolerance}. The row's method and the
// reference, `raytrace`, shade every light of the scene over one visible-surface buffer, and
// the interior mismatch of each light (mask_compare.h) must stay within the row's tolerance.
// A row that expects a refusal asserts the method's InputError instead.
//
// Scenes: every built-in scene, every example scene (examples/*.json, examples/sweep/*.json)
// and degenerate cases built here. The per-method suites test internals, not agreement;
// raytrace itself is checked against an independent caster (raytrace/contract_reference_test).
//
// `ctest -R Conformance` runs the rows and `-V` shows each row's line; `conformance_test` run
// by itself also prints the whole table in markdown when it ends.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "shadowkit/core/error.h"
#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/generators.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;

const fs::path kExamples = fs::path(SHADOWKIT_SOURCE_DIR) / "examples";

// Built-in and example scenes are seen by their own camera at this reduced size; the sweep's
// scenes keep their own (at most 320x240), where they were found to fail.
constexpr int kWidth = 240, kHeight = 135;

// ---- Scenes -----------------------------------------------------------------------------

Scene builtin(const std::string& spec) {
  return testing::resized(load_scene(spec, {}), kWidth, kHeight);
}

Scene example(const std::string& file) {
  return testing::resized(load_scene_file(kExamples / file, {}), kWidth, kHeight);
}

Scene sweep(const std::string& file) {
  return load_scene_file(kExamples / "sweep" / file, {});
}

const PolygonSoup kGround = testing::horizontal_quad(-10, 10, -10, 10, 0);

Camera view(Vec3 eye, Vec3 look_at = {0, 0.5, 0}) {
  return testing::camera(eye, look_at, kWidth, kHeight);
}

// The ground, a box floating at 0.2 to 1.2 and an open square above it, everything scaled by
// \p s about the origin.
std::vector<PolygonSoup> box_and_square(double s = 1) {
  return {testing::horizontal_quad(-10 * s, 10 * s, -10 * s, 10 * s, 0),
          testing::box(Vec3{-1, 0.2, -1} * s, Vec3{1, 1.2, 1} * s),
          testing::horizontal_quad(-0.5 * s, 1.5 * s, 1.5 * s, 2.5 * s, 2 * s)};
}

// The closed box [-1, 1] x [0.5, 2.5] x [-1, 1] moved by \p offset, without its +x face when
// \p open.
PolygonSoup floating_box(bool open, Vec3 offset) {
  PolygonSoup closed = testing::box(Vec3{-1, 0.5, -1} + offset, Vec3{1, 2.5, 1} + offset);
  if (!open) return closed;
  PolygonSoup out;
  out.positions = closed.positions;
  for (std::size_t f = 0; f < closed.face_count(); ++f) {
    if (f == 1) continue;  // +x
    out.add_face({closed.indices.begin() + closed.face_start[f],
                  closed.indices.begin() + closed.face_start[f + 1]});
  }
  return out;
}

// A directional light exactly along \p d, which must be a unit vector: renormalizing could
// round it off an axis.
Light along(Vec3 d) {
  return Light{Light::Type::directional, {}, d};
}

// tetra:3 under directional lights along the camera's right axis and along -right (a sun on
// the horizon to the camera's east or west), each also turned off its axis by \p angle toward
// the camera's down and forward axes; \p exact keeps the lights on the axes too. angular's
// theta-planes all hold a light along the axis (light_frame.cpp), and are the usual planes
// through the axis once the light is turned off it by any angle.
Scene sun_beside_the_right_axis(double angle, bool exact) {
  Scene scene = builtin("tetra:3");
  const Camera& cam = scene.camera;
  scene.lights.clear();
  for (const double sign : {1.0, -1.0}) {
    const Vec3 axis = cam.right() * sign;
    if (exact) scene.lights.push_back(along(axis));
    for (const Vec3 toward : {-cam.true_up(), cam.forward()}) {
      scene.lights.push_back(along(axis * std::cos(angle) + toward * std::sin(angle)));
    }
  }
  return scene;
}

/// \brief A scene of the table, and how to make it.
struct SceneEntry {
  std::string name;
  std::function<Scene()> make;
};

const std::vector<SceneEntry>& scene_catalog() {
  static const std::vector<SceneEntry> catalog = [] {
    std::vector<SceneEntry> c;
    // Every built-in scene (shadowkit info), the cube field at a modest count.
    for (const char* spec : {"cubes:64", "terrain:40", "tetra:3", "room", "table", "three-lights",
                             "square", "coil", "holed", "hole-like"}) {
      c.push_back({spec, [spec] { return builtin(spec); }});
    }
    // Every example scene.
    for (const char* file :
         {"cubes-2000.json", "default.json", "formats.json", "house.json", "open-meshes.json",
          "room.json", "subdivision.json", "three-lights.json"}) {
      c.push_back({file, [file] { return example(file); }});
    }
    // The smallest failing scenes of scripts/mismatch_sweep.py.
    for (const char* file :
         {"angular-coarse-torus-self-shadow.json", "angular-crease-grazed-by-a-light.json",
          "angular-eye-inside-box.json", "angular-fins-around-a-light-full-turn.json",
          "angular-grazing-light-far-shadow.json",
          "angular-knot-shadow-under-a-light-on-the-ground.json",
          "angular-light-axis-along-box-top.json", "angular-light-in-the-plane-of-box-bottoms.json",
          "angular-light-inside-touching-boxes.json", "angular-low-sun-along-a-torus.json",
          "angular-open-box-face-steep-to-the-light.json", "angular-prism-on-a-large-ground.json",
          "angular-resolution-grazing-light.json",
          "angular-run-starting-on-an-occluders-plane.json",
          "angular-saturation-grazing-light.json",
          "light-in-the-plane-of-a-ground-of-triangles.json",
          "raytrace-light-in-ceiling-plane.json", "svbsp-cut-point-snapped-off-a-knot-face.json",
          "volume-light-inside-box.json"}) {
      c.push_back({std::string("sweep/") + file, [file] { return sweep(file); }});
    }

    // ---- Degenerate cases ----
    const Camera cam = view({6, 5, 7});
    // Lights in face planes: a point light in the plane of the box's top face (that face is
    // in shadow and casts nothing; its neighbours' edges cast shadow planes that hold the
    // light), one in the ground's plane (the whole ground fails condition 1), a sun, and a
    // sun level with the ground. The same scene 1e-6 and 1e6 times its size, not brought to
    // the working frame: every tolerance in a method must be relative to the scene.
    for (const double s : {1.0, 1e-6, 1e6}) {
      const std::string name = s == 1  ? "lights-in-face-planes"
                               : s < 1 ? "lights-in-face-planes-scaled-by-1e-6"
                                       : "lights-in-face-planes-scaled-by-1e6";
      c.push_back({name, [s] {
                     return testing::make_scene(
                         testing::camera(Vec3{6, 5, 7} * s, Vec3{0, 0.5, 0} * s, kWidth, kHeight),
                         {testing::point_light(Vec3{-2, 1.2, 1} * s),
                          testing::point_light(Vec3{3, 0, 0} * s),
                          testing::directional_light({0.3, -1, -0.2}),
                          testing::directional_light({0.5, 0, -1})},
                         box_and_square(s));
                   }});
    }
    // A point light at a corner of the box: three face planes hold it, and every ray to it
    // from the ground in front of the box ends on the box.
    c.push_back(
        {"light-at-a-box-corner", [cam] {
           return testing::make_scene(cam, {testing::point_light({1, 1.2, 1})}, box_and_square());
         }});
    // A point light inside a closed box (no contour edge: everything outside it is in
    // shadow) and one inside a box without its +x face (the light escapes through the hole).
    c.push_back({"lights-inside-a-closed-and-an-open-box", [] {
                   return testing::make_scene(
                       view({8, 7, 3}, {0, 0, 0}),
                       {testing::point_light({-1.9, 1.5, -0.2}), testing::point_light({2, 1.5, 0})},
                       {kGround, floating_box(false, {-2, 0, 0}), floating_box(true, {2, 0, 0})});
                 }});
    // A sun 3 degrees above the horizon (the ground is grazed, the box's shadow is long) and
    // a sun straight down (every vertical face's plane holds it).
    c.push_back({"suns-grazing-and-straight-down", [cam] {
                   return testing::make_scene(
                       cam, {testing::directional_light({1, -0.0524, 0.2}), along({0, -1, 0})},
                       box_and_square());
                 }});
    c.push_back(
        {"sun-along-the-camera-right-axis", [] { return sun_beside_the_right_axis(1e-4, true); }});
    // Turned 1e-7 off the axis toward forward, the sun is 3.4e-8 rad above the horizon.
    c.push_back({"sun-1e-7-off-the-camera-right-axis",
                 [] { return sun_beside_the_right_axis(1e-7, false); }});
    // The same closed box twice, at one spot: each copy's faces lie in the other's planes.
    c.push_back({"coincident-boxes", [cam] {
                   return testing::make_scene(cam,
                                              {testing::point_light({-2, 5, 3}),
                                               testing::directional_light({0.4, -1, -0.3})},
                                              {kGround, testing::box({-1, 0.2, -1}, {1, 1.2, 1}),
                                               testing::box({-1, 0.2, -1}, {1, 1.2, 1})});
                 }});
    // Faces touching and coplanar: a box standing on the ground (its bottom face lies in the
    // ground's plane, and its shadows start at the contact line), a square lying on the
    // ground, and two squares of different objects overlapping in one plane above them.
    c.push_back({"touching-and-coplanar-faces", [cam] {
                   return testing::make_scene(cam,
                                              {testing::point_light({-3, 5, 2}),
                                               testing::directional_light({0.5, -1, -0.4})},
                                              {kGround, testing::box({-1, 0, -1}, {1, 2, 1}),
                                               testing::horizontal_quad(-3, -1, 1, 3, 0),
                                               testing::horizontal_quad(0, 1.5, 1.5, 2.5, 3),
                                               testing::horizontal_quad(-0.5, 1, 1, 2, 3)});
                 }});
    // Nothing casts a shadow on the ground.
    c.push_back({"no-occluder", [cam] {
                   return testing::make_scene(cam,
                                              {testing::point_light({-2, 4, 3}),
                                               testing::directional_light({0.4, -1, -0.3})},
                                              {kGround});
                 }});
    // A point light 1e-3 above the ground beside a box, and one 1e-4 off the box's +x face.
    c.push_back({"light-very-close-to-a-surface", [cam] {
                   return testing::make_scene(cam,
                                              {testing::point_light({2.5, 1e-3, 1.5}),
                                               testing::point_light({1 + 1e-4, 0.7, 0.2})},
                                              box_and_square());
                 }});
    // The camera inside a closed box, with a square inside it; one light outside (all in
    // shadow) and one inside (the square's shadow on the walls).
    c.push_back({"camera-inside-a-closed-box", [] {
                   return testing::make_scene(
                       view({0.5, 0.3, 0.8}, {-1, -0.5, -1}),
                       {testing::point_light({5, 6, 4}), testing::point_light({0.3, 1.5, 0.2})},
                       {testing::box({-2, -2, -2}, {2, 2, 2}),
                        testing::horizontal_quad(-1, 0, -1, 0, 0.5)});
                 }});
    // The camera in the ground's plane, looking up at the square and at a box behind it:
    // the ground is seen edge-on, and no count at the eye exists.
    c.push_back({"camera-in-the-ground-plane", [] {
                   return testing::make_scene(view({0, 0, 6}, {0, 1, 0}),
                                              {testing::point_light({0, 4, 0})},
                                              {kGround, testing::horizontal_quad(-1, 1, -1, 1, 1),
                                               testing::box({-2.5, 0, -4}, {2.5, 2.5, -2})});
                 }});
    // The camera on the plane through the light and the square's edge x = 1: the near
    // plane cuts that shadow plane.
    c.push_back({"camera-on-a-shadow-plane", [] {
                   return testing::square_over_plane(view({1.25, 0.25, 0.1}, {3, 0, 2}),
                                                     testing::point_light({0, 4, 0}));
                 }});
    // A box beside a point light holds the light's X axis (angular's frame) in its shadow.
    c.push_back({"light-beside-a-box-on-its-axis", [] {
                   return testing::make_scene(
                       testing::camera({-1.95, 3.59, -2.55}, {-0.42, 0.2, -0.29}, 320, 240, 40),
                       {testing::point_light({1.84, 1.48, -0.65})},
                       {testing::horizontal_quad(-6, 6, -6, 6, 0),
                        testing::box({0.22, 0, 0.25}, {2.02, 1.8, 2.05})});
                 }});
    // The room's light moved into the camera's own plane (beside and above the eye, at its
    // depth) and just in front of and behind it.
    c.push_back({"room-lights-in-the-camera-plane", [] {
                   Scene scene = builtin("room");
                   const Camera& eye = scene.camera;
                   const Vec3 beside = eye.position + eye.right() * -0.5 + eye.true_up() * 0.8;
                   scene.lights.clear();
                   for (const double depth : {-0.05, 0.0, 0.05}) {
                     scene.lights.push_back(Light::point(beside + eye.forward() * depth));
                   }
                   return scene;
                 }});
    return c;
  }();
  return catalog;
}

Scene scene_named(const std::string& name) {
  for (const SceneEntry& e : scene_catalog()) {
    if (e.name == name) return e.make();
  }
  ADD_FAILURE() << "no scene '" << name << "' in the catalog";
  return {};
}

// ---- Rows -------------------------------------------------------------------------------

/// \brief One row of the table.
struct Row {
  std::string method;
  std::map<std::string, std::string> settings;
  std::string scene;
  double tolerance_pct = 0;   ///< allowed interior mismatch of every light, percent
  std::string refusal;        ///< when set: the method refuses, and its InputError says this
  std::string known_failure;  ///< when set: why the method exceeds the tolerance it should meet
};

std::string settings_text(const Row& row) {
  std::string s;
  for (const auto& [key, value] : row.settings) s += (s.empty() ? "" : ",") + key + "=" + value;
  return s.empty() ? "defaults" : s;
}

void PrintTo(const Row& row, std::ostream* os) {
  *os << row.method << " " << settings_text(row) << " " << row.scene;
}

// Tolerances, in percent of the interior pixels (docs/design.md, "What correct means").

// volume and svbsp are exact up to the scan converter's sample points: the raster decides
// only which pixel centres a shadow polygon or a fragment covers, and a centre within snapping
// distance (1/256 pixel) of its edge lies on a shadow boundary, which the interior excludes.
// What is left are isolated single pixels: a centre within rounding of an edge that the
// reference's 3x3 neighbourhood does not show (a fragment's sliver, a shadow ray grazing an
// edge), or the reference's own float rounding (docs/methods/raytrace.md). The largest
// measured is 0.037% (svbsp on the subdivision example, 6 pixels); 0.05% of the ~20,000
// interior pixels of these images is ten.
constexpr double kExact = 0.05;

// angular cuts each pair at its entry's centre theta, half an entry from the truth. With the
// automatic R (eq. 4: about one entry per scan line where the scene is seen) the shadow's
// edge is then within a pixel or so of the truth, and on receivers the light meets at less
// than 4 degrees answers are re-checked exactly (kGrazingSine). A few pixels a scene remain:
// 0.2%, the largest measured being 0.15% (the knot under a light on the ground).
constexpr double kAngular = 0.2;
// On a finely tessellated open curved surface (the subdivision example's open box) the half
// entry reaches past the terminator onto lit faces (docs/methods/angular.md). The automatic R
// follows the image's scan lines, so at 135 rows the reach covers more pixels: 0.68% here,
// 0.22% at 480x270, 0.04% at 1280x720 or at R = 1000 (the row below).
constexpr double kAngularOpenCurvedSurface = 1.0;

// shadowmap at `resolution` texels a side. Two errors of the method's own:
// - Aliasing: a shadow edge is off by up to a texel's footprint on the receiver. Where that
//   footprint is wider than a pixel, a band along the edge falls in the interior; the band
//   halves each time the resolution doubles (docs/methods/shadowmap.md): 0.1% at 1024 texels,
//   scaled by 1024 / resolution (cubes-2000: 0.15% at 256, 0.048% at 512, 0.011% at 1024).
//   The table's rows take 512 texels, a sixteenth of the default's cube map.
// - Acne on faces the light grazes past the slope cap (84.3 degrees): whole faces that shadow
//   themselves, which a finer map does not mend. A scene's allowance for it is the share of
//   its interior on such faces, in the table below; 0 for most.
std::map<std::string, std::string> shadowmap_at(int resolution) {
  return {{"resolution", std::to_string(resolution)}};
}
double shadowmap_tolerance(double acne_pct, int resolution) {
  return acne_pct + 0.1 * 1024.0 / resolution;
}

// voxel at M voxels along the bound's longest side. A voxel holds one state, so a shadow edge
// is stair-stepped at the voxel size, and everything within a voxel of a contact line or of a
// thin part shares one state. Both bands are a voxel wide, and the mismatch falls at least as
// fast as 1/M (docs/methods/voxel.md; square: 0.39% at M = 64, 0.26% at 128, 0 at 256;
// cubes:64: 2.1%, 0.72%, 0.05%), so a row's tolerance is its scene's tolerance at M = 64
// scaled by 64 / M. The table runs every scene at M = 64, where the voxel costs a quarter of
// M = 128, and the built-in scenes and the cases with the widest bands again at 128.
// At M = 64: 1% for most scenes; 2.5% where many small casters stand on the ground; 10% for
// a camera at or just above the ground's level, which sees a voxel-high band along the
// contact lines and shadow edges magnified (camera-in-the-ground-plane: 8.2% at 64, 0.09% at
// 128).
std::map<std::string, std::string> voxel_at(int m, const char* test = "topology") {
  return {{"resolution", std::to_string(m)}, {"test", test}};
}
double voxel_tolerance(double pct_at_64, int m) {
  return pct_at_64 * 64.0 / m;
}
constexpr double kVoxelBand = 1.0, kVoxelWideBand = 2.5, kVoxelLowCamera = 10;

/// \brief A scene's tolerances for every method at the table's standard settings: shadowmap
/// at 512 texels (its column is the acne allowance), voxel at M = 64 with the topology test,
/// the others at their defaults. `voxel_at_128` adds a voxel row at M = 128.
struct SceneTolerances {
  const char* scene;
  double shadowmap_acne, volume, svbsp, angular, voxel;
  bool voxel_at_128 = false;
};

constexpr int kMapResolution = 512, kVoxels = 64;

// clang-format off
const SceneTolerances kTolerances[] = {
    // scene                                      shadowmap volume  svbsp   angular   voxel (M = 64)
    // -- built-in scenes
    {"cubes:64",                                    0,      kExact, kExact, kAngular, kVoxelWideBand, true},
    // A sun 17 degrees high stretches a texel's footprint on the slopes 3.4 times along its
    // light, and its shadows' edges run over the whole view: 0.63% at 512 texels, 0.27% at
    // 2048, 0.15% at 8192. The voxel's band along those edges: 1.8% at M = 64.
    {"terrain:40",                                  0.5,    kExact, kExact, kAngular, kVoxelWideBand, true},
    {"tetra:3",                                     0,      kExact, kExact, kAngular, kVoxelBand,     true},
    {"room",                                        0,      kExact, kExact, kAngular, kVoxelBand,     true},
    // Acne on a face of a chair that the point light meets at 89 degrees: 0.16%.
    {"table",                                       0.3,    kExact, kExact, kAngular, kVoxelWideBand, true},
    // Acne on a face of the prism that the second point light meets at 89.9 degrees: 0.12%
    // to 0.75% of the interior, as the texels fall.
    {"three-lights",                                1.0,    kExact, kExact, kAngular, kVoxelBand,     true},
    {"square",                                      0,      kExact, kExact, kAngular, kVoxelBand,     true},
    {"coil",                                        0,      kExact, kExact, kAngular, kVoxelBand,     true},
    {"holed",                                       0,      kExact, kExact, kAngular, kVoxelBand,     true},
    {"hole-like",                                   0,      kExact, kExact, kAngular, kVoxelBand,     true},
    // -- examples/
    {"cubes-2000.json",                             0,      kExact, kExact, kAngular, kVoxelBand},
    // Acne on a face of the box that the directional light meets at 88 degrees
    // (docs/methods/shadowmap.md): 0.27%.
    {"default.json",                                0.5,    kExact, kExact, kAngular, kVoxelWideBand},
    {"formats.json",                                0,      kExact, kExact, kAngular, kVoxelBand},
    // The pergola's 5 cm slats and the 15 cm window reveals, under voxels of 0.9 m (a 60 m
    // lot at M = 64): 2.1%.
    {"house.json",                                  0,      kExact, kExact, kAngular, kVoxelWideBand},
    {"open-meshes.json",                            0,      kExact, kExact, kAngular, kVoxelBand},
    {"room.json",                                   0,      kExact, kExact, kAngular, kVoxelBand},
    {"subdivision.json",                            0,      kExact, kExact, kAngularOpenCurvedSurface, kVoxelBand},
    {"three-lights.json",                           1.0,    kExact, kExact, kAngular, kVoxelBand},
    // -- examples/sweep/
    {"sweep/angular-coarse-torus-self-shadow.json", 0,      kExact, kExact, kAngular, kVoxelBand},
    // A point light grazing the open box's faces: shadowmap's acne there, 0.80%.
    {"sweep/angular-crease-grazed-by-a-light.json", 1.0,    kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-eye-inside-box.json",           0,      kExact, kExact, kAngular, kVoxelBand},
    // Two fins around a point light: shadowmap's cube map differs on 1.7% of the interior.
    {"sweep/angular-fins-around-a-light-full-turn.json",
                                                    2.0,    kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-grazing-light-far-shadow.json", 0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-knot-shadow-under-a-light-on-the-ground.json",
                                                    0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-light-axis-along-box-top.json", 0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-light-in-the-plane-of-box-bottoms.json",
                                                    0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-light-inside-touching-boxes.json",
                                                    0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-low-sun-along-a-torus.json",    0,      kExact, kExact, kAngular, kVoxelBand},
    // The open box's face steep to a high light: shadowmap's acne there, 4.1%; voxel 1.8%.
    {"sweep/angular-open-box-face-steep-to-the-light.json",
                                                    4.5,    kExact, kExact, kAngular, kVoxelWideBand},
    {"sweep/angular-prism-on-a-large-ground.json",  0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-resolution-grazing-light.json", 0,      kExact, kExact, kAngular, kVoxelBand},
    // A ground's scan line whose first lookup lies within the tolerance of the open box's
    // wall plane, not behind it yet: the lit answer held to the pair's end (a row, 0.63%).
    {"sweep/angular-run-starting-on-an-occluders-plane.json",
                                                    0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/angular-saturation-grazing-light.json", 0,      kExact, kExact, kAngular, kVoxelBand},
    // A point light in the ground's plane, which in working coordinates lies a rounding
    // off the plane of the ground's triangles: the ground fails condition 1 in every method.
    {"sweep/light-in-the-plane-of-a-ground-of-triangles.json",
                                                    0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/raytrace-light-in-ceiling-plane.json",  0,      kExact, kExact, kAngular, kVoxelBand},
    // A fragment's corner on a knot face's outline snaps off it on the raster, and the pixel
    // centre beside it is owned by no fragment: svbsp shadowed it (one pixel, 0.064%).
    {"sweep/svbsp-cut-point-snapped-off-a-knot-face.json",
                                                    0,      kExact, kExact, kAngular, kVoxelBand},
    {"sweep/volume-light-inside-box.json",          0,      kExact, kExact, kAngular, kVoxelBand},
    // -- degenerate cases
    {"lights-in-face-planes",                       0,      kExact, kExact, kAngular, kVoxelBand},
    {"lights-in-face-planes-scaled-by-1e-6",        0,      kExact, kExact, kAngular, kVoxelBand},
    {"lights-in-face-planes-scaled-by-1e6",         0,      kExact, kExact, kAngular, kVoxelBand},
    {"light-at-a-box-corner",                       0,      kExact, kExact, kAngular, kVoxelBand,     true},
    {"lights-inside-a-closed-and-an-open-box",      0,      kExact, kExact, kAngular, kVoxelBand},
    {"suns-grazing-and-straight-down",              0,      kExact, kExact, kAngular, kVoxelBand},
    {"sun-along-the-camera-right-axis",             0,      kExact, kExact, kAngular, kVoxelBand},
    {"sun-1e-7-off-the-camera-right-axis",          0,      kExact, kExact, kAngular, kVoxelBand},
    {"coincident-boxes",                            0,      kExact, kExact, kAngular, kVoxelBand},
    {"touching-and-coplanar-faces",                 0,      kExact, kExact, kAngular, kVoxelBand},
    {"no-occluder",                                 0,      kExact, kExact, kAngular, kVoxelBand},
    {"light-very-close-to-a-surface",               0,      kExact, kExact, kAngular, kVoxelBand},
    {"camera-inside-a-closed-box",                  0,      kExact, kExact, kAngular, kVoxelBand},
    {"camera-in-the-ground-plane",                  0,      kExact, kExact, kAngular, kVoxelLowCamera, true},
    {"camera-on-a-shadow-plane",                    0,      kExact, kExact, kAngular, kVoxelLowCamera, true},
    {"light-beside-a-box-on-its-axis",              0,      kExact, kExact, kAngular, kVoxelBand},
    {"room-lights-in-the-camera-plane",             0,      kExact, kExact, kAngular, kVoxelBand},
};
// clang-format on

// svbsp.paper=1 filters only the polygons whose front faces the light; the others are in
// shadow and cast nothing (Fig. 3). That is the contract where every polygon turned from a
// light is hidden from it by polygons turned to it: surfaces closed and consistently
// oriented, each light on their front side (outside a solid, inside a room). These scenes
// break the assumption, and the row's tolerance is the difference measured, rounded up
// (docs/papers/chin-feiner-1989.md).
const struct {
  const char* scene;
  double tolerance_pct;
} kSvbspPaperBeyondItsAssumption[] = {
    // Open meshes seen and lit from their back: lit in the contract, in shadow here (0.46%).
    {"open-meshes.json", 0.6},
    // The terrain is open along its border: a ray to the low sun that leaves a hill under
    // the border crosses only faces turned from the light, which cast nothing here (9.2%).
    {"terrain:40", 10},
    // The light sees the inside of the open box, the back of its faces: they cast nothing on
    // the ground, and are in shadow where the contract has them lit (2.1%).
    {"subdivision.json", 2.5},
    // Two fins, open non-manifold meshes, lit from their back around the light (1.9%).
    {"sweep/angular-fins-around-a-light-full-turn.json", 2.0},
    // The light sees the inside of the open box, the back of the wall that shadows the
    // ground: it casts nothing (21%).
    {"sweep/angular-run-starting-on-an-occluders-plane.json", 21.5},
    // A point light on the bottom face of one of the boxes, in its plane and within it: every
    // other face of that box is turned from it, so the box casts nothing, and the side of
    // the box stacked above, which it hides from the light, is lit (5.2%).
    {"sweep/angular-light-in-the-plane-of-box-bottoms.json", 5.5},
    // A light inside a closed box: every wall is turned from it, so nothing casts and the
    // ground around the box is lit (14%, 95%, 80%).
    {"sweep/angular-light-inside-touching-boxes.json", 15},
    {"sweep/volume-light-inside-box.json", 96},
    {"lights-inside-a-closed-and-an-open-box", 81},
    // A light on the box's corner: no face is turned to it, the box casts nothing (13%).
    {"light-at-a-box-corner", 14},
    // The camera and a light inside a closed box: its walls are turned from that light (66%).
    {"camera-inside-a-closed-box", 66},
    // Lights outside the room, whose walls face inward: turned from them, the walls cast
    // nothing (94%).
    {"room-lights-in-the-camera-plane", 94},
};

double svbsp_paper_tolerance(const std::string& scene, double exact) {
  for (const auto& [name, tolerance] : kSvbspPaperBeyondItsAssumption) {
    if (scene == name) return tolerance;
  }
  return exact;
}

/// \brief A row whose method is wrong beyond the tolerance it should meet, and why. The row
/// runs and prints its mismatch, then is skipped; it fails once the method meets the
/// tolerance, so that the entry is removed.
struct KnownFailure {
  const char* method;
  const char* settings;  ///< as settings_text() prints them; nullptr: any
  const char* scene;
  const char* reason;
};

// Acne past the slope cap (docs/methods/shadowmap.md): under a light this close to a
// receiver's plane, the whole receiver shadows itself, at any resolution (the grazing
// sweep scenes: 52.9%, 52.8% and 50.8% at 256, 4096 and 16384 texels).
constexpr const char* kShadowmapAcne =
    "shadowmap: acne on receivers the light grazes past the slope cap; a finer map does not "
    "mend it (Williams's self-shadowing, docs/methods/shadowmap.md)";

const KnownFailure kKnownFailures[] = {
    {"shadowmap", nullptr, "sweep/angular-grazing-light-far-shadow.json", kShadowmapAcne},
    {"shadowmap", nullptr, "sweep/angular-knot-shadow-under-a-light-on-the-ground.json",
     kShadowmapAcne},
    {"shadowmap", nullptr, "sweep/angular-low-sun-along-a-torus.json", kShadowmapAcne},
    {"shadowmap", nullptr, "sweep/angular-resolution-grazing-light.json", kShadowmapAcne},
    {"shadowmap", nullptr, "sweep/angular-saturation-grazing-light.json", kShadowmapAcne},
    {"shadowmap", nullptr, "light-very-close-to-a-surface", kShadowmapAcne},
};

std::string known_failure(const std::string& method, const std::string& settings,
                          const std::string& scene) {
  for (const KnownFailure& k : kKnownFailures) {
    if (method == k.method && scene == k.scene && (!k.settings || settings == k.settings)) {
      return k.reason;
    }
  }
  return {};
}

std::vector<Row> table_rows() {
  std::vector<Row> rows;
  const auto add = [&](const std::string& method, std::map<std::string, std::string> settings,
                       const std::string& scene, double tolerance) {
    Row row{method, std::move(settings), scene, tolerance, {}, {}};
    row.known_failure = known_failure(method, settings_text(row), scene);
    rows.push_back(std::move(row));
  };
  for (const SceneTolerances& t : kTolerances) {
    add("shadowmap", shadowmap_at(kMapResolution), t.scene,
        shadowmap_tolerance(t.shadowmap_acne, kMapResolution));
    add("volume", {}, t.scene, t.volume);
    add("svbsp", {}, t.scene, t.svbsp);
    add("angular", {}, t.scene, t.angular);
    add("voxel", voxel_at(kVoxels), t.scene, voxel_tolerance(t.voxel, kVoxels));
    if (t.voxel_at_128) add("voxel", voxel_at(128), t.scene, voxel_tolerance(t.voxel, 128));
  }

  // Settings, and how they move the mismatch.
  // shadowmap: the texel band shrinks as the resolution grows.
  for (const int r : {256, 1024, 2048}) {
    add("shadowmap", shadowmap_at(r), "cubes-2000.json", shadowmap_tolerance(0, r));
  }
  // voxel: the voxel band shrinks as M grows (64 and 128 are rows above).
  add("voxel", voxel_at(256), "square", voxel_tolerance(kVoxelBand, 256));
  // voxel's offset test (§4.1): the moved point A' falls among the voxels of nearby surfaces
  // at grazing angles and on curved receivers, which the topology test's rays do not
  // (docs/methods/voxel.md); most where many small casters stand on a grazed ground.
  // At M = 128, with the tolerances the voxel suite held them to.
  const struct {
    const char* scene;
    double pct_at_64;
  } offset[] = {{"square", 1},       {"cubes:64", 16}, {"tetra:3", 2},         {"room", 6},
                {"three-lights", 3}, {"table", 8},     {"subdivision.json", 1}};
  for (const auto& [scene, pct] : offset) {
    add("voxel", voxel_at(128, "offset"), scene, voxel_tolerance(pct, 128));
  }
  // Without the frame buffer (§5.1) each visible point is moved along its own face's normal,
  // not its voxel's sample's: the offset test's errors, a little differently placed.
  for (const auto& [scene, pct] : offset) {
    if (std::string(scene) == "room" || std::string(scene) == "table" ||
        std::string(scene) == "subdivision.json") {
      continue;
    }
    auto settings = voxel_at(128, "offset");
    settings["framebuffer"] = "0";
    add("voxel", settings, scene, voxel_tolerance(pct, 128));
  }
  // angular: a fixed R of 1000 entries closes most of the open curved surface's gap.
  add("angular", {{"resolution", "1000"}}, "subdivision.json", kAngular);
  // angular: eq. 4 as written, and Sec. 11.2's hemispheres with the light inside the scene,
  // hold the default's bar (docs/papers/thakur-cheng-miura.md). Without the exact assists
  // (exact=0) the error is the table's, reported against R there, not barred here.
  for (const char* scene : {"cubes:64", "table", "three-lights", "default.json"}) {
    add("angular", {{"resolution", "eq4"}}, scene, kAngular);
  }
  for (const char* scene :
       {"room", "room.json", "sweep/angular-light-inside-touching-boxes.json"}) {
    add("angular", {{"light_inside", "hemispheres"}}, scene, kAngular);
  }
  // angular: the RE-loops paper's own pairing (Sec. 3.2) holds the default's bar everywhere.
  for (const SceneTolerances& t : kTolerances)
    add("angular", {{"pairing", "paper"}}, t.scene, t.angular);
  // volume: depth-pass and depth-fail forced everywhere count the same volumes.
  for (const char* count : {"pass", "fail"}) {
    for (const char* scene : {"cubes:64", "room", "default.json"}) {
      add("volume", {{"count", count}}, scene, kExact);
    }
  }
  // svbsp: the shadowed fragments alone (§6) give the same mask.
  for (const char* scene : {"table", "three-lights"}) {
    add("svbsp", {{"shadowed_only", "1"}}, scene, kExact);
  }
  // svbsp: §6's contour planes (convex solids filtered as units) are as exact as the default;
  // the paper's own algorithm (one-sided, Figs. 3-4) is where its assumption holds, and
  // differs as kSvbspPaperBeyondItsAssumption says elsewhere.
  for (const SceneTolerances& t : kTolerances) {
    add("svbsp", {{"contour_planes", "1"}}, t.scene, t.svbsp);
    add("svbsp", {{"paper", "1"}}, t.scene, svbsp_paper_tolerance(t.scene, t.svbsp));
  }

  // Refusals by design. voxel takes polygons as bilinear patches (docs/methods/voxel.md), so it
  // refuses no scene of the table for holding no Catmull-Clark surface; it refuses a
  // voxelization that would exceed its bound on subpatches.
  // depth-pass needs the count at the eye, which a camera in a face plane leaves undefined.
  rows.push_back({"volume",
                  {{"count", "pass"}},
                  "camera-in-the-ground-plane",
                  0,
                  "pass needs the count at the eye, which object 'object0' leaves undefined",
                  {}});
  // The bound: cubes:64 needs more than 1000 subpatches at M = 128.
  rows.push_back({"voxel",
                  {{"resolution", "128"}, {"max_subpatches", "1000"}},
                  "cubes:64",
                  0,
                  "makes more than 1000 subpatches (voxel.max_subpatches)",
                  {}});
  return rows;
}

std::string row_name(const Row& row) {
  std::string name = row.method;
  for (const auto& [key, value] : row.settings) name += "_" + key + "_" + value;
  name += "_" + row.scene;
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

// ---- The printed table --------------------------------------------------------------------

/// \brief Collects every row's line and prints them as one markdown table at the end.
class TablePrinter : public ::testing::Environment {
 public:
  static std::vector<std::string>& lines() {
    static std::vector<std::string> l;
    return l;
  }
  void TearDown() override {
    if (lines().size() < 2) return;  // a single row (ctest) has printed its line already
    std::printf(
        "\n| method | settings | scene | lights | surface pixels | interior mismatch (worst "
        "light) | tolerance | result |\n|---|---|---|---|---|---|---|---|\n");
    for (const std::string& line : lines()) std::printf("%s\n", line.c_str());
  }
};

const ::testing::Environment* const kPrinter =
    ::testing::AddGlobalTestEnvironment(new TablePrinter);

void record(const Row& row, std::size_t lights, std::size_t surface, const std::string& mismatch,
            const std::string& tolerance, const std::string& result) {
  char line[512];
  std::snprintf(line, sizeof line, "| %s | %s | %s | %zu | %zu | %s | %s | %s |",
                row.method.c_str(), settings_text(row).c_str(), row.scene.c_str(), lights, surface,
                mismatch.c_str(), tolerance.c_str(), result.c_str());
  std::printf("[conformance] %s\n", line);
  TablePrinter::lines().push_back(line);
}

std::string percent(double pct) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f%%", pct);
  return text;
}

// ---- The test ---------------------------------------------------------------------------

class Table : public ::testing::TestWithParam<Row> {};

TEST_P(Table, Agrees) {
  const Row& row = GetParam();
  const Scene scene = scene_named(row.scene);
  ASSERT_FALSE(scene.lights.empty());
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  // Enough surface to compare: agreement on an empty image would prove nothing.
  ASSERT_GE(vsb.covered_count(), 1000u) << row.scene;
  const MethodOptions options(row.method, row.settings);

  if (!row.refusal.empty()) {
    std::string message = "no error";
    try {
      const auto method = make_method(row.method, options);
      method->prepare(scene, {});
      for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        testing::light_mask(*method, scene, vsb, l);
      }
    } catch (const InputError& e) {
      message = e.what();
    }
    EXPECT_THAT(message, ::testing::HasSubstr(row.refusal));
    record(row, scene.lights.size(), vsb.covered_count(), "-", "-",
           message.find(row.refusal) != std::string::npos ? "refused, as expected"
                                                          : "NOT REFUSED AS EXPECTED");
    return;
  }

  const std::vector<MaskComparison> lights =
      testing::compare_with_reference(scene, vsb, row.method, options);
  ASSERT_EQ(lights.size(), scene.lights.size());
  double worst = 0;
  std::string over;  // the lights over the tolerance
  for (std::size_t l = 0; l < lights.size(); ++l) {
    const MaskComparison& c = lights[l];
    worst = std::max(worst, c.interior_pct());
    if (c.interior_pct() <= row.tolerance_pct) continue;
    over += " light " + std::to_string(l) + ": " + std::to_string(c.interior_mismatched) + " of " +
            std::to_string(c.interior_pixels) + " interior pixels differ;";
  }
  const bool agrees = over.empty();
  record(row, lights.size(), vsb.covered_count(), percent(worst), percent(row.tolerance_pct),
         !row.known_failure.empty() ? (agrees ? "KNOWN FAILURE AGREES NOW" : "known failure")
         : agrees                   ? "ok"
                                    : "FAILED");
  if (!row.known_failure.empty()) {
    if (agrees) {
      ADD_FAILURE() << "listed in kKnownFailures but within its tolerance now: remove the entry";
    } else {
      GTEST_SKIP() << "known failure (" << percent(worst) << " > " << percent(row.tolerance_pct)
                   << "): " << row.known_failure;
    }
    return;
  }
  EXPECT_TRUE(agrees) << "over the tolerance of " << percent(row.tolerance_pct) << ":" << over;
}

INSTANTIATE_TEST_SUITE_P(Conformance, Table, ::testing::ValuesIn(table_rows()),
                         [](const ::testing::TestParamInfo<Row>& param_info) {
                           return row_name(param_info.param);
                         });

// Every scene of the catalog has a row per method, and every built-in scene and example scene
// is in the catalog: a new one cannot be left out of the table silently.
TEST(SceneCatalog, HoldsEveryBuiltInAndExampleSceneWithARowPerMethod) {
  const auto in_catalog = [](const std::string& name) {
    // The 584k-triangle knot is a benchmark scene: scale_test holds it to the same bars. The
    // fold scene shows 153 pixels, too few for the table: angular's scenes_test holds it.
    return name == "knot-600k.json" ||
           name == "sweep/angular-visible-point-past-a-fold-edge.json" ||
           std::any_of(scene_catalog().begin(), scene_catalog().end(),
                       [&](const SceneEntry& e) { return e.name == name; });
  };
  std::map<std::string, std::map<std::string, int>> rows;
  for (const Row& row : table_rows()) rows[row.scene][row.method]++;
  for (const SceneEntry& e : scene_catalog()) {
    for (const std::string& method : method_names()) {
      if (method == "raytrace") continue;  // the reference
      EXPECT_GE(rows[e.name][method], 1) << e.name << " " << method;
    }
  }
  for (const std::string& name : builtin_scene_names()) {
    EXPECT_TRUE(std::any_of(
        scene_catalog().begin(), scene_catalog().end(),
        [&](const SceneEntry& e) { return e.name == name || e.name.starts_with(name + ":"); }))
        << name;
  }
  int examples = 0;
  for (const std::string& dir : {std::string(), std::string("sweep/")}) {
    for (const auto& entry : fs::directory_iterator(kExamples / dir)) {
      if (entry.path().extension() != ".json") continue;
      EXPECT_TRUE(in_catalog(dir + entry.path().filename().string())) << entry.path();
      ++examples;
    }
  }
  EXPECT_GE(examples, 18);
}

}  // namespace
}  // namespace shadowkit
