// No exact method may depend on where a scene sits or on its units: each scene below is
// written as given and moved whole (translated by 1e9 and 1e12, scaled by 1e-6 and 1e6 about
// the origin), and every light's mask must agree with the unmoved scene's mask from the same
// method in all but 0.01% of interior pixels. The working frame (WorldFrame) is what makes
// this hold: float and tolerance-based geometry computed at 1e9 from the origin loses the
// digits that decide near-coplanar faces.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "shadowkit/core/error.h"
#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/generators.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kExamples = fs::path(SHADOWKIT_SOURCE_DIR) / "examples";

// Small enough for the whole suite under AddressSanitizer, large enough that 0.01% of the
// interior pixels is a handful of pixels rather than none.
constexpr int kWidth = 320, kHeight = 180;
constexpr double kMaxInteriorMismatchPct = 0.01;

/// \brief p -> k p + t, applied to a whole scene.
struct Similarity {
  std::string name;
  double k;
  Vec3 t;
};

// The loader refuses geometry whose largest extent is below 1e-11 of its largest coordinate;
// every scene below is at least 14 across, so at 1e12 (a limit of 10) it is computed.
const std::vector<Similarity> kSimilarities = {
    {"translated by (1e9, -2e9, 3e9)", 1, {1e9, -2e9, 3e9}},
    {"translated by (1e12, -1e12, 1e12)", 1, {1e12, -1e12, 1e12}},
    {"scaled by 1e-6", 1e-6, {}},
    {"scaled by 1e6", 1e6, {}},
};

json array_of(Vec3 p) {
  return json::array({p.x, p.y, p.z});
}
Vec3 vec3_of(const json& a) {
  return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
}

/// \p scene (a scene file's JSON without a root "generator") with \p s applied to it. An
/// object's transform p' = T Rz Ry Rx S p followed by k p + t is the transform with
/// translate k T + t and scale k S, since k is uniform; directional lights do not change.
json moved(json scene, const Similarity& s) {
  const auto move_point = [&](json& p) { p = array_of(vec3_of(p) * s.k + s.t); };
  move_point(scene["camera"]["position"]);
  move_point(scene["camera"]["look_at"]);
  for (json& light : scene["lights"]) {
    if (light["type"] == "point") move_point(light["position"]);
  }
  for (json& object : scene["objects"]) {
    json& transform = object["transform"];
    if (!transform.contains("translate")) transform["translate"] = array_of({});
    move_point(transform["translate"]);
    if (!transform.contains("scale")) {
      transform["scale"] = s.k;
    } else if (transform["scale"].is_number()) {
      transform["scale"] = s.k * transform["scale"].get<double>();
    } else {
      transform["scale"] = array_of(vec3_of(transform["scale"]) * s.k);
    }
  }
  return scene;
}

json camera_json(const Camera& c) {
  return {{"position", array_of(c.position)},
          {"look_at", array_of(c.look_at)},
          {"up", array_of(c.up)},
          {"fov_y_deg", c.fov_y_deg},
          {"width", kWidth},
          {"height", kHeight}};
}

// Every primitive generator and a mesh file, each under a transform with rotations (and a
// non-uniform scale on the sphere), over a ground; a point and a directional light.
json mixed_scene() {
  json scene = json::parse(R"({
    "camera": {"position": [5, 5, 8], "look_at": [0, 0.6, 0], "up": [0, 1, 0], "fov_y_deg": 45},
    "lights": [
      {"type": "point", "position": [-3, 6, 3]},
      {"type": "directional", "direction": [0.5, -1, -0.4]}
    ],
    "objects": [
      {"generator": "ground", "size": 20},
      {"generator": "box", "size": [1.2, 0.8, 1.6],
       "transform": {"rotate_deg": [0, 35, 0], "translate": [-2, 0.4, 0.5]}},
      {"generator": "sphere", "radius": 0.7, "segments": 24, "rings": 12,
       "transform": {"scale": [1, 1.3, 1], "translate": [1.5, 1.2, 0.8]}},
      {"generator": "tetrahedron", "size": 1.5,
       "transform": {"rotate_deg": [180, 20, 0], "translate": [0.2, 1.8, -1.5]}},
      {"mesh": "pebble.obj",
       "transform": {"scale": 1.5, "rotate_deg": [-90, 40, 0], "translate": [-0.5, 0.39, 2.2]}}
    ]
  })");
  scene["camera"]["width"] = kWidth;
  scene["camera"]["height"] = kHeight;
  scene["objects"][4]["mesh"] = (kExamples / "models" / "pebble.obj").string();
  return scene;
}

// examples/default.json (a torus knot, an open non-manifold sheet, solids; a point and a
// directional light) with its mesh files named from anywhere.
json default_example() {
  json scene = json::parse(std::ifstream(kExamples / "default.json"));
  for (json& object : scene["objects"]) {
    if (object.contains("mesh"))
      object["mesh"] = (kExamples / object["mesh"].get<std::string>()).string();
  }
  scene["camera"]["width"] = kWidth;
  scene["camera"]["height"] = kHeight;
  return scene;
}

// A built-in scene spelt out, its geometry as one object generator with \p params, so that
// it can be moved.
json builtin(const json& params) {
  const SceneSource source = builtin_scene_source(params, params.dump());
  json lights = json::array();
  for (const Light& light : source.lights) {
    lights.push_back(light.type == Light::Type::point
                         ? json{{"type", "point"}, {"position", array_of(light.position)}}
                         : json{{"type", "directional"}, {"direction", array_of(light.direction)}});
  }
  return {{"camera", camera_json(source.camera)},
          {"lights", lights},
          {"objects", json::array({params})}};
}

json scene_json(const std::string& name) {
  if (name == "mixed") return mixed_scene();
  if (name == "default") return default_example();
  // 14 rather than the default 10 across, for the 1e12 translation.
  if (name == "room") return builtin({{"generator", "room"}, {"size", 14}});
  return builtin({{"generator", name}});
}

/// \brief A method's mask for every light of a scene, and the scene's object per pixel.
struct SceneMasks {
  std::vector<ShadowMask> masks;
  std::vector<std::uint32_t> object_ids;
};

class FrameInvariance : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name =
        std::string("shadowkit_frame_") + std::to_string(::getpid()) + "_" + info->name();
    for (char& c : name) c = c == '/' ? '_' : c;
    dir_ = fs::temp_directory_path() / name;
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const json& scene, const std::string& name) {
    const fs::path path = dir_ / (name + ".json");
    std::ofstream(path) << scene.dump(2);
    return path;
  }

  SceneMasks masks_of(const fs::path& path, const std::string& method_name) {
    const Scene scene = load_scene_file(path, quiet_);
    const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, quiet_);
    const auto method = make_method(method_name, {});
    method->prepare(scene, quiet_);
    SceneMasks out{{}, vsb.object_ids()};
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      method->build(scene, l, quiet_);
      ShadowMask mask(vsb.width, vsb.height, kMaskBackground);
      method->shade(scene, vsb, mask, quiet_);
      out.masks.push_back(std::move(mask));
    }
    return out;
  }

  fs::path dir_;
  Context quiet_{0, [](const std::string&) {}};
};

/// Interior pixels (compare_masks's definition) of \p mask whose value is \p value: those
/// that a copy with \p value flipped disagrees with.
std::size_t interior_pixels_of(const ShadowMask& mask, const std::vector<std::uint32_t>& ids,
                               std::uint8_t value) {
  ShadowMask flipped = mask;
  for (std::uint8_t& p : flipped.pixels) {
    if (p == value) p = value == kMaskLit ? kMaskShadow : kMaskLit;
  }
  return compare_masks(mask, flipped, ids).interior_mismatched;
}

TEST_P(FrameInvariance, MovedSceneGivesTheSameMasks) {
  const auto& [scene_name, method_name] = GetParam();
  const json scene = scene_json(scene_name);
  const SceneMasks reference = masks_of(write(scene, "reference"), method_name);
  ASSERT_EQ(reference.masks.size(), scene["lights"].size());
  for (std::size_t l = 0; l < reference.masks.size(); ++l) {
    // Both kinds of interior pixel, or agreement would prove nothing.
    EXPECT_GT(interior_pixels_of(reference.masks[l], reference.object_ids, kMaskLit), 100u)
        << "light " << l;
    EXPECT_GT(interior_pixels_of(reference.masks[l], reference.object_ids, kMaskShadow), 100u)
        << "light " << l;
  }
  for (std::size_t i = 0; i < kSimilarities.size(); ++i) {
    const Similarity& s = kSimilarities[i];
    SCOPED_TRACE(s.name);
    const SceneMasks masks =
        masks_of(write(moved(scene, s), "moved" + std::to_string(i)), method_name);
    ASSERT_EQ(masks.masks.size(), reference.masks.size());
    double worst = 0;
    for (std::size_t l = 0; l < masks.masks.size(); ++l) {
      const MaskComparison c =
          compare_masks(reference.masks[l], masks.masks[l], reference.object_ids);
      EXPECT_LE(c.interior_pct(), kMaxInteriorMismatchPct)
          << "light " << l << ": " << c.interior_mismatched << " of " << c.interior_pixels;
      worst = std::max(worst, c.interior_pct());
    }
    std::printf("[frame] %-12s %-8s %-34s worst interior mismatch %.4f%%\n", scene_name.c_str(),
                method_name.c_str(), s.name.c_str(), worst);
  }
}

INSTANTIATE_TEST_SUITE_P(
    ExactMethods, FrameInvariance,
    ::testing::Combine(::testing::Values("mixed", "default", "three-lights", "room"),
                       ::testing::Values("raytrace", "volume", "svbsp", "angular")),
    [](const ::testing::TestParamInfo<std::tuple<std::string, std::string>>& param_info) {
      std::string name = std::get<0>(param_info.param) + "_" + std::get<1>(param_info.param);
      for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

// A scene a micrometre across a billion units out has too few digits in its coordinates to
// describe it: refused, not computed from rounding noise.
TEST(FrameInvarianceLimits, TinySceneFarFromTheOriginIsRefused) {
  const fs::path path =
      fs::temp_directory_path() / ("shadowkit_frame_tiny_" + std::to_string(::getpid()) + ".json");
  json scene = moved(moved(mixed_scene(), {"", 1e-6, {}}), {"", 1, {1e9, -2e9, 3e9}});
  // The camera stays where it was: moved with the scene, its view would be 1e-5 long 3e9
  // from the origin, which the camera's own check refuses before the geometry's.
  scene["camera"] = mixed_scene()["camera"];
  std::ofstream(path) << scene.dump();
  std::string error = "no error";
  try {
    load_scene_file(path, {0, [](const std::string&) {}});
  } catch (const InputError& e) {
    error = e.what();
  }
  fs::remove(path);
  // The 20e-6 ground's extent, rounded to 2.0027e-05 by coordinates near 1e9, against 3e9.
  EXPECT_THAT(error, ::testing::StartsWith(path.string() + ": the geometry is 2.00"));
  EXPECT_THAT(error, ::testing::HasSubstr(" across but lies 3e+09 from the origin: its coordinates "
                                          "hold too few digits of its shape"));
}

}  // namespace
}  // namespace shadowkit
