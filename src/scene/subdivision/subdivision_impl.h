#pragma once
// Internals shared by the files of SubdivisionSurface; OpenSubdiv stays out of the public header.
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "shadowkit/scene/mesh.h"
#include "shadowkit/scene/subdivision.h"

namespace shadowkit {
namespace subdivision {

namespace Far = OpenSubdiv::Far;

/// \brief A vertex primvar for OpenSubdiv's refiners and stencil tables, in double.
struct Point {
  Vec3 p;
  void Clear() { p = {}; }
  void AddWithWeight(const Point& src, double weight) { p += src.p * weight; }
};

/// \brief Quads with at most one extraordinary vertex each: the patches of Lai & Cheng §3.
struct QuadMesh {
  std::vector<Vec3> positions;
  std::vector<std::array<std::uint32_t, 4>> quads;
};

/// The scene format's Catmull-Clark scheme (scene-format.md): boundary edges and corners
/// sharp, no creases. Null when OpenSubdiv rejects the topology.
std::unique_ptr<Far::TopologyRefiner> make_refiner(int vertex_count,
                                                   std::span<const int> face_sizes,
                                                   std::span<const int> face_vertices);

/// The quad mesh whose faces are the patches of the welded control mesh \p control: the
/// control mesh itself, or the control mesh subdivided once (§3). InputError naming \p name
/// when the control mesh is degenerate or not manifold.
QuadMesh quad_base(const PolygonSoup& control, const std::string& name);

}  // namespace subdivision

struct SubdivisionSurface::Impl {
  std::size_t control_faces = 0;
  subdivision::QuadMesh base;
  std::unique_ptr<const subdivision::Far::PatchTable> patch_table;
  std::unique_ptr<const subdivision::Far::PatchMap> patch_map;
  /// The patch table's points: every vertex of the adaptive refinement, then the end caps'.
  std::vector<subdivision::Point> patch_points;
};

}  // namespace shadowkit
