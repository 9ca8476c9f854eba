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

/// \brief How finely a view sees, a pixel at distance d being d x pixel_at_unit_distance: a
/// tessellation for it keeps every cell within \p pixels pixels of the limit surface, and
/// where a facet may turn from a light, a cell no more than a pixel across: there the facets
/// decide the contract's condition 1, and their terminator moves by up to a cell.
struct ViewTolerance {
  Vec3 eye;
  double pixel_at_unit_distance = 0;  ///< 2 tan(fov_y / 2) / height for a pinhole camera
  double pixels = 0.5;
  /// Where a cell is wider than a pixel, the most its normals may differ, about in radians:
  /// images shade each facet flat.
  double normal_spread = 0.05;
  std::vector<Vec3> point_lights;   ///< positions
  std::vector<Vec3> toward_lights;  ///< unit directions toward the directional lights
};

/// \brief A tessellation fitted to a view (SubdivisionSurface::tessellate_for_view()).
struct ViewTessellation {
  PolygonSoup soup;
  int finest = 1;                   ///< 1 / the side of the finest cell, in patch sides
  std::size_t triangles_asked = 0;  ///< what the view's tolerance asked for, or at least
  bool asked_exactly = true;        ///< false: it asked for more than triangles_asked
  bool coarsened = false;           ///< the bound made it coarser than the view asks
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
  /// Limit position and first derivatives of \p patch at (u, v), both in [0, 1]: exact,
  /// except within 2^-10 of an extraordinary vertex, where a Gregory patch matches the limit
  /// position and tangent plane at its corners (design.md). Safe to call from many threads.
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

  /// A crack-free tessellation fitted to \p view: each patch a quadtree of cells, down to
  /// 1/256 of the patch, a cell split while it fails the view's tolerance, checked at its
  /// corners, side midpoints and centre. A cell is fanned from its centre over the corners of
  /// finer cells along its sides, in its patch or across a patch side. Past \p most_triangles,
  /// the finest cells are merged into their parents until it fits (or every patch is one
  /// cell).
  ViewTessellation tessellate_for_view(const ViewTolerance& view, std::size_t most_triangles) const;

  ~SubdivisionSurface();
  SubdivisionSurface(const SubdivisionSurface&) = delete;
  SubdivisionSurface& operator=(const SubdivisionSurface&) = delete;

 private:
  struct Impl;
  explicit SubdivisionSurface(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowkit
