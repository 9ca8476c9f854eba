#include "counting_tile.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace shadowkit::volume {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

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
  all_keys = {};
  receivers = {};
  shadowed = occupied = 0;
  for (int band = 0; band * kBand < h; ++band) load_band(frame, band);
  return !all_keys.empty();
}

void CountingTile::load_band(const VisibleFrame& frame, int band) {
  // Per cell: the visible sub-objects and their keys (a count past kCellReceivers: too many
  // to keep apart), and the box of them all.
  std::uint32_t part[kCellColumns][kCellReceivers];
  KeyRange part_keys[kCellColumns][kCellReceivers];
  int parts[kCellColumns] = {};
  Bounds3 all_parts[kCellColumns];
  std::fill_n(cell_keys[band], kCellColumns, KeyRange{});
  std::fill_n(cell_faces[band], kCellColumns, FaceRange{});
  bool lit[kCellColumns] = {};  // shows a face's lit side
  for (int r = band * kBand; r < std::min(h, (band + 1) * kBand); ++r) {
    std::copy_n(frame.surfaces.face.begin() + std::ptrdiff_t(frame.surfaces.index(x0, y0 + r)), w,
                face + r * w);
    std::fill_n(count + r * w, w, frame.eye_count);
    std::uint64_t& settled_row = settled[r];
    settled_row = w < kTile ? ~std::uint64_t(0) << w : 0;
    for (int cell = 0; cell * kBlock < w; ++cell) {
      KeyRange& keys = run_keys[r][cell];
      keys = {};
      FaceRange& faces = run_faces[r][cell];
      faces = {};
      const int end = std::min(w, (cell + 1) * kBlock);
      for (int c = cell * kBlock, next; c < end; c = next) {
        // A run of one face: its key is linear along the run, so the ends bound it.
        const std::uint32_t f = face[r * w + c];
        for (next = c + 1; next < end && face[r * w + next] == f;) ++next;
        if (f == kNoFace || !frame.lit_side[f]) {
          settled_row |= ((std::uint64_t(2) << (next - 1 - c)) - 1) << c;
        }
        if (f == kNoFace) {
          std::fill(key + r * w + c, key + r * w + next, kNaN);
          continue;
        }
        faces.add(f);
        lit[cell] |= frame.lit_side[f];
        const KeyPlane& plane = frame.face_keys[f];
        for (int i = c; i < next; ++i) key[r * w + i] = plane.at(x0 + i, y0 + r);
        KeyRange run;
        run.add(key[r * w + c]);
        run.add(key[r * w + next - 1]);
        keys.add(run);
        const std::uint32_t p = frame.parts.of_face[f];
        all_parts[cell].add(frame.parts.bounds[p]);
        const int known = std::min(parts[cell], kCellReceivers);
        const int slot = int(std::find(part[cell], part[cell] + known, p) - part[cell]);
        if (slot == known && parts[cell]++ < kCellReceivers)
          part[cell][slot] = p, part_keys[cell][slot] = {};
        if (slot < kCellReceivers && slot < parts[cell]) part_keys[cell][slot].add(run);
      }
      keys.widen();
      cell_keys[band][cell].add(keys);
      cell_faces[band][cell].add(faces);
    }
  }
  // Crow's receivers: each visible sub-object's box within the piece of the view that its
  // keys span.
  const int ya = y0 + band * kBand, yb = y0 + std::min(h, (band + 1) * kBand) - 1;
  band_receivers[band] = {};
  for (int cell = 0; cell * kBlock < w; ++cell) {
    CellReceivers& out = cell_receivers[band][cell];
    out.count = 0;
    if (cell_keys[band][cell].empty()) continue;
    occupied |= std::uint64_t(1) << (band * kCellColumns + cell);
    if (!lit[cell]) shadowed |= std::uint64_t(1) << (band * kCellColumns + cell);
    const int xa = x0 + cell * kBlock, xb = x0 + std::min(w, (cell + 1) * kBlock) - 1;
    const auto add = [&](const Bounds3& box, const KeyRange& keys) {
      const Bounds3 piece = view_piece(frame.rays, xa, ya, xb, yb, keys);
      Bounds3& r = out.boxes[out.count++];
      r = {max(box.lo, piece.lo), min(box.hi, piece.hi)};
      band_receivers[band].add(r);
      receivers.add(r);
    };
    if (parts[cell] > kCellReceivers) {
      add(all_parts[cell], cell_keys[band][cell]);
    } else {
      for (int i = 0; i < parts[cell]; ++i) {
        part_keys[cell][i].widen();
        add(frame.parts.bounds[part[cell][i]], part_keys[cell][i]);
      }
    }
    all_keys.add(cell_keys[band][cell]);
  }
}

std::size_t CountingTile::finish(const VisibleFrame& frame, ShadowMask& mask) {
  std::size_t negative = 0;
  for (int r = 0; r < h; ++r) {
    // The cells' settled jumps go into the row's difference array too.
    int* row_delta = delta + r * (kTile + 1);
    for (int cell = 0; cell * kBlock < w; ++cell) {
      row_delta[cell * kBlock] += cell_jump[r / kBand][cell];
      row_delta[std::min(w, (cell + 1) * kBlock)] -= cell_jump[r / kBand][cell];
    }
    std::uint8_t* out = &mask.pixels[frame.surfaces.index(x0, y0 + r)];
    const std::uint64_t shadowed_row = shadowed >> (r / kBand * kCellColumns);
    int jump = 0;
    for (int c = 0; c < w; ++c) {
      jump += row_delta[c];
      const std::uint32_t f = face[r * w + c];
      if (f == kNoFace) continue;
      if (shadowed_row >> (c / kBlock) & 1) {
        out[c] = kMaskShadow;
        continue;
      }
      const int total = count[r * w + c] + jump;
      negative += total < 0;
      out[c] = mask_value(frame, f, total);
    }
  }
  return negative;
}

void CountingTile::finish_uncounted(const VisibleFrame& frame, int x0, int y0, int w, int h,
                                    ShadowMask& mask) {
  static_assert(kTile == VisibleSurfaceBuffer::kCoverageBlock);
  const VisibleSurfaceBuffer& s = frame.surfaces;
  for (int r = 0; r < h; ++r) {
    // Tiles are the coverage blocks: a row of sky is skipped whole.
    if (!s.block_covered[std::size_t(y0 + r) * s.blocks_per_row() + x0 / kTile]) continue;
    const std::size_t first = s.index(x0, y0 + r);
    for (std::size_t i = first; i < first + std::size_t(w); ++i) {
      const std::uint32_t f = s.face[i];
      if (f != kNoFace) mask.pixels[i] = mask_value(frame, f, frame.eye_count);
    }
  }
}

}  // namespace shadowkit::volume
