#include "shadowkit/scene/subdivision.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opensubdiv/far/primvarRefiner.h>

#include <map>
#include <unordered_map>

#include "control_meshes.h"
#include "osd_reference.h"
#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

namespace Far = OpenSubdiv::Far;
using ::testing::HasSubstr;

using Point = test::OsdPoint;

/// A vertex of a uniform refinement with its place on a patch.
struct PatchSample {
  std::uint32_t patch;
  double u, v;
  Vec3 limit;   ///< OpenSubdiv's limit position (limit masks, exact at every vertex)
  Vec3 normal;  ///< from OpenSubdiv's limit tangent masks
};

// The reference, independent of the patch table: OpenSubdiv's uniform refinement of the
// control mesh, the limit masks at the refined vertices, and their (patch, u, v) found by
// following each patch's faces down the levels (face children at corner averages, edge
// children at edge midpoints).
class UniformReference {
 public:
  UniformReference(const PolygonSoup& control, const SubdivisionSurface& surface, int levels) {
    refiner_ = test::reference_refiner(control);
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;  // the limit masks need the last level's rings
    refiner_->RefineUniform(uniform);
    // The surface's patches are the control faces or, after the one-step rule, level 1's.
    base_level_ = surface.patch_count() == surface.control_face_count() ? 0 : 1;
    refine_positions(control.positions);
    place_base_faces(surface);
    for (int level = base_level_; level < levels; ++level) descend(level);
    collect();
  }

  const std::vector<PatchSample>& samples() const { return samples_; }

 private:
  struct FacePlace {
    std::uint32_t patch;
    std::vector<std::array<double, 2>> uv;  // per face vertex
  };

  void refine_positions(const std::vector<Vec3>& control) {
    std::vector<Point> all(std::size_t(refiner_->GetNumVerticesTotal()));
    for (std::size_t v = 0; v < control.size(); ++v) all[v].p = control[v];
    const Far::PrimvarRefinerReal<double> primvars(*refiner_);
    Point* src = all.data();
    for (int level = 1; level < refiner_->GetNumLevels(); ++level) {
      Point* dst = src + refiner_->GetLevel(level - 1).GetNumVertices();
      primvars.Interpolate(level, src, dst);
      src = dst;
    }
    const int last = refiner_->GetMaxLevel();
    limit_.resize(std::size_t(refiner_->GetLevel(last).GetNumVertices()));
    tan_u_ = tan_v_ = limit_;
    primvars.Limit(src, limit_, tan_u_, tan_v_);
  }

  void place_base_faces(const SubdivisionSurface& surface) {
    std::map<std::array<std::uint32_t, 4>, std::uint32_t> patch_of;
    for (std::uint32_t p = 0; p < surface.patch_count(); ++p) {
      std::array<std::uint32_t, 4> key = surface.patch_corners(p);
      std::sort(key.begin(), key.end());
      patch_of[key] = p;
    }
    const Far::TopologyLevel& level = refiner_->GetLevel(base_level_);
    if (std::size_t(level.GetNumFaces()) != surface.patch_count()) {
      throw std::logic_error("the reference's base level is not the surface's patches");
    }
    constexpr std::array<std::array<double, 2>, 4> kCornerUv{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    for (int f = 0; f < level.GetNumFaces(); ++f) {
      const Far::ConstIndexArray v = level.GetFaceVertices(f);
      std::array<std::uint32_t, 4> key{std::uint32_t(v[0]), std::uint32_t(v[1]),
                                       std::uint32_t(v[2]), std::uint32_t(v[3])};
      std::sort(key.begin(), key.end());
      if (!patch_of.count(key))
        throw std::logic_error("face " + std::to_string(f) + " is no patch");
      FacePlace place{patch_of[key], {}};
      const std::array<std::uint32_t, 4> corners = surface.patch_corners(place.patch);
      for (int k = 0; k < 4; ++k) {
        const auto at = std::find(corners.begin(), corners.end(), std::uint32_t(v[k]));
        place.uv.push_back(kCornerUv[std::size_t(at - corners.begin())]);
      }
      places_.push_back(place);
    }
  }

  void descend(int level_index) {
    const Far::TopologyLevel& level = refiner_->GetLevel(level_index);
    const Far::TopologyLevel& child = refiner_->GetLevel(level_index + 1);
    std::vector<FacePlace> next(std::size_t(child.GetNumFaces()));
    for (int f = 0; f < level.GetNumFaces(); ++f) {
      const FacePlace& place = places_[std::size_t(f)];
      const Far::ConstIndexArray v = level.GetFaceVertices(f), e = level.GetFaceEdges(f);
      std::unordered_map<int, std::array<double, 2>> uv;
      std::array<double, 2> centre{0, 0};
      for (int k = 0; k < v.size(); ++k) {
        const auto a = place.uv[std::size_t(k)], b = place.uv[std::size_t((k + 1) % v.size())];
        uv[level.GetVertexChildVertex(v[k])] = a;
        uv[level.GetEdgeChildVertex(e[k])] = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
        centre = {centre[0] + a[0] / v.size(), centre[1] + a[1] / v.size()};
      }
      uv[level.GetFaceChildVertex(f)] = centre;
      for (int c : level.GetFaceChildFaces(f)) {
        FacePlace& child_place = next[std::size_t(c)];
        child_place.patch = place.patch;
        for (int w : child.GetFaceVertices(c)) child_place.uv.push_back(uv.at(w));
      }
    }
    places_ = std::move(next);
  }

  void collect() {
    const Far::TopologyLevel& level = refiner_->GetLevel(refiner_->GetMaxLevel());
    for (int f = 0; f < level.GetNumFaces(); ++f) {
      const Far::ConstIndexArray v = level.GetFaceVertices(f);
      for (int k = 0; k < v.size(); ++k) {
        const auto w = std::size_t(v[k]);
        const auto uv = places_[std::size_t(f)].uv[std::size_t(k)];
        samples_.push_back({places_[std::size_t(f)].patch, uv[0], uv[1], limit_[w].p,
                            normalize(cross(tan_u_[w].p, tan_v_[w].p))});
      }
    }
  }

  std::unique_ptr<Far::TopologyRefiner> refiner_;
  int base_level_ = 0;
  std::vector<Point> limit_, tan_u_, tan_v_;
  std::vector<FacePlace> places_;
  std::vector<PatchSample> samples_;
};

double size_of(const PolygonSoup& soup) {
  Bounds3 box;
  for (const Vec3& p : soup.positions) box.add(p);
  return box.diagonal();
}

// evaluate() against the limit masks at every vertex of a 4-level uniform refinement.
void expect_matches_uniform_refinement(const PolygonSoup& control) {
  const auto surface = SubdivisionSurface::build(control, "test");
  const UniformReference reference(control, *surface, 4);
  ASSERT_FALSE(reference.samples().empty());
  const double tolerance = 1e-9 * size_of(control);
  for (const PatchSample& s : reference.samples()) {
    const SurfacePoint p = surface->evaluate(s.patch, s.u, s.v);
    ASSERT_LE(length(p.position - s.limit), tolerance)
        << "patch " << s.patch << " at (" << s.u << ", " << s.v << ")";
    ASSERT_GT(dot(p.normal(), s.normal), 1 - 1e-9)
        << "patch " << s.patch << " at (" << s.u << ", " << s.v << ")";
  }
}

TEST(SubdivisionSurface, ValenceThreeCubeIsSubdividedOnceAndMatchesTheLimit) {
  const auto surface = SubdivisionSurface::build(test::cube_control(), "cube");
  EXPECT_EQ(surface->patch_count(), 24u);  // four valence-3 corners per face: one step first
  expect_matches_uniform_refinement(test::cube_control());
}

TEST(SubdivisionSurface, ValenceThreeAndFiveFansKeepTheirFacesAndMatchTheLimit) {
  for (int valence : {3, 5}) {
    SCOPED_TRACE(valence);
    EXPECT_EQ(SubdivisionSurface::build(test::fan_control(valence), "fan")->patch_count(),
              std::size_t(valence));
    expect_matches_uniform_refinement(test::fan_control(valence));
  }
}

TEST(SubdivisionSurface, TrianglesAreSubdividedOnceAndMatchTheLimit) {
  // 1 quad + 4 triangles become 4 + 4 x 3 quads.
  EXPECT_EQ(SubdivisionSurface::build(test::pyramid_control(), "pyramid")->patch_count(), 16u);
  expect_matches_uniform_refinement(test::pyramid_control());
}

TEST(SubdivisionSurface, RegularTorusMatchesTheLimit) {
  EXPECT_EQ(SubdivisionSurface::build(test::torus_control(), "torus")->patch_count(), 24u);
  expect_matches_uniform_refinement(test::torus_control());
}

TEST(SubdivisionSurface, DerivativesMatchFiniteDifferences) {
  for (const PolygonSoup& control : {test::cube_control(), test::fan_control(5)}) {
    const auto surface = SubdivisionSurface::build(control, "test");
    constexpr double h = 1e-6;
    for (std::uint32_t patch = 0; patch < surface->patch_count(); ++patch) {
      for (const auto& [u, v] : {std::pair{0.3, 0.6}, {0.5, 0.5}, {0.02, 0.9}, {0.97, 0.01}}) {
        const SurfacePoint p = surface->evaluate(patch, u, v);
        const Vec3 du = (surface->evaluate(patch, u + h, v).position -
                         surface->evaluate(patch, u - h, v).position) /
                        (2 * h);
        const Vec3 dv = (surface->evaluate(patch, u, v + h).position -
                         surface->evaluate(patch, u, v - h).position) /
                        (2 * h);
        EXPECT_LE(length(p.du - du), 1e-6 * length(p.du)) << patch << " " << u << " " << v;
        EXPECT_LE(length(p.dv - dv), 1e-6 * length(p.dv)) << patch << " " << u << " " << v;
      }
    }
  }
}

TEST(SubdivisionSurface, NeighbouringPatchesAgreeAlongTheirSharedEdge) {
  for (const PolygonSoup& control :
       {test::cube_control(), test::fan_control(5), test::pyramid_control()}) {
    const auto surface = SubdivisionSurface::build(control, "test");
    // Point at parameter t along the patch edge from corner k to corner k + 1.
    auto along = [&](std::uint32_t patch, int k, double t) {
      constexpr std::array<std::array<double, 2>, 4> c{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
      const auto a = c[std::size_t(k)], b = c[std::size_t((k + 1) % 4)];
      return surface->evaluate(patch, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])).position;
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, int>> first_side;
    int shared = 0;
    for (std::uint32_t patch = 0; patch < surface->patch_count(); ++patch) {
      const auto corners = surface->patch_corners(patch);
      for (int k = 0; k < 4; ++k) {
        const std::uint32_t a = corners[std::size_t(k)], b = corners[std::size_t((k + 1) % 4)];
        const auto it = first_side.find({b, a});  // consistently oriented: walked b to a there
        if (it == first_side.end()) {
          first_side[{a, b}] = {patch, k};
          continue;
        }
        ++shared;
        for (double t : {0.0, 0.125, 0.3, 0.5, 0.77, 1.0}) {
          EXPECT_LE(length(along(patch, k, t) - along(it->second.first, it->second.second, 1 - t)),
                    1e-12 * size_of(control));
        }
      }
    }
    EXPECT_GT(shared, 0);
  }
}

TEST(SubdivisionSurface, PlanarGridGivesAPlanarSurfaceWithSharpCorners) {
  const PolygonSoup control = test::planar_grid_control(4);
  const auto surface = SubdivisionSurface::build(control, "grid");
  ASSERT_EQ(surface->patch_count(), 16u);
  for (std::uint32_t patch = 0; patch < surface->patch_count(); ++patch) {
    for (double u : {0.0, 0.25, 0.5, 1.0}) {
      for (double v : {0.0, 0.4, 1.0}) {
        const SurfacePoint p = surface->evaluate(patch, u, v);
        EXPECT_EQ(p.position.z, 0.0);
        EXPECT_NEAR(std::abs(p.normal().z), 1.0, 1e-12);
      }
    }
  }
  // Boundary corners are sharp: the surface passes through the control corners.
  EXPECT_LE(length(surface->evaluate(0, 0, 0).position - Vec3{0, 0, 0}), 1e-12);
  EXPECT_LE(length(surface->evaluate(15, 1, 1).position - Vec3{4, 4, 0}), 1e-12);
  // Boundary edges are sharp: the boundary curve stays on the control boundary line y = 0.
  EXPECT_NEAR(surface->evaluate(1, 0.37, 0).position.y, 0.0, 1e-12);
}

TEST(SubdivisionSurface, LoneQuadIsItsBilinearPatchAndLoneTriangleHasThreePatches) {
  PolygonSoup quad;
  quad.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  quad.add_face({0, 1, 2, 3});
  const auto surface = SubdivisionSurface::build(quad, "quad");
  ASSERT_EQ(surface->patch_count(), 1u);
  for (const auto& [u, v] : {std::pair{0.0, 0.0}, {0.25, 0.5}, {1.0, 0.75}}) {
    EXPECT_LE(length(surface->evaluate(0, u, v).position - Vec3{2 * u, v, 0}), 1e-12);
  }
  PolygonSoup triangle;
  triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  triangle.add_face({0, 1, 2});
  EXPECT_EQ(SubdivisionSurface::build(triangle, "triangle")->patch_count(), 3u);
}

TEST(SubdivisionSurface, TinyAndHugeCoordinatesScaleTheSurface) {
  const auto unit = SubdivisionSurface::build(test::cube_control(), "cube");
  for (double scale : {1e-9, 1e12}) {
    const auto scaled = SubdivisionSurface::build(test::scaled(test::cube_control(), scale), "c");
    ASSERT_EQ(scaled->patch_count(), unit->patch_count());
    for (std::uint32_t patch = 0; patch < unit->patch_count(); ++patch) {
      const SurfacePoint a = unit->evaluate(patch, 0.3, 0.8), b = scaled->evaluate(patch, 0.3, 0.8);
      EXPECT_LE(length(b.position - a.position * scale), 1e-12 * scale);
      EXPECT_LE(length(b.du - a.du * scale), 1e-11 * scale);
    }
  }
}

TEST(SubdivisionSurface, DuplicatePositionsAreWeldedIntoOneControlMesh) {
  // Each face with its own four positions, as an STL-like soup gives them.
  const PolygonSoup indexed = test::cube_control();
  PolygonSoup soup;
  for (std::uint32_t k = 0; k < indexed.indices.size(); ++k) {
    soup.positions.push_back(indexed.positions[indexed.indices[k]]);
    if (k % 4 == 3) soup.add_face({k - 3, k - 2, k - 1, k});
  }
  const auto welded = SubdivisionSurface::build(soup, "cube");
  const auto reference = SubdivisionSurface::build(indexed, "cube");
  ASSERT_EQ(welded->patch_count(), reference->patch_count());
  for (std::uint32_t patch = 0; patch < welded->patch_count(); ++patch) {
    EXPECT_LE(length(welded->evaluate(patch, 0.5, 0.5).position -
                     reference->evaluate(patch, 0.5, 0.5).position),
              1e-12);
  }
}

std::string error_of(const PolygonSoup& control) {
  try {
    SubdivisionSurface::build(control, "scene.json: key 'objects[2]'");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SubdivisionSurface, BadControlMeshesAreInputErrors) {
  EXPECT_THAT(error_of(PolygonSoup{}), HasSubstr("objects[2]'"));
  EXPECT_THAT(error_of(PolygonSoup{}), HasSubstr("no faces"));

  PolygonSoup repeated = test::fan_control(4);
  repeated.add_face({0, 1, 0, 2});
  EXPECT_THAT(error_of(repeated), HasSubstr("control face 5 is degenerate"));

  PolygonSoup collapsed;  // three positions welded into one
  collapsed.positions = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  collapsed.add_face({0, 1, 2});
  EXPECT_THAT(error_of(collapsed), HasSubstr("degenerate"));

  PolygonSoup fin = test::fan_control(4);  // a third face on the edge 0-1
  fin.positions.push_back({0.5, 0, 2});
  fin.add_face({1, 0, 9});
  EXPECT_THAT(error_of(fin), HasSubstr("not manifold at the edge"));

  PolygonSoup flipped = test::fan_control(4);  // one face walks its edges the wrong way
  std::reverse(flipped.indices.begin(), flipped.indices.begin() + 4);
  EXPECT_THAT(error_of(flipped), HasSubstr("not manifold"));

  PolygonSoup bowtie;  // two triangles touching at one vertex
  bowtie.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  bowtie.add_face({0, 1, 2});
  bowtie.add_face({0, 3, 4});
  EXPECT_THAT(error_of(bowtie), HasSubstr("not manifold at the vertex (0, 0, 0)"));
}

}  // namespace
}  // namespace shadowkit
