#pragma once
// One tile of the counting pass: what its pixels see, summarized for Crow's coherence tests
// (1977, Sec. VII), and their counts.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "depth_keys.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/raster/tile_bins.h"
#include "shadowkit/scene/sub_objects.h"

namespace shadowkit::volume {

inline constexpr int kTile = raster::TileBins::kTile;
/// A cell is kBand rows by kBlock columns: the unit of the depth-key and receiver tests.
inline constexpr int kBlock = 8, kBand = 8;
inline constexpr int kCellColumns = kTile / kBlock, kCellRows = kTile / kBand;
/// Receivers kept apart per cell; a cell showing more sub-objects keeps the box of them all.
inline constexpr int kCellReceivers = 4;

/// \brief The frame as the counting pass sees it: the visible surfaces and, per scene face,
/// its depth-key plane and whether its visible side faces the light (contract condition 1).
struct VisibleFrame {
  const VisibleSurfaceBuffer& surfaces;
  const SubObjects& parts;
  RayGrid rays;
  std::vector<KeyPlane> face_keys;
  std::vector<char> lit_side;
  int eye_count;  ///< where every depth-pass count starts

  VisibleFrame(const Scene& scene, const Light& light, const SubObjects& parts,
               const VisibleSurfaceBuffer& surfaces, int eye_count);
};

/// A visible point on face \p f with count \p total is in shadow when the count is positive
/// or when the camera sees the face's unlit side (contract condition 1).
inline std::uint8_t mask_value(const VisibleFrame& frame, std::uint32_t f, int total) {
  return total <= 0 && frame.lit_side[f] ? kMaskLit : kMaskShadow;
}

/// Whether the visible point of pixel (\p x, \p y), at depth key \p visible, lies beyond
/// \p plane (on its positive side; the eye on its negative), whose key plane is \p key: a
/// larger key than the visible one. Keys within the slack of each other fall back to the
/// exact plane test on the visible point itself. A point whose face lies in \p plane is not
/// beyond it, whatever the rounding of its position: so a face of a coincident copy is on
/// the boundary of the copy's volume, as a face is on its own.
inline bool beyond_plane(const Plane& plane, const KeyPlane& key, const VisibleFrame& frame, int x,
                         int y, double visible) {
  const double k = key.at(x, y);
  if (k - key.slack > visible) return true;
  if (k + key.slack < visible) return false;
  const std::size_t i = frame.surfaces.index(x, y);
  return !same_plane(frame.surfaces.plane(i), plane) && plane.distance(frame.surfaces.point(i)) > 0;
}

/// \brief The faces a run of pixels shows: exactly lo and hi while it shows at most two,
/// any face in [lo, hi] once it shows more.
struct FaceRange {
  std::uint32_t lo = kNoFace, hi = 0;
  bool between = false;  ///< faces strictly between lo and hi may show

  void add(std::uint32_t f) {
    if (lo == kNoFace) {
      lo = hi = f;
    } else if (f != lo && f != hi) {
      between |= lo != hi || (lo < f && f < hi);
      lo = std::min(lo, f), hi = std::max(hi, f);
    }
  }
  void add(const FaceRange& r) {
    if (r.lo == kNoFace) return;
    add(r.lo), add(r.hi);
    between |= r.between;
  }
  bool shows(std::uint32_t f) const { return f == lo || f == hi || (between && lo < f && f < hi); }
  bool shows_either(const std::array<std::uint32_t, 2>& f) const {
    return shows(f[0]) || shows(f[1]);
  }
};

/// \brief Crow's receivers in one cell: boxes that hold its visible points, one per visible
/// sub-object (its box within the piece of the view that its keys there span).
struct CellReceivers {
  int count = 0;
  Bounds3 boxes[kCellReceivers];
};

/// \brief One tile of pixels: their faces and counts, and the ranges of visible depth keys
/// per kBlock pixels of a row and per cell, with the receivers of each cell. Jumps settled
/// for a whole span go into a per-row difference array (+jump at its first column, -jump past
/// its last), summed once in finish().
struct CountingTile {
  int x0 = 0, y0 = 0, w = 0, h = 0;
  std::uint32_t face[kTile * kTile];
  double key[kTile * kTile];  ///< visible depth key per pixel (NaN for background)
  int count[kTile * kTile];
  int delta[kTile * (kTile + 1)];
  int cell_jump[kCellRows][kCellColumns];  ///< settled jumps over whole cells
  KeyRange run_keys[kTile][kCellColumns];  ///< per row and kBlock-pixel run
  /// Per row and run, and per cell: the range of the face ids they show (lo > hi: none).
  /// A shadow polygon's edge faces need the pixel test (edge_face_beyond) wherever they
  /// show; where the range excludes them, a run or cell may be settled by its keys.
  FaceRange run_faces[kTile][kCellColumns], cell_faces[kCellRows][kCellColumns];
  KeyRange cell_keys[kCellRows][kCellColumns], all_keys;
  CellReceivers cell_receivers[kCellRows][kCellColumns];
  Bounds3 band_receivers[kCellRows];  ///< hold every visible point of a cell row
  Bounds3 receivers;                  ///< holds every visible point of the tile
  /// Cells whose every visible point is in shadow, whatever the other volumes add: it lies
  /// in a convex volume (ConvexVolume), or the camera sees only unlit sides (contract
  /// condition 1). Every count being >= 0, no more polygons need to visit them.
  std::uint64_t shadowed = 0;
  std::uint64_t occupied = 0;  ///< cells with visible points
  /// Per row, bit x: pixel x of the row is settled, whatever more volumes add: background
  /// (or past the tile's width), the camera sees its face's unlit side, or it lies in a
  /// convex volume. Convex volumes skip settled pixels, and cells whose pixels all are.
  std::uint64_t settled[kTile];

  /// Whether every visible point of the tile is settled in shadow: nothing more can change it.
  bool all_shadowed() const { return (shadowed & occupied) == occupied; }

  /// Loads the tile at (x0, y0), w x h pixels; false if it shows only background.
  bool load(const VisibleFrame& frame, int x0, int y0, int w, int h);
  /// Adds the settled jumps to the counts and writes the tile's mask pixels: shadow where
  /// the count is positive or where the camera sees a face's unlit side. Returns the number
  /// of negative counts (an error in the counting).
  std::size_t finish(const VisibleFrame& frame, ShadowMask& mask);
  /// The mask of a tile that no shadow polygon reaches: every count is the eye's.
  static void finish_uncounted(const VisibleFrame& frame, int x0, int y0, int w, int h,
                               ShadowMask& mask);

 private:
  void load_band(const VisibleFrame& frame, int band);
};

}  // namespace shadowkit::volume
