#pragma once
/// \brief Catmull-Clark subdivision surfaces (scene-format.md, "subdivision"): the exact limit
/// surface, evaluated with OpenSubdiv's Far patch tables, and a crack-free tessellation of it
/// that every method other than `voxel` sees as an ordinary mesh.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "shadowkit/core/vec.h"
#include "shadowkit/scene/mesh.h"

namespace shadowkit {

/// \brief A point of a parametric surface with its first partial derivatives.
struct SurfacePoint {
  Vec3 position;
  Vec3 du, dv;
  /// Unit normal along du x dv.
  Vec3 normal() const { return normalize(cross(du, dv)); }
};

/// \brief The limit surface of a Catmull-Clark control mesh: no creases, boundary edges and
/// corners sharp (OpenSubdiv's VTX_BOUNDARY_EDGE_AND_CORNER), so an open mesh keeps its outline.
///
/// Lai & Cheng (§3): a control mesh with a non-quad face, or a face with more than one
/// extraordinary vertex, is subdivided once first (the whole mesh, so that all patches are
/// faces of one mesh). Every face of the resulting quad mesh is then one *patch* with
/// parameters (u, v) in [0, 1]^2 and at most one extraordinary vertex: OpenSubdiv's ptex
/// parameterisation of that face, u from corner 0 toward corner 1, v from corner 0 toward 3.
class SubdivisionSurface {
 public:
  /// Builds the surface of \p control (world space). InputError naming \p name when the
  /// control mesh cannot be subdivided.
  static std::shared_ptr<const SubdivisionSurface> build(const PolygonSoup& control,
                                                         const std::string& name);

  /// Faces of the control mesh as given (after welding coincident positions).
  std::size_t control_face_count() const;
  /// Patches: the control faces, or the faces of the control mesh subdivided once.
  std::size_t patch_count() const;
  /// Exact limit position and first derivatives of \p patch at (u, v), both in [0, 1].
  SurfacePoint evaluate(std::uint32_t patch, double u, double v) const;
  /// The patch's corners as vertex ids of the (once-subdivided) quad mesh, in the order
  /// (u, v) = (0, 0), (1, 0), (1, 1), (0, 1). Two patches share an edge exactly when they
  /// share its two corner ids; the limit curve of a shared edge is the same from both sides.
  std::array<std::uint32_t, 4> patch_corners(std::uint32_t patch) const;

  /// A crack-free tessellation: \p segments x \p segments cells per patch, uniform in (u, v),
  /// each split into two triangles along its shorter diagonal, counter-clockwise in (u, v)
  /// (the control mesh's orientation). Every point on a shared edge or corner is evaluated
  /// once and shared by the patches around it, so a closed control mesh gives a closed mesh.
  /// \p face_patch, when given, receives the patch of each output triangle.
  PolygonSoup tessellate(int segments, std::vector<std::uint32_t>* face_patch = nullptr) const;

  ~SubdivisionSurface();
  SubdivisionSurface(const SubdivisionSurface&) = delete;
  SubdivisionSurface& operator=(const SubdivisionSurface&) = delete;

 private:
  struct Impl;
  explicit SubdivisionSurface(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowkit
