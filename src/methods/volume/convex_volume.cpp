#include "convex_volume.h"

#include <algorithm>
#include <bit>

namespace shadowkit {

ConvexVolumes::ConvexVolumes(const std::vector<ShadowPolygon>& polygons,
                             const std::vector<ShadowFrustum>& frusta,
                             const std::vector<char>& cullable, const RayGrid& rays)
    : index_(frusta.size(), -1) {
  std::vector<char> depth_pass(frusta.size(), 1);
  for (const ShadowPolygon& p : polygons) depth_pass[p.sub_object] &= !p.depth_fail;
  for (const ShadowPolygon& p : polygons) {
    const std::uint32_t k = p.sub_object;
    const std::span<const Plane> planes = frusta[k].volume_planes();
    if (index_[k] >= 0 || !depth_pass[k] || !cullable[k] || planes.empty()) continue;
    ConvexVolume v;
    v.sub_object = k;
    for (const Plane& inward : planes) {
      // Depth-pass keeps the eye off these planes (needs_depth_fail, the eye's count).
      const bool eye_outside = inward.distance(rays.eye) < 0;
      const Plane plane = eye_outside ? inward : Plane{-inward.normal, -inward.d};
      v.inside_beyond |= std::uint32_t(eye_outside) << v.plane_count;
      v.keys[v.plane_count] = rays.key_plane(plane.normal, plane.d);
      v.planes[v.plane_count++] = plane;
    }
    index_[k] = std::int32_t(volumes_.size());
    volumes_.push_back(v);
  }
}

std::size_t ConvexVolume::count_cell(const VisibleFrame& frame, int band, int c, int xa, int xb,
                                     int ya, int yb, CountingTile& t) const {
  const int cx0 = t.x0 + c * kBlock, cx1 = std::min(t.x0 + t.w, cx0 + kBlock) - 1;
  const int cy0 = t.y0 + band * kBand, cy1 = std::min(t.y0 + t.h, cy0 + kBand) - 1;
  // Each plane against the cell's visible keys: all beyond it, none, or mixed (left to the
  // pixels).
  std::uint32_t mixed = 0;
  for (int i = 0; i < plane_count; ++i) {
    const Crossing cross = classify_rectangle(keys[i], cx0, cx1, cy0, cy1, t.cell_keys[band][c]);
    if (cross == Crossing::mixed) {
      mixed |= 1u << i;
    } else if ((cross == Crossing::all_before) != bool(inside_beyond >> i & 1)) {
      return 0;  // every visible point of the cell outside this plane
    }
  }
  if (!mixed) {  // every visible point of the cell in the volume: shadowed, whatever else
    t.shadowed |= std::uint64_t(1) << (band * kCellColumns + c);
    return 0;
  }
  std::size_t tested = 0;
  const int a = std::max(xa, cx0), b = std::min(xb, cx1);
  for (int py = std::max(ya, cy0); py <= std::min(yb, cy1); ++py) {
    const int row = py - t.y0;
    // The run of the row the same way, then its pixels against the planes still mixed.
    std::uint32_t run_mixed = 0;
    bool outside = false;
    for (std::uint32_t m = mixed; m && !outside; m &= m - 1) {
      const int i = std::countr_zero(m);
      const double ka = keys[i].at(a, py), kb = keys[i].at(b, py);
      const Crossing cross =
          classify(std::min(ka, kb), std::max(ka, kb), keys[i].slack, t.run_keys[row][c]);
      if (cross == Crossing::mixed) {
        run_mixed |= 1u << i;
      } else {
        outside = (cross == Crossing::all_before) != bool(inside_beyond >> i & 1);
      }
    }
    if (outside) continue;
    if (!run_mixed) {
      int* delta = t.delta + row * (kTile + 1) - t.x0;
      ++delta[a], --delta[b + 1];
      continue;
    }
    for (int px = a; px <= b; ++px) {
      const int i = row * t.w + px - t.x0;
      if (t.face[i] == kNoFace) continue;
      ++tested;
      bool inside = true;
      for (std::uint32_t m = run_mixed; m && inside; m &= m - 1) {
        const int k = std::countr_zero(m);
        inside = beyond_plane(planes[k], keys[k], frame, px, py, t.key[i]) ==
                 bool(inside_beyond >> k & 1);
      }
      t.count[i] += inside;
    }
  }
  return tested;
}

}  // namespace shadowkit
