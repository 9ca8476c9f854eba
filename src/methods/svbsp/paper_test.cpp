// svbsp.paper=1: Chin & Feiner's Figs. 3 and 4 as written (one-sided, no §6 refinement), each
// refinement switched on alone, and the settings' errors.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

using Settings = std::map<std::string, std::string>;

const Settings kPaper = {{"paper", "1"}};
const Camera kCamera = testing::camera({0, 9, 6}, {0, 0, 0}, 64, 48);

Settings paper_with(const std::string& refinement) {
  Settings s = kPaper;
  s[refinement] = "1";
  return s;
}

std::size_t lit_count(const std::vector<Fragment>& fragments) {
  std::size_t lit = 0;
  for (const Fragment& f : fragments) lit += f.lit;
  return lit;
}

TEST(SvbspPaper, FigureTwoGivesEveryEdgeOfALitFragmentAPlane) {
  // The scene of Svbsp.FigureTwoSplitsTheFarLineAtTheShadowPlaneThroughB. §7: the paper's
  // implementation tells no edge made by splitting from an original one, so cd's edge in
  // ab's plane and gf's edge at g, in b's plane, get planes too: 4 + 4 + 4, not 10.
  const Scene scene = testing::make_scene(
      kCamera, {testing::point_light({0, 10, 0})},
      {testing::horizontal_quad(-2, -0.5, -1, 1, 6), testing::horizontal_quad(1, 2, -1, 1, 6),
       testing::horizontal_quad(-3, 0, -1, 1, 3)});
  const MethodRun paper = run_method(scene, 0, kPaper);
  EXPECT_EQ(paper.svbsp_nodes, 12);
  EXPECT_EQ(paper.fragments.size(), 4u);
  const auto areas = face_areas(paper.fragments);
  EXPECT_NEAR(areas.at(2).shadowed, (3 - 0.875) * 2, 1e-12);
  EXPECT_EQ(run_method(scene, 0, paper_with("skip_edges_in_tree")).svbsp_nodes, 10);
}

TEST(SvbspPaper, APolygonTurnedFromTheLightIsShadowedAndCastsNothing) {
  // The square of square_over_plane turned upside down: its front faces the ground.
  const Scene scene =
      testing::make_scene(kCamera, {testing::point_light({0, 4, 0})},
                          {testing::horizontal_quad(-10, 10, -10, 10, 0),
                           testing::polygon({{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}})});
  ASSERT_LT(scene.face_plane(1).normal.y, 0);
  const auto paper = face_areas(run_method(scene, 0, kPaper).fragments);
  EXPECT_NEAR(paper.at(0).lit, 400, 1e-10);  // Fig. 3: only polygons facing the light cast
  EXPECT_EQ(paper.at(0).shadowed, 0);
  EXPECT_NEAR(paper.at(1).shadowed, 4, 1e-12);
  // The contract's two-sided surfaces: the square casts from the side the light sees.
  const double side = 8.0 / 3.0;
  const auto two_sided = face_areas(run_method(scene, 0).fragments);
  EXPECT_NEAR(two_sided.at(0).shadowed, side * side, 1e-10);
  EXPECT_NEAR(two_sided.at(1).lit, 4, 1e-12);
}

TEST(SvbspPaper, LightsInAPolygonsPlaneLeaveItShadowedWithoutAShadow) {
  // A quad edge-on to the light (its plane x = 0 holds the light) and the ground's plane
  // holding a second light: each such polygon is shadowed whole and casts nothing, in every
  // mode; from the light on the ground the square's front faces away.
  const Scene scene = testing::make_scene(
      kCamera, {testing::point_light({0, 4, 0}), testing::point_light({3, 0, 0})},
      {testing::horizontal_quad(-10, 10, -10, 10, 0),
       testing::polygon({{0, 1, -1}, {0, 1, 1}, {0, 2, 1}, {0, 2, -1}}),
       testing::horizontal_quad(4, 6, -1, 1, 1)});
  for (const Settings& settings : {kPaper, Settings{}, Settings{{"contour_planes", "1"}}}) {
    const auto above = face_areas(run_method(scene, 0, settings).fragments);
    EXPECT_EQ(above.at(1).lit, 0);
    EXPECT_NEAR(above.at(0).shadowed, 64.0 / 9.0, 1e-10);  // the square scaled by 4 / 3
    const auto on_ground = face_areas(run_method(scene, 1, settings).fragments);
    EXPECT_EQ(on_ground.at(0).lit, 0);
    EXPECT_NEAR(on_ground.at(0).shadowed, 400, 1e-10);
  }
  EXPECT_NEAR(face_areas(run_method(scene, 1, kPaper).fragments).at(2).shadowed, 4, 1e-12);
  EXPECT_NEAR(face_areas(run_method(scene, 1).fragments).at(2).lit, 4, 1e-12);
}

TEST(SvbspPaper, AnEmptySceneHasNoFragmentsAndNoNodes) {
  const Scene scene = testing::make_scene(kCamera, {testing::point_light({0, 4, 0})}, {});
  for (const Settings& settings : {kPaper, Settings{}, Settings{{"contour_planes", "1"}}}) {
    const MethodRun run = run_method(scene, 0, settings);
    EXPECT_TRUE(run.fragments.empty());
    EXPECT_EQ(run.svbsp_nodes, 0);
  }
}

// Table 1's Tetra256 and Tetra1024 (built-in tetra:3 and tetra:4, 258 and 1026 input
// polygons, 130 and 514 facing the light), lit as Haines's SPD lights them
// (docs/papers/chin-feiner-1989.md).
const Light kSpdLight = testing::point_light({-23.124358, 10.6, 9.743159});

TEST(SvbspPaper, TableOneFragmentsOfTheTetrahedraAreThePapersWithin30Percent) {
  const struct {
    const char* scene;
    double fragments;
  } table[] = {{"tetra:3", 723}, {"tetra:4", 3345}};
  for (const auto& [name, fragments] : table) {
    Scene scene = load_scene(name, {});
    scene.lights = {kSpdLight};
    const MethodRun paper = run_method(scene, 0, kPaper);
    EXPECT_NEAR(double(paper.fragments.size()), fragments, 0.3 * fragments) << name;
    // Fig. 4: each lit fragment, a triangle or more, adds a plane per edge.
    EXPECT_GE(paper.svbsp_nodes, 3.0 * double(lit_count(paper.fragments))) << name;
    EXPECT_LT(run_method(scene, 0).svbsp_nodes, paper.svbsp_nodes) << name;
  }
}

// Each refinement alone on top of the paper's algorithm: the same areas, and what it saves.
TEST(SvbspPaper, EachRefinementKeepsEveryAreaAndSavesWhatItShould) {
  for (const char* name : {"tetra:3", "cubes:64", "three-lights"}) {
    const Scene scene = load_scene(name, {});
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const MethodRun paper = run_method(scene, l, kPaper);
      const auto want = face_areas(paper.fragments);
      const auto run = [&](const char* refinement) {
        const MethodRun r = run_method(scene, l, paper_with(refinement));
        const auto got = face_areas(r.fragments);
        EXPECT_EQ(got.size(), want.size()) << name << " " << refinement;
        for (const auto& [face, a] : want) {
          const double tolerance = 1e-9 * (1 + a.lit + a.shadowed);
          EXPECT_NEAR(got.at(face).lit, a.lit, tolerance) << name << " " << refinement << face;
        }
        return r;
      };
      const std::string at = std::string(name) + " L" + std::to_string(l);
      EXPECT_LT(run("skip_edges_in_tree").svbsp_nodes, paper.svbsp_nodes) << at;
      EXPECT_LT(run("contour_planes").svbsp_nodes, paper.svbsp_nodes) << at;
      EXPECT_LE(run("merge_siblings").fragments.size(), paper.fragments.size()) << at;
      EXPECT_LE(run("whole_pieces").fragments.size(), paper.fragments.size()) << at;
      // One-sided, the far side of a solid is turned from the light: shadowed already.
      EXPECT_EQ(run("far_side").fragments.size(), paper.fragments.size()) << at;
    }
  }
}

TEST(SvbspSettings, BadValuesAreInputErrorsNamingTheSetting) {
  for (const char* key : {"paper", "contour_planes", "far_side", "skip_edges_in_tree",
                          "merge_siblings", "whole_pieces", "shadowed_only"}) {
    for (const auto& [value, message] :
         {std::pair{"2", "expected 0 or 1"}, std::pair{"-1", "expected 0 or 1"},
          std::pair{"0.5", "expected 0 or 1"}, std::pair{"yes", "expected a number"}}) {
      try {
        SvbspMethod method({"svbsp", {{key, value}}});
        ADD_FAILURE() << key << "=" << value << " accepted";
      } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).find(std::string("option 'svbsp.") + key + "'"), 0u)
            << e.what();
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_THROW(SvbspMethod({"svbsp", {{"contour_edges", "1"}}}), InputError);
}

}  // namespace
}  // namespace shadowkit::svbsp
