#pragma once
// OpenSubdiv set up for the tests apart from SubdivisionSurface: the references its
// evaluation is checked against.
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>
#include <vector>

#include "shadowkit/scene/mesh.h"

namespace shadowkit::test {

namespace Far = OpenSubdiv::Far;

/// \brief A vertex primvar in double for OpenSubdiv's refiners and stencils.
struct OsdPoint {
  Vec3 p;
  void Clear() { p = {}; }
  void AddWithWeight(const OsdPoint& src, double w) { p += src.p * w; }
};

/// The refiner of \p mesh with the scene format's Catmull-Clark rules (boundary edges and
/// corners sharp, no creases), not yet refined.
inline std::unique_ptr<Far::TopologyRefiner> reference_refiner(const PolygonSoup& mesh) {
  OpenSubdiv::Sdc::Options rules;
  rules.SetVtxBoundaryInterpolation(OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  std::vector<int> sizes, indices(mesh.indices.begin(), mesh.indices.end());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    sizes.push_back(int(mesh.face_start[f + 1] - mesh.face_start[f]));
  }
  Far::TopologyDescriptor d;
  d.numVertices = int(mesh.positions.size());
  d.numFaces = int(sizes.size());
  d.numVertsPerFace = sizes.data();
  d.vertIndicesPerFace = indices.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return std::unique_ptr<Far::TopologyRefiner>(
      Factory::Create(d, Factory::Options(OpenSubdiv::Sdc::SCHEME_CATMARK, rules)));
}

}  // namespace shadowkit::test
