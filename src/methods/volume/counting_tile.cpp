#include "counting_tile.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace shadowkit {

VisibleFrame::VisibleFrame(const Scene& scene, const Light& light, const SubObjects& parts_,
                           const VisibleSurfaceBuffer& surfaces_, int eye_count_)
    : surfaces(surfaces_),
      parts(parts_),
      rays(scene.camera),
      face_keys(scene.face_count()),
      lit_side(scene.face_count()),
      eye_count(eye_count_) {
  tbb::parallel_for(std::uint32_t(0), scene.face_count(), [&](std::uint32_t f) {
    const Plane& plane = scene.face_plane(f);
    face_keys[f] = rays.key_plane(plane.normal, plane.d);
    lit_side[f] = faces_light(plane, rays.eye, light);
  });
}

bool CountingTile::load(const VisibleFrame& frame, int x0_, int y0_, int w_, int h_) {
  x0 = x0_, y0 = y0_, w = w_, h = h_;
  std::fill_n(delta, h * (kTile + 1), 0);
  std::fill_n(&cell_jump[0][0], kCellRows * kCellColumns, 0);
  std::fill_n(points_loaded_, h, false);
  std::fill_n(&cell_keys[0][0], kCellRows * kCellColumns, KeyRange{});
  std::fill_n(&cell_receivers[0][0], kCellRows * kCellColumns, Bounds3{});
  for (int r = 0; r < h; ++r) {
    std::uint32_t last_face = kNoFace;
    for (int c = 0; c < w; ++c) {
      const int k = r * w + c;
      face[k] = frame.surfaces.face[frame.surfaces.index(x0 + c, y0 + r)];
      count[k] = frame.eye_count;
      if (c % kBlock == 0) run_keys[r][c / kBlock] = {}, last_face = kNoFace;
      if (face[k] == kNoFace) continue;
      run_keys[r][c / kBlock].add(frame.face_keys[face[k]].at(x0 + c, y0 + r));
      if (face[k] != last_face) {
        last_face = face[k];
        cell_receivers[r / kBand][c / kBlock].add(
            frame.parts.bounds[frame.parts.of_face[last_face]]);
      }
    }
    for (int b = 0; b * kBlock < w; ++b) {
      run_keys[r][b].widen();
      cell_keys[r / kBand][b].add(run_keys[r][b]);
    }
  }
  // Crow's receivers per cell: the visible sub-objects' boxes, within the piece of the view
  // that the cell's keys span.
  all_keys = {};
  receivers = {};
  for (int cr = 0; cr * kBand < h; ++cr) {
    for (int cc = 0; cc * kBlock < w; ++cc) {
      const KeyRange& keys = cell_keys[cr][cc];
      Bounds3& box = cell_receivers[cr][cc];
      if (keys.empty()) continue;
      const Bounds3 piece = view_piece(frame.rays, x0 + cc * kBlock, y0 + cr * kBand,
                                       x0 + std::min(w, (cc + 1) * kBlock) - 1,
                                       y0 + std::min(h, (cr + 1) * kBand) - 1, keys);
      box = {max(box.lo, piece.lo), min(box.hi, piece.hi)};
      all_keys.add(keys);
      receivers.add(box);
    }
  }
  return !all_keys.empty();
}

void CountingTile::load_points(const VisibleFrame& frame, int row) {
  if (points_loaded_[row]) return;
  points_loaded_[row] = true;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (int c = 0; c < w; ++c) {
    const std::size_t i = frame.surfaces.index(x0 + c, y0 + row);
    const Vec3 p = frame.surfaces.covered(i) ? frame.surfaces.point(i) : Vec3{kNaN, kNaN, kNaN};
    const int k = row * w + c;
    x[k] = p.x, y[k] = p.y, z[k] = p.z;
  }
}

std::size_t CountingTile::finish(const VisibleFrame& frame, ShadowMask& mask) {
  std::size_t negative = 0;
  for (int r = 0; r < h; ++r) {
    int jump = 0;
    for (int c = 0; c < w; ++c) {
      jump += delta[r * (kTile + 1) + c];
      const int k = r * w + c;
      if (face[k] == kNoFace) continue;
      const int total = count[k] + jump + cell_jump[r / kBand][c / kBlock];
      negative += total < 0;
      const bool lit = total <= 0 && frame.lit_side[face[k]];
      mask.pixels[frame.surfaces.index(x0 + c, y0 + r)] = lit ? kMaskLit : kMaskShadow;
    }
  }
  return negative;
}

}  // namespace shadowkit
