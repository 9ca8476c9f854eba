#include "stencil_count.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>

#include "convex_volume.h"
#include "counting_tile.h"
#include "polygon_tiles.h"
#include "shadowkit/core/prefetch.h"
#include "shadowkit/raster/screen_polygon.h"

namespace shadowkit::volume {
namespace {

using raster::ScreenPolygon;

std::vector<KeyPlane> polygon_keys(const std::vector<ShadowPolygon>& polygons,
                                   const RayGrid& rays) {
  std::vector<KeyPlane> keys(polygons.size());
  tbb::parallel_for(std::size_t(0), polygons.size(), [&](std::size_t i) {
    keys[i] = rays.key_plane(polygons[i].normal, polygons[i].d);
  });
  return keys;
}

// What a polygon adds to every pixel of a span settled as a whole: depth-pass counts the
// crossings before the visible point, depth-fail those behind it.
int settled_jump(const ShadowPolygon& p, Crossing c) {
  if (!p.depth_fail) return c == Crossing::all_before ? p.jump : 0;
  return c == Crossing::all_behind ? -p.jump : 0;
}

// Whether the visible point of pixel \p i, on the polygon's edge face \p k, lies beyond the
// polygon's plane. Hazard: where the raster gives such a face a pixel whose ray passes just
// outside it (vertices snap to 1/256 pixel), the visible point is taken on its plane a
// little past the edge, across the polygon's plane: within a pixel's width of the edge, the
// face's side of the edge decides.
bool edge_face_beyond(const ShadowPolygon& p, int k, const VisibleFrame& frame, std::size_t i,
                      double visible) {
  const double side = dot(p.normal, frame.surfaces.point(i)) + p.d;
  if (std::abs(side) <= frame.rays.grid.step / visible) return p.edge_face_sides[k] > 0;
  return side > 0;
}

// Adds one polygon's crossings on columns [first, last] of tile row \p row, pixel by pixel,
// where the visible point lies beyond the polygon's plane (beyond_plane): only coverage
// depends on the raster. The tile's own copies of faces and keys keep the common case to a
// few operations per pixel.
void count_span(const ShadowPolygon& p, const KeyPlane& key, const VisibleFrame& frame,
                CountingTile& t, int row, int first, int last) {
  const int py = t.y0 + row;
  const int base = row * t.w - t.x0;
  // Depth-pass counts the crossing between the eye and the visible point (Crow); depth-fail
  // the one behind it, where a light cap passing through its own visible point counts too:
  // its volume begins right behind it.
  const int before = p.depth_fail ? 0 : p.jump, behind = p.depth_fail ? -p.jump : 0;
  for (int c = first; c <= last; ++c) {
    const std::uint32_t f = t.face[base + c];
    if (f == kNoFace) continue;
    const double visible = t.key[base + c];
    bool beyond;
    if (f == p.edge_faces[0] || f == p.edge_faces[1]) {
      beyond = edge_face_beyond(p, f == p.edge_faces[0] ? 0 : 1, frame, frame.surfaces.index(c, py),
                                visible);
    } else {
      beyond = beyond_plane({p.normal, p.d}, key, frame, c, py, visible);
    }
    t.count[base + c] += beyond && f != p.face ? before : behind;
  }
}

// Crow's receiver test for one sub-object over the cells of one tile, made on first use:
// its polygons are skipped over cells whose visible points lie outside its shadow frustum.
class ReceiverTest {
 public:
  ReceiverTest(const ShadowFrustum& frustum, bool cullable, const CountingTile& t)
      : frustum_(frustum), tile_(t) {
    if (!cullable) tested_ = reached_ = ~std::uint64_t(0), bands_tested_ = bands_reached_ = ~0u;
  }
  /// Whether it can shadow a visible point of cell row (band) \p band.
  bool reaches_band(int band) {
    const unsigned bit = 1u << band;
    if (!(bands_tested_ & bit)) {
      bands_tested_ |= bit;
      if (!frustum_.misses(tile_.band_receivers[band])) bands_reached_ |= bit;
    }
    return bands_reached_ & bit;
  }
  /// Whether it can shadow a visible point of the cell.
  bool reaches(int cell_row, int cell_column) {
    const std::uint64_t bit = std::uint64_t(1) << (cell_row * kCellColumns + cell_column);
    if (tile_.shadowed & bit) return false;  // settled whatever it adds
    if (!(tested_ & bit)) {
      tested_ |= bit;
      const CellReceivers& cell = tile_.cell_receivers[cell_row][cell_column];
      for (int i = 0; i < cell.count; ++i) {
        if (!frustum_.misses(cell.boxes[i])) {
          reached_ |= bit;
          break;
        }
      }
    }
    return reached_ & bit;
  }
  /// Whether it can shadow a visible point of cells [first, last] of the cell row (none if
  /// first > last).
  bool reaches_any(int cell_row, int first, int last) {
    if (first > last) return false;
    const std::uint64_t cells = ((std::uint64_t(2) << (last - first)) - 1)
                                << (cell_row * kCellColumns + first);
    // Cells already known to be reached settle it without a new test.
    if (reached_ & cells) return true;
    for (int c = first; c <= last; ++c) {
      if (reaches(cell_row, c)) return true;
    }
    return false;
  }

 private:
  const ShadowFrustum& frustum_;
  const CountingTile& tile_;
  std::uint64_t tested_ = 0, reached_ = 0;
  unsigned bands_tested_ = 0, bands_reached_ = 0;
};

// Counts the shadow polygons over one tile.
class TileCounter {
 public:
  TileCounter(const std::vector<ShadowPolygon>& polygons, const std::vector<KeyPlane>& keys,
              const VisibleFrame& frame)
      : polygons_(polygons), keys_(keys), frame_(frame) {}

  // Walks one polygon over the tile; returns the pixels tested one by one.
  std::size_t count_polygon(const ScreenPolygon& s, ReceiverTest& receivers,
                            CountingTile& t) const {
    const ShadowPolygon& poly = polygons_[s.face];
    const KeyPlane& key = keys_[s.face];
    int ya = std::max(t.y0, s.min_y), yb = std::min(t.y0 + t.h - 1, s.max_y);
    const int xa = std::max(t.x0, s.min_x), xb = std::min(t.x0 + t.w - 1, s.max_x);
    if (xa > xb || ya > yb) return 0;
    // Hi-Z over the whole tile first: a polygon wholly behind (depth-pass) or in front of
    // (depth-fail) every visible point adds nothing.
    const Crossing whole = classify_rectangle(key, xa, xb, ya, yb, t.all_keys);
    if (whole != Crossing::mixed && settled_jump(poly, whole) == 0) return 0;
    if (!overlaps_rectangle(s, xa, ya, xb, yb)) return 0;
    narrow_to_strip(s, true, xa, xb, ya, yb);
    if (ya > yb) return 0;
    // Band by band, those where the receiver test leaves a cell within the polygon's columns:
    // the polygon's span on each row (empty: first > last), walked on from the band before
    // where it can.
    int span_a[kTile], span_b[kTile];
    std::optional<raster::PolygonSpanWalker> walker;
    int walked = ya;  // the walker's current row
    std::size_t tested = 0;
    for (int first = ya; first <= yb;) {
      const int band = (first - t.y0) / kBand, last = std::min(yb, t.y0 + (band + 1) * kBand - 1);
      if (receivers.reaches_band(band) &&
          receivers.reaches_any(band, (xa - t.x0) / kBlock, (xb - t.x0) / kBlock)) {
        if (!walker || walked != first) walker.emplace(s, first, yb), walked = first;
        int band_xa = t.x0 + t.w, band_xb = t.x0 - 1;  // the spans' columns in the band
        for (; walked <= last; ++walked, walker->next_row()) {
          int& a = span_a[walked - t.y0] = xa;
          int& b = span_b[walked - t.y0] = xb;
          if (!walker->span(a, b)) {
            a = xb + 1;
            continue;
          }
          band_xa = std::min(band_xa, a), band_xb = std::max(band_xb, b);
        }
        if (band_xa <= band_xb) {
          tested += count_band(poly, key, band, first, last, band_xa, band_xb, span_a, span_b,
                               receivers, t);
        }
      }
      first = last + 1;
    }
    return tested;
  }

  // Counts a convex volume whole over the tile, in the cells within the bounds of its items
  // \p group (its outline, or its polygons where the outline has too many corners) and,
  // band by band, within its \p outline; returns the pixels tested one by one.
  std::size_t count_volume(const ConvexVolume& volume, std::span<const OutlineEdge> outline,
                           std::span<const ScreenPolygon* const> group, ReceiverTest& receivers,
                           CountingTile& t) const {
    int xa = t.x0 + t.w, xb = t.x0 - 1, ya = t.y0 + t.h, yb = t.y0 - 1;
    for (const ScreenPolygon* s : group) {
      xa = std::min(xa, s->min_x), xb = std::max(xb, s->max_x);
      ya = std::min(ya, s->min_y), yb = std::max(yb, s->max_y);
    }
    xa = std::max(xa, t.x0), xb = std::min(xb, t.x0 + t.w - 1);
    ya = std::max(ya, t.y0), yb = std::min(yb, t.y0 + t.h - 1);
    if (xa > xb || ya > yb) return 0;
    std::size_t tested = 0;
    for (int band = (ya - t.y0) / kBand; band <= (yb - t.y0) / kBand; ++band) {
      // The columns of the band within the volume's outline.
      const int band_ya = std::max(ya, t.y0 + band * kBand),
                band_yb = std::min(yb, t.y0 + band * kBand + kBand - 1);
      int band_xa = xa, band_xb = xb;
      if (!outline_columns(outline, band_ya, band_yb, band_xa, band_xb)) continue;
      if (!receivers.reaches_band(band)) continue;
      for (int c = (band_xa - t.x0) / kBlock; c <= (band_xb - t.x0) / kBlock; ++c) {
        if (receivers.reaches(band, c))
          tested += volume.count_cell(frame_, band, c, band_xa, band_xb, band_ya, band_yb, t);
      }
    }
    return tested;
  }

 private:
  // Rows [first, last] of one band, where the polygon's spans cover columns [xa, xb]. Each
  // cell the polygon reaches is settled first, by the receiver test and by its depth keys
  // against the cell's: only the rows of cells it passes through are tested run by run, and
  // only runs it passes through pixel by pixel.
  std::size_t count_band(const ShadowPolygon& poly, const KeyPlane& key, int band, int first,
                         int last, int xa, int xb, const int* span_a, const int* span_b,
                         ReceiverTest& receivers, CountingTile& t) const {
    const int ca = (xa - t.x0) / kBlock, cb = (xb - t.x0) / kBlock;
    std::size_t tested = 0;
    for (int c = ca; c <= cb; ++c) {
      if (!receivers.reaches(band, c)) continue;
      const int cx0 = std::max(xa, t.x0 + c * kBlock),
                cx1 = std::min(xb, t.x0 + c * kBlock + kBlock - 1);
      const Crossing cross = classify_rectangle(key, cx0, cx1, first, last, t.cell_keys[band][c]);
      const int jump = settled_jump(poly, cross);
      if (cross == Crossing::mixed || jump != 0) {
        tested += count_cell(poly, key, band, c, first, last, span_a, span_b, jump, t);
      }
    }
    return tested;
  }

  // One cell: a settled \p jump over the polygon's spans (over the whole cell when they
  // cover it), or, where the polygon passes through the visible points (jump 0), run by run
  // and pixel by pixel.
  std::size_t count_cell(const ShadowPolygon& poly, const KeyPlane& key, int band, int c, int first,
                         int last, const int* span_a, const int* span_b, int jump,
                         CountingTile& t) const {
    const int cx0 = t.x0 + c * kBlock, cx1 = std::min(t.x0 + t.w, cx0 + kBlock) - 1;
    if (jump != 0 && !t.cell_faces[band][c].shows_either(poly.edge_faces) &&
        first == t.y0 + band * kBand && last == std::min(t.y0 + t.h, first + kBand) - 1 &&
        std::all_of(span_a + first - t.y0, span_a + last - t.y0 + 1,
                    [&](int a) { return a <= cx0; }) &&
        std::all_of(span_b + first - t.y0, span_b + last - t.y0 + 1,
                    [&](int b) { return b >= cx1; })) {
      t.cell_jump[band][c] += jump;
      return 0;
    }
    std::size_t tested = 0;
    for (int py = first; py <= last; ++py) {
      const int a = std::max(span_a[py - t.y0], cx0), b = std::min(span_b[py - t.y0], cx1);
      if (a > b) continue;
      const int row = py - t.y0;
      const bool shows_edge_face = t.run_faces[row][c].shows_either(poly.edge_faces);
      int j = jump;
      if (j == 0 || shows_edge_face) {
        // A run showing one of the polygon's edge faces needs edge_face_beyond, pixel by pixel.
        Crossing cross = Crossing::mixed;
        if (!shows_edge_face) {
          const double ka = key.at(a, py), kb = key.at(b, py);
          cross = classify(std::min(ka, kb), std::max(ka, kb), key.slack, t.run_keys[row][c]);
        }
        if (cross == Crossing::mixed) {
          count_span(poly, key, frame_, t, row, a, b);
          tested += std::size_t(b - a + 1);
          continue;
        }
        j = settled_jump(poly, cross);
        if (j == 0) continue;
      }
      int* delta = t.delta + row * (kTile + 1) - t.x0;
      delta[a] += j;
      delta[b + 1] -= j;
    }
    return tested;
  }

  const std::vector<ShadowPolygon>& polygons_;
  const std::vector<KeyPlane>& keys_;
  const VisibleFrame& frame_;
};

// Whether the shadow polygons of a sub-object may be skipped over pixels whose visible points
// lie outside its shadow frustum: their crossings there add up to the sub-object's share of
// the eye's count, taken away again (depth-pass), or to nothing (depth-fail). Depth-pass
// sub-objects whose frustum may hold the eye are never skipped.
std::vector<char> receiver_cullable(const ShadowFrusta& frusta,
                                    const std::vector<ShadowPolygon>& polygons, Vec3 eye) {
  std::vector<char> cullable(frusta.size(), 1);
  const Bounds3 at_eye{eye, eye};
  for (const ShadowPolygon& p : polygons) {
    if (!p.depth_fail && !frusta[p.sub_object].misses(at_eye)) cullable[p.sub_object] = 0;
  }
  return cullable;
}

// Orders \p items by how near the light their sub-objects lie, nearest first, keeping each
// sub-object's together; returns the sub-object of each, in the new order. The bins keep this
// order in every tile, and a near caster's volume holds more of what lies behind it: the
// pixels it settles (CountingTile::settled) spare the volumes that come after it most of
// their tests.
std::vector<std::uint32_t> order_from_light(std::vector<const ScreenPolygon*>& items,
                                            const std::vector<ShadowPolygon>& polygons,
                                            const SubObjects& parts, const Light& light) {
  std::vector<double> near(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Vec3 c = parts.bounds[k].center();
    near[k] =
        light.type == Light::Type::point ? length(c - light.position) : dot(c, light.direction);
  }
  // Sorted with their keys beside them (a key looked up per comparison misses the cache),
  // ties in their order.
  std::vector<std::uint32_t> item_parts(items.size());
  std::vector<std::pair<double, std::uint32_t>> order(items.size());
  tbb::parallel_for(std::size_t(0), items.size(), [&](std::size_t i) {
    item_parts[i] = polygons[items[i]->face].sub_object;
    order[i] = {near[item_parts[i]], std::uint32_t(i)};
  });
  tbb::parallel_sort(order.begin(), order.end());
  std::vector<const ScreenPolygon*> sorted(items.size());
  std::vector<std::uint32_t> sorted_parts(items.size());
  tbb::parallel_for(std::size_t(0), items.size(), [&](std::size_t i) {
    sorted[i] = items[order[i].second];
    sorted_parts[i] = item_parts[order[i].second];
  });
  items.swap(sorted);
  return sorted_parts;
}

// One tile's counting: its binned items, which come grouped by sub-object, one sub-object
// at a time.
struct TilePass {
  const std::vector<ShadowPolygon>& polygons;
  const ShadowFrusta& frusta;
  const std::vector<char>& cullable;
  const ConvexVolumes& volumes;
  const TileCounter& counter;
  std::span<const ScreenPolygon> screen;        ///< per shadow polygon
  std::span<const ScreenPolygon* const> items;  ///< what was binned
  std::span<const std::uint32_t> item_parts;    ///< the sub-object of each item

  // Counts the items \p binned (indices into items) over tile t; adds the pixels tested one
  // by one to \p fill and the sub-objects Crow's receiver test culls to \p culled.
  void count(std::span<const std::uint32_t> binned, CountingTile& t, std::size_t& fill,
             std::size_t& culled) const {
    thread_local std::vector<const ScreenPolygon*> group;
    // Nearest the light first: the volumes that settle cells come early, and once every
    // cell is settled the rest are skipped whole (Crow's casters in the shadow of nearer ones).
    for (std::size_t b = 0, end; b < binned.size() && !t.all_shadowed(); b = end) {
      const std::uint32_t k = item_parts[binned[b]];
      group.clear();
      for (end = b; end < binned.size() && item_parts[binned[end]] == k; ++end) {
        group.push_back(items[binned[end]]);
      }
      // The next sub-object's frustum and volume, scattered in memory, start loading now.
      if (end < binned.size()) {
        const std::uint32_t next = item_parts[binned[end]];
        prefetch(frusta[next]);
        if (const ConvexVolume* v = volumes.of(next)) prefetch(*v);
      }
      if (cullable[k] && frusta[k].misses(t.receivers)) {
        ++culled;
        continue;
      }
      fill += count_sub_object(k, group, t);
    }
  }

 private:
  // Sub-object k's items \p group over tile t, with Crow's receiver test once for the tile,
  // then per cell; returns the pixels tested one by one.
  std::size_t count_sub_object(std::uint32_t k, std::vector<const ScreenPolygon*>& group,
                               CountingTile& t) const {
    ReceiverTest receivers(frusta[k], cullable[k], t);
    const ConvexVolume* volume = volumes.of(k);
    if (volume) return counter.count_volume(*volume, volumes.outline(k), group, receivers, t);
    if (volumes.binned_by_hull(k)) {  // one item for all its polygons
      group.clear();
      const auto [first, last] = volumes.screen_polygons(k);
      for (std::uint32_t i = first; i < last; ++i) group.push_back(&screen[i]);
    }
    std::size_t tested = 0;
    for (const ScreenPolygon* s : group) tested += counter.count_polygon(*s, receivers, t);
    return tested;
  }
};

}  // namespace

StencilStats count_shadow_polygons(const std::vector<ShadowPolygon>& polygons,
                                   std::span<const ScreenPolygon> screen, int eye_count,
                                   const Scene& scene, const Light& light, const SubObjects& parts,
                                   const ShadowFrusta& frusta, const VisibleSurfaceBuffer& surfaces,
                                   ShadowMask& mask, std::vector<const ScreenPolygon*>& items) {
  const Camera& cam = scene.camera;
  const VisibleFrame frame(scene, light, parts, surfaces, eye_count);
  const std::vector<KeyPlane> keys = polygon_keys(polygons, frame.rays);
  const TileCounter counter(polygons, keys, frame);
  const std::vector<char> cullable = receiver_cullable(frusta, polygons, cam.position);
  const ConvexVolumes volumes(polygons, frusta, cullable, frame.rays, screen);
  // Convex volumes are binned by their outlines, one item each, the other polygons one by
  // one; items of one sub-object stay together.
  items.clear();
  for (const ScreenPolygon& s : screen) {
    const std::uint32_t k = polygons[s.face].sub_object;
    if (!volumes.binned_by_hull(k)) items.push_back(&s);
  }
  for (std::uint32_t k = 0; k < frusta.size(); ++k) {
    if (volumes.binned_by_hull(k)) items.push_back(&volumes.hull(k));
  }
  const std::vector<std::uint32_t> item_parts = order_from_light(items, polygons, parts, light);
  const PolygonBins bins(items, cam.width, cam.height);
  std::atomic<std::size_t> fill = 0, negative = 0, culled = 0, shadowed = 0;

  const TilePass pass{polygons, frusta, cullable, volumes, counter, screen, items, item_parts};
  // One task per tile: the cost is in the tiles of the cube cluster, a few contiguous rows,
  // and larger chunks left one core with the last of them in some runs (shade time 26-29 ms
  // or 34-35 ms on `cubes:2000` run to run).
  tbb::parallel_for(
      0, bins.tile_count(),
      [&](int tile) {
        thread_local CountingTile t;
        const int x0 = (tile % bins.tiles_x) * kTile, y0 = (tile / bins.tiles_x) * kTile;
        const int w = std::min(kTile, cam.width - x0), h = std::min(kTile, cam.height - y0);
        if (bins.start[tile] == bins.start[tile + 1]) {
          CountingTile::finish_uncounted(frame, x0, y0, w, h, mask);
          return;
        }
        if (!t.load(frame, x0, y0, w, h)) return;
        std::size_t tile_fill = 0, tile_culled = 0;
        pass.count({bins.items.data() + bins.start[tile], bins.items.data() + bins.start[tile + 1]},
                   t, tile_fill, tile_culled);
        fill += tile_fill;
        culled += tile_culled;
        shadowed += std::size_t(std::popcount(t.shadowed));
        negative += t.finish(frame, mask);
      },
      tbb::simple_partitioner());
  return {fill.load(), negative.load(), culled.load(), volumes.size(), shadowed.load()};
}

}  // namespace shadowkit::volume
