#include "unowned_centres.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "shadowkit/raster/visible_surface.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

// A square seen from above, split across x by the plane x = cut into a lit fragment (x <
// cut) and a shadowed one.
struct SplitSquare {
  Scene scene = testing::make_scene(testing::camera({0.3, 5, 0.2}, {0, 0, 0}, 64, 48),
                                    {testing::directional_light({0, -1, 0})},
                                    {testing::horizontal_quad(-1, 1, -1, 1, 0)});
  VisibleSurfaceBuffer surfaces = render_visible_surfaces(scene, {});
  double cut = 0;
  std::vector<Fragment> fragments;
  std::vector<std::uint32_t> candidates{0, 1};

  SplitSquare() {
    const Mesh& mesh = scene.objects[0].mesh;
    std::vector<Vec3> corners;
    for (std::uint32_t k = 0; k < mesh.face_size(0); ++k) {
      corners.push_back(mesh.vertices[mesh.face_vertex(0, k)]);
    }
    cut = 0.5 * (mesh.bounds().lo.x + mesh.bounds().hi.x) + 0.1;
    ConvexPolygon left, right;
    split_polygon(make_polygon(corners, 0), Plane{{1, 0, 0}, -cut}, 1e-12, std::nullopt, left,
                  right);
    fragments = {{left, true}, {right, false}};
  }
  // The mask with every covered pixel unowned.
  ShadowMask unowned() const {
    ShadowMask mask(surfaces.width, surfaces.height, kMaskBackground);
    for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
      if (surfaces.covered(i)) mask.pixels[i] = kUnowned;
    }
    return mask;
  }
  std::uint8_t expected(std::size_t i) const {
    return surfaces.point(i).x < cut ? kMaskLit : kMaskShadow;
  }
  // A covered centre whose neighbours are all covered and, as it is, \p side.
  std::optional<std::size_t> deep_inside(std::uint8_t side) const {
    for (int y = 1; y + 1 < surfaces.height; ++y) {
      for (int x = 1; x + 1 < surfaces.width; ++x) {
        bool inside = true;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const std::size_t j = surfaces.index(x + dx, y + dy);
            inside = inside && surfaces.covered(j) && expected(j) == side;
          }
        }
        if (inside) return surfaces.index(x, y);
      }
    }
    return std::nullopt;
  }
};

TEST(UnownedCentres, WithNoOwnedNeighbourTheFragmentHoldingThePointDecides) {
  const SplitSquare square;
  ShadowMask mask = square.unowned();
  resolve_unowned(square.scene, square.fragments, square.candidates, square.surfaces, mask);
  std::size_t lit = 0, shadowed = 0;
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
    if (!square.surfaces.covered(i)) {
      EXPECT_EQ(mask.pixels[i], kMaskBackground);
      continue;
    }
    EXPECT_EQ(mask.pixels[i], square.expected(i)) << "pixel " << i;
    (mask.pixels[i] == kMaskLit ? lit : shadowed) += 1;
  }
  EXPECT_GT(lit, 100u);
  EXPECT_GT(shadowed, 100u);
}

TEST(UnownedCentres, OwnedNeighboursThatAgreeDecide) {
  const SplitSquare square;
  ShadowMask mask = square.unowned();
  // Every centre owned, and wrongly, but two: their neighbours decide them, not the point.
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
    if (square.surfaces.covered(i)) {
      mask.pixels[i] = square.expected(i) == kMaskLit ? kMaskShadow : kMaskLit;
    }
  }
  // One centre on each side of the cut, all of whose neighbours are on its side.
  std::vector<std::size_t> chosen;
  for (const std::uint8_t side : {kMaskLit, kMaskShadow}) {
    if (const auto i = square.deep_inside(side)) chosen.push_back(*i);
  }
  ASSERT_EQ(chosen.size(), 2u);
  for (const std::size_t i : chosen) mask.pixels[i] = kUnowned;
  resolve_unowned(square.scene, square.fragments, square.candidates, square.surfaces, mask);
  for (const std::size_t i : chosen) {
    EXPECT_NE(mask.pixels[i], square.expected(i)) << "pixel " << i;
    EXPECT_EQ(mask.pixels[i], mask.pixels[i + 1]) << "pixel " << i;
  }
}

TEST(UnownedCentres, AFaceWithoutFragmentsIsShadowed) {
  const SplitSquare square;
  ShadowMask mask = square.unowned();
  resolve_unowned(square.scene, {}, {}, square.surfaces, mask);
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
    if (square.surfaces.covered(i)) {
      EXPECT_EQ(mask.pixels[i], kMaskShadow);
    }
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
