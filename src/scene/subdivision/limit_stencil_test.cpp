// The limit surface next to extraordinary vertices against OpenSubdiv's own evaluation.
#include <gtest/gtest.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTableFactory.h>

#include <cmath>
#include <random>

#include "control_meshes.h"
#include "osd_reference.h"
#include "shadowkit/scene/subdivision.h"

namespace shadowkit {
namespace {

namespace Far = OpenSubdiv::Far;
using test::OsdPoint;

/// \brief The quad mesh whose faces are the patches: the control mesh, or its first uniform
/// level when SubdivisionSurface applied Lai & Cheng's one step (§3).
struct BaseMesh {
  PolygonSoup quads;
  std::vector<OsdPoint> points;
};

BaseMesh base_mesh(const PolygonSoup& control, const SubdivisionSurface& surface) {
  BaseMesh base;
  for (const Vec3& p : control.positions) base.points.push_back({p});
  if (surface.patch_count() == surface.control_face_count()) {
    base.quads = control;
    return base;
  }
  const auto refiner = test::reference_refiner(control);
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(1));
  const Far::TopologyLevel& level = refiner->GetLevel(1);
  std::vector<OsdPoint> fine(std::size_t(level.GetNumVertices()));
  const OsdPoint* src = base.points.data();
  OsdPoint* dst = fine.data();
  Far::PrimvarRefinerReal<double>(*refiner).Interpolate(1, src, dst);
  base.points = fine;
  for (const OsdPoint& p : fine) base.quads.positions.push_back(p.p);
  for (int f = 0; f < level.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = level.GetFaceVertices(f);
    base.quads.add_face(
        {std::uint32_t(v[0]), std::uint32_t(v[1]), std::uint32_t(v[2]), std::uint32_t(v[3])});
  }
  return base;
}

/// \brief Parameters on one patch, as OpenSubdiv's limit stencils take them.
struct Locations {
  int patch;
  std::vector<double> u, v;
};

// Per patch with a corner of irregular valence, \p count random (u, v) at 2^-1 to 2^-20 of
// that corner, the last two of each corner on the patch's sides through it.
std::vector<Locations> near_extraordinary_corners(const Far::TopologyRefiner& refiner,
                                                  const SubdivisionSurface& surface, int count) {
  const Far::TopologyLevel& level = refiner.GetLevel(0);
  std::mt19937 random(2007);
  std::uniform_real_distribution<double> exponent(1, 20), share(0, 1);
  constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<Locations> out;
  for (int f = 0; f < level.GetNumFaces(); ++f) {
    const Far::ConstIndexArray corners = level.GetFaceVertices(f);
    Locations at{f, {}, {}};
    for (int k = 0; k < 4; ++k) {
      if (level.IsVertexValenceRegular(corners[k])) continue;
      for (int i = 0; i < count; ++i) {
        const double r = std::exp2(-exponent(random));
        const double a = i == count - 1 ? 0 : share(random), b = i == count - 2 ? 0 : share(random);
        at.u.push_back(kCorner[k][0] == 0 ? r * a : 1 - r * a);
        at.v.push_back(kCorner[k][1] == 0 ? r * b : 1 - r * b);
      }
    }
    // The patch is the base face of the same index, corner for corner (quad_base()).
    const std::array<std::uint32_t, 4> patch = surface.patch_corners(std::uint32_t(f));
    for (int k = 0; k < 4; ++k) EXPECT_EQ(patch[std::size_t(k)], std::uint32_t(corners[k]));
    if (!at.u.empty()) out.push_back(std::move(at));
  }
  return out;
}

// evaluate() assembles its own patch points (the adaptive refinement's vertices, then the
// Gregory end caps' local points in double) and looks patches up in its own patch map. The
// reference is OpenSubdiv's LimitStencilTable over a refiner made here, isolated to the same
// level 10 with the same sharp-corner rule; within 2^-10 of an extraordinary vertex both
// evaluate the Gregory end caps, beyond it the B-spline patches of the isolation.
void expect_matches_limit_stencils(const PolygonSoup& control) {
  const auto surface = SubdivisionSurface::build(control, "test");
  const BaseMesh base = base_mesh(control, *surface);
  ASSERT_EQ(base.quads.face_count(), surface->patch_count());
  const auto refiner = test::reference_refiner(base.quads);
  Far::TopologyRefiner::AdaptiveOptions adaptive(10);
  adaptive.useInfSharpPatch = true;
  refiner->RefineAdaptive(adaptive);
  const std::vector<Locations> locations = near_extraordinary_corners(*refiner, *surface, 24);
  ASSERT_FALSE(locations.empty());
  using Factory = Far::LimitStencilTableFactoryReal<double>;
  Factory::LocationArrayVec arrays;
  for (const Locations& at : locations) {
    Factory::LocationArray array;
    array.ptexIdx = at.patch;  // all quads: a face is one ptex face of the same index
    array.numLocations = int(at.u.size());
    array.s = at.u.data();
    array.t = at.v.data();
    arrays.push_back(array);
  }
  const std::unique_ptr<const Far::LimitStencilTableReal<double>> stencils(
      Factory::Create(*refiner, arrays));
  ASSERT_NE(stencils, nullptr);
  std::vector<OsdPoint> position(std::size_t(stencils->GetNumStencils())), du = position,
                                                                           dv = position;
  stencils->UpdateValues(base.points.data(), position.data());
  stencils->UpdateDerivs(base.points.data(), du.data(), dv.data());
  Bounds3 box;
  for (const Vec3& p : control.positions) box.add(p);
  const double size = box.diagonal();
  std::size_t s = 0, in_end_caps = 0;
  for (const Locations& at : locations) {
    for (std::size_t i = 0; i < at.u.size(); ++i, ++s) {
      const SurfacePoint p = surface->evaluate(std::uint32_t(at.patch), at.u[i], at.v[i]);
      in_end_caps +=
          std::min({at.u[i], 1 - at.u[i]}) < 0x1p-10 && std::min({at.v[i], 1 - at.v[i]}) < 0x1p-10;
      ASSERT_LE(length(p.position - position[s].p), 1e-12 * size)
          << "patch " << at.patch << " at (" << at.u[i] << ", " << at.v[i] << ")";
      ASSERT_LE(length(p.du - du[s].p), 1e-9 * std::max(length(du[s].p), size))
          << "patch " << at.patch << " at (" << at.u[i] << ", " << at.v[i] << ")";
      ASSERT_LE(length(p.dv - dv[s].p), 1e-9 * std::max(length(dv[s].p), size))
          << "patch " << at.patch << " at (" << at.u[i] << ", " << at.v[i] << ")";
    }
  }
  EXPECT_GT(in_end_caps, s / 4);  // a good share within the end caps' 2^-10
}

TEST(LimitStencils, CubeCornersOfValenceThreeAfterOneStep) {
  expect_matches_limit_stencils(test::cube_control());
}

TEST(LimitStencils, InteriorVerticesOfValenceThreeFiveAndSix) {
  for (int valence : {3, 5, 6}) {
    SCOPED_TRACE(valence);
    expect_matches_limit_stencils(test::fan_control(valence));
  }
}

TEST(LimitStencils, TriangleCentresAndApexAfterOneStep) {
  expect_matches_limit_stencils(test::pyramid_control());
}

}  // namespace
}  // namespace shadowkit
