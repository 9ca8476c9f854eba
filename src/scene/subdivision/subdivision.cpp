// The limit surface of the patches: OpenSubdiv's adaptive refinement and patch table.
#include "shadowkit/scene/subdivision.h"

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>

#include "shadowkit/core/error.h"
#include "subdivision_impl.h"

namespace shadowkit {
namespace {

namespace Far = OpenSubdiv::Far;
using subdivision::Point;

// Regular regions become exact bicubic B-spline patches; the region left around an
// extraordinary vertex after the deepest isolation OpenSubdiv allows (10 levels, 2^-10 of a
// patch) is a Gregory end cap, which interpolates the exact limit position and tangent plane
// at its corners: the most exact evaluation Far offers short of Stam's eigenanalysis.
constexpr unsigned kIsolationLevel = 10;

Far::PatchTableFactory::Options patch_options() {
  Far::PatchTableFactory::Options options(kIsolationLevel);
  options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
  options.SetPatchPrecision<double>();
  options.useInfSharpPatch = true;  // sharp boundary corners are regular patches, not isolated
  return options;
}

// Positions of every vertex of the adaptive refinement, level by level, then of the end
// caps' local points.
std::vector<Point> patch_points(const Far::TopologyRefiner& refiner, const Far::PatchTable& table,
                                const std::vector<Vec3>& base) {
  const int refined = refiner.GetNumVerticesTotal();
  std::vector<Point> points(std::size_t(refined + table.GetNumLocalPoints()));
  for (std::size_t v = 0; v < base.size(); ++v) points[v].p = base[v];
  const Far::PrimvarRefinerReal<double> primvars(refiner);
  Point* src = points.data();
  for (int level = 1; level < refiner.GetNumLevels(); ++level) {
    Point* dst = src + refiner.GetLevel(level - 1).GetNumVertices();
    primvars.Interpolate(level, src, dst);
    src = dst;
  }
  // PatchTable::ComputeLocalPointValues assumes float stencils; ours are double.
  if (const auto* stencils = table.GetLocalPointStencilTable<double>()) {
    stencils->UpdateValues(points.data(), points.data() + refined);
  }
  return points;
}

}  // namespace

SubdivisionSurface::SubdivisionSurface(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SubdivisionSurface::~SubdivisionSurface() = default;

std::shared_ptr<const SubdivisionSurface> SubdivisionSurface::build(const PolygonSoup& control,
                                                                    const std::string& name) {
  auto impl = std::make_unique<Impl>();
  const PolygonSoup welded = welded_soup(control);
  impl->control_faces = welded.face_count();
  impl->base = subdivision::quad_base(welded, name);
  std::vector<int> sizes(impl->base.quads.size(), 4), vertices;
  for (const auto& quad : impl->base.quads)
    vertices.insert(vertices.end(), quad.begin(), quad.end());
  const std::unique_ptr<Far::TopologyRefiner> refiner =
      subdivision::make_refiner(int(impl->base.positions.size()), sizes, vertices);
  SHADOWKIT_CHECK(refiner != nullptr);  // a manifold quad mesh, already accepted once

  const Far::PatchTableFactory::Options options = patch_options();
  refiner->RefineAdaptive(options.GetRefineAdaptiveOptions());
  impl->patch_table.reset(Far::PatchTableFactory::Create(*refiner, options));
  impl->patch_points = patch_points(*refiner, *impl->patch_table, impl->base.positions);
  // All quads: each face is one ptex face, with the same index.
  impl->patch_map = std::make_unique<Far::PatchMap>(*impl->patch_table);
  return std::shared_ptr<const SubdivisionSurface>(new SubdivisionSurface(std::move(impl)));
}

std::size_t SubdivisionSurface::control_face_count() const {
  return impl_->control_faces;
}

std::size_t SubdivisionSurface::patch_count() const {
  return impl_->base.quads.size();
}

std::array<std::uint32_t, 4> SubdivisionSurface::patch_corners(std::uint32_t patch) const {
  return impl_->base.quads.at(patch);
}

SurfacePoint SubdivisionSurface::evaluate(std::uint32_t patch, double u, double v) const {
  SHADOWKIT_CHECK(patch < patch_count() && u >= 0 && u <= 1 && v >= 0 && v <= 1);
  const Far::PatchTable::PatchHandle* handle = impl_->patch_map->FindPatch(int(patch), u, v);
  SHADOWKIT_CHECK(handle != nullptr);
  // 20: the most points of any Catmark patch (a Gregory basis end cap).
  std::array<double, 20> w, w_du, w_dv;
  impl_->patch_table->EvaluateBasis(*handle, u, v, w.data(), w_du.data(), w_dv.data());
  const Far::ConstIndexArray points = impl_->patch_table->GetPatchVertices(*handle);
  SHADOWKIT_CHECK(points.size() <= int(w.size()));
  SurfacePoint s;
  for (int k = 0; k < points.size(); ++k) {
    const Vec3 p = impl_->patch_points[std::size_t(points[k])].p;
    s.position += p * w[k];
    s.du += p * w_du[k];
    s.dv += p * w_dv[k];
  }
  return s;
}

}  // namespace shadowkit
