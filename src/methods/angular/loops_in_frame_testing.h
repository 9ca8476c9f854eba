#pragma once
// Test support: one object's RE loops in a light's frame, sliced at R entries of equal width.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "light_frame.h"
#include "loop_slicer.h"
#include "ridge_edges.h"

namespace shadowkit::angular {

/// \brief One object's RE loops in a light's frame, as AngularTable::build prepares them.
struct LoopsInFrame {
  std::vector<Vec3> local;
  std::vector<double> theta;
  std::vector<std::uint32_t> hidden_id;  ///< the identity: a pair's hidden id is its face
  std::vector<RidgeEdge> ridges;
  std::vector<RidgeEdgeLoop> loops;

  LoopsInFrame(const Mesh& mesh, const FarSheets& sheets, const LightFrame& frame)
      : ridges(find_ridge_edges(mesh, sheets)), loops(chain_ridge_edge_loops(ridges)) {
    for (const Vec3& v : mesh.vertices) {
      local.push_back(frame.local(v));
      theta.push_back(frame.angular_local(local.back()).theta);
    }
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) hidden_id.push_back(f);
  }

  /// \p entries entries of equal width over the loops' theta range.
  ThetaQuantization quantization(int entries) const {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const RidgeEdge& re : ridges) {
      lo = std::min({lo, theta[re.from], theta[re.to]});
      hi = std::max({hi, theta[re.from], theta[re.to]});
    }
    return {lo, (hi - lo) / entries, entries, false};
  }
};

/// The slices at the centres of \p q's entries.
inline std::vector<ThetaSlice> slices_of(const ThetaQuantization& q, bool point_light) {
  std::vector<ThetaSlice> slices;
  for (int k = 0; k < q.resolution; ++k) {
    slices.push_back(ThetaSlice::at(q.centre(k), point_light, std::uint32_t(k)));
  }
  return slices;
}

/// A prism over the U-shaped (non-convex) outline \p u in the xy plane, z in [-1, 1].
inline PolygonSoup prism(const std::vector<Vec3>& u) {
  PolygonSoup s;
  const std::uint32_t n = std::uint32_t(u.size());
  for (const Vec3& p : u) s.positions.push_back({p.x, p.y, 1});
  for (const Vec3& p : u) s.positions.push_back({p.x, p.y, -1});
  std::vector<std::uint32_t> front, back;
  for (std::uint32_t i = 0; i < n; ++i) front.push_back(i), back.push_back(2 * n - 1 - i);
  s.add_face(front);
  s.add_face(back);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    s.add_face({i, n + i, n + j, j});
  }
  return s;
}

}  // namespace shadowkit::angular
