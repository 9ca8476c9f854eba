#include "stencil_count.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "../../raster/convex_polygon.h"
#include "../../raster/tile_bins.h"
#include "depth_keys.h"

namespace shadowkit {
namespace {

using raster::ScreenPolygon;
using raster::TileBins;
constexpr int kTile = TileBins::kTile;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNoSubObject = std::numeric_limits<std::uint32_t>::max();

// Shadow polygons as convex screen polygons, face = polygon index. Order does not matter:
// counts add up.
std::vector<ScreenPolygon> setup_shadow_polygons(const std::vector<ShadowPolygon>& polygons,
                                                 const RasterProjection& view) {
  constexpr std::size_t kChunk = 1024;
  std::vector<std::vector<ScreenPolygon>> chunks((polygons.size() + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    for (std::size_t i = c * kChunk; i < std::min(polygons.size(), (c + 1) * kChunk); ++i) {
      const ShadowPolygon& p = polygons[i];
      raster::setup_convex_polygon({p.corners.data(), std::size_t(p.corner_count)},
                                   std::uint32_t(i), view, chunks[c]);
    }
  });
  std::vector<ScreenPolygon> all;
  for (const auto& c : chunks) all.insert(all.end(), c.begin(), c.end());
  return all;
}

std::vector<KeyPlane> polygon_keys(const std::vector<ShadowPolygon>& polygons,
                                   const RayGrid& rays) {
  std::vector<KeyPlane> keys(polygons.size());
  tbb::parallel_for(std::size_t(0), polygons.size(), [&](std::size_t i) {
    keys[i] = rays.key_plane(polygons[i].normal, polygons[i].d);
  });
  return keys;
}

// Per scene face: its depth key plane (the visible keys of its pixels) and whether its
// visible side faces the light (contract condition 1).
struct FaceTable {
  std::vector<KeyPlane> keys;
  std::vector<char> lit_side;
  FaceTable(const Scene& scene, const Light& light, const RayGrid& rays)
      : keys(scene.face_count()), lit_side(scene.face_count()) {
    tbb::parallel_for(std::uint32_t(0), scene.face_count(), [&](std::uint32_t f) {
      const Plane& plane = scene.face_plane(f);
      keys[f] = rays.key_plane(plane.normal, plane.d);
      lit_side[f] = faces_light(plane, rays.eye, light);
    });
  }
};

// Whether polygon \p s may own a pixel centre of the tile [x0, x1] x [y0, y1]: no edge has
// all four corner centres outside. Long thin shadow polygons cross few of the tiles their
// bounds overlap; this keeps the span walk off the rest.
bool overlaps_tile(const ScreenPolygon& s, int x0, int y0, int x1, int y1) {
  for (int i = 0; i < s.count; ++i) {
    const raster::FixedPoint a = s.corners[i].p, b = s.corners[(i + 1) % s.count].p;
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    // As EdgeWalker: E = dx (256 py + 128 - y_i) - dy (256 px + 128 - x_i), >= 0 inside.
    const auto e = [&](int px, int py) {
      return dx * (py * raster::kSubpixel + raster::kSubpixel / 2 - a.y) -
             dy * (px * raster::kSubpixel + raster::kSubpixel / 2 - a.x);
    };
    if (std::max({e(x0, y0), e(x1, y0), e(x0, y1), e(x1, y1)}) < 0) return false;
  }
  return true;
}

// Narrows [va, vb], pixels along one axis, to those where polygon \p s can own pixel centres
// within pixels [ua, ub] along the other (u = x for rows, u = y for columns): the extent of
// the polygon within that strip, widened by a pixel. A thin slanted shadow polygon spans
// many more rows of a tile than it crosses within its columns, and the other way round.
void narrow_to_strip(const ScreenPolygon& s, bool u_is_x, int ua, int ub, int& va, int& vb) {
  constexpr double kSub = double(raster::kSubpixel);
  const double lo = (ua - 0.5) * kSub, hi = (ub + 1.5) * kSub;  // centres +- one pixel
  double v_min = kInf, v_max = -kInf;
  for (int i = 0; i < s.count; ++i) {
    const raster::FixedPoint a = s.corners[i].p, b = s.corners[(i + 1) % s.count].p;
    double u0 = double(u_is_x ? a.x : a.y), v0 = double(u_is_x ? a.y : a.x);
    double u1 = double(u_is_x ? b.x : b.y), v1 = double(u_is_x ? b.y : b.x);
    if (u0 > u1) std::swap(u0, u1), std::swap(v0, v1);
    if (u1 < lo || u0 > hi) continue;
    // The part of the edge inside the strip; v is linear in u along it.
    const double slope = u1 > u0 ? (v1 - v0) / (u1 - u0) : 0;
    const double va_edge = u0 < lo ? v0 + slope * (lo - u0) : v0;
    const double vb_edge = u1 > hi ? v0 + slope * (hi - u0) : v1;
    v_min = std::min({v_min, va_edge, vb_edge});
    v_max = std::max({v_max, va_edge, vb_edge});
  }
  va = std::max(va, int(std::floor(v_min / kSub)) - 1);
  vb = std::min(vb, int(std::ceil(v_max / kSub)) + 1);
}

// What a polygon adds to every pixel of a span settled as a whole: depth-pass counts the
// crossings before the visible point, depth-fail those behind it.
int settled_jump(const ShadowPolygon& p, Crossing c) {
  if (!p.depth_fail) return c == Crossing::all_before ? p.jump : 0;
  return c == Crossing::all_behind ? -p.jump : 0;
}

// Visible keys are kept per run of kBlock pixels of a row: a span is settled against the
// runs it touches, so a polygon in front of the near cubes of one part of a row is not tested
// pixel by pixel because the row also shows the far ground elsewhere.
constexpr int kBlock = 8;
// Rows of a band: the Hi-Z test between the whole tile and single spans.
constexpr int kBand = 8;

// One tile: visible faces, keys and counts; visible points (NaN for background, so that no
// plane test passes) loaded per row when an unsettled span first needs them. Whole-span jumps
// go into `delta` (+jump at the first column, -jump past the last) and are summed along each
// row at the end: O(1) per span.
struct TileCounts {
  double x[kTile * kTile], y[kTile * kTile], z[kTile * kTile];
  std::uint32_t face[kTile * kTile];
  int count[kTile * kTile];
  int delta[kTile * (kTile + 1)];
  KeyRange block[kTile][kTile / kBlock], band[kTile / kBand][kTile / kBlock], all;
  Bounds3 receivers, band_receivers[kTile / kBand];  ///< hold every visible point there
  bool points_loaded[kTile];
  int x0, y0, w, h;

  KeyRange span_keys(int row, int first, int last) const {
    KeyRange r;
    for (int b = first / kBlock; b <= last / kBlock; ++b) r.add(block[row][b]);
    return r;
  }
  KeyRange band_keys(int b, int first, int last) const {
    KeyRange r;
    for (int k = first / kBlock; k <= last / kBlock; ++k) r.add(band[b][k]);
    return r;
  }
};

// Adds one polygon's crossings on one span of a row. The plane test is exact in double on
// the visible point itself, so only coverage depends on the raster.
void count_span(const ShadowPolygon& p, const TileCounts& t, int* count, int first, int last) {
  const double nx = p.normal.x, ny = p.normal.y, nz = p.normal.z, d = p.d;
  const int jump = p.jump;
  if (!p.depth_fail) {
    // Crow's depth-pass: the crossing lies between the eye and the visible point.
    for (int i = first; i <= last; ++i) {
      count[i] += (nx * t.x[i] + ny * t.y[i] + nz * t.z[i] + d > 0) ? jump : 0;
    }
  } else if (p.face == kNoFace) {
    // Depth-fail: the crossing lies behind the visible point.
    for (int i = first; i <= last; ++i) {
      count[i] -= (nx * t.x[i] + ny * t.y[i] + nz * t.z[i] + d <= 0) ? jump : 0;
    }
  } else {
    // A light cap through its own visible point: the volume begins right behind it.
    for (int i = first; i <= last; ++i) {
      const bool behind = nx * t.x[i] + ny * t.y[i] + nz * t.z[i] + d <= 0 || t.face[i] == p.face;
      count[i] -= behind ? jump : 0;
    }
  }
}

// Counts the shadow polygons over the tiles of one frame.
class TileCounter {
 public:
  TileCounter(const std::vector<ShadowPolygon>& polygons, const std::vector<KeyPlane>& keys,
              const FaceTable& faces, const SubObjects& parts, const RayGrid& rays,
              const VisibleSurfaceBuffer& surfaces, int eye_count)
      : polygons_(polygons),
        keys_(keys),
        faces_(faces),
        parts_(parts),
        rays_(rays),
        surfaces_(surfaces),
        eye_count_(eye_count) {}

  // Loads the faces and keys of the tile at (x0, y0), w x h pixels; false if it shows only
  // background.
  bool load(int x0, int y0, int w, int h, TileCounts& t) const {
    t.x0 = x0, t.y0 = y0, t.w = w, t.h = h;
    t.all = {};
    t.receivers = {};
    std::fill_n(t.band_receivers, kTile / kBand, Bounds3{});
    std::fill_n(&t.band[0][0], kTile / kBand * (kTile / kBlock), KeyRange{});
    std::fill_n(t.delta, h * (kTile + 1), 0);
    std::fill_n(t.points_loaded, h, false);
    std::uint32_t last_face = kNoFace;
    for (int y = 0; y < h; ++y) {
      if (y % kBand == 0) last_face = kNoFace;
      for (int b = 0; b < kTile / kBlock; ++b) t.block[y][b] = {};
      for (int x = 0; x < w; ++x) {
        const std::uint32_t f = surfaces_.face[surfaces_.index(x0 + x, y0 + y)];
        t.face[y * w + x] = f;
        t.count[y * w + x] = eye_count_;
        if (f == kNoFace) continue;
        t.block[y][x / kBlock].add(faces_.keys[f].at(x0 + x, y0 + y));
        if (f != last_face) {
          t.band_receivers[y / kBand].add(parts_.bounds[parts_.of_face[f]]);
          last_face = f;
        }
      }
      for (int b = 0; b < kTile / kBlock; ++b) {
        t.block[y][b].widen();
        t.band[y / kBand][b].add(t.block[y][b]);
      }
    }
    // Crow's receivers: the visible sub-objects' boxes, within the piece of the view the
    // keys span.
    for (int b = 0; b * kBand < h; ++b) {
      KeyRange keys;
      for (const KeyRange& k : t.band[b]) keys.add(k);
      t.all.add(keys);
      if (keys.empty()) continue;
      const Bounds3 piece = view_piece(rays_, x0, y0 + b * kBand, x0 + w - 1,
                                       std::min(y0 + h, y0 + (b + 1) * kBand) - 1, keys);
      Bounds3& r = t.band_receivers[b];
      r = {max(r.lo, piece.lo), min(r.hi, piece.hi)};
      t.receivers.add(r);
    }
    return !t.all.empty();
  }

  // Walks one triangle's spans over the tile; settles each span by keys where it can and
  // tests pixel by pixel where the polygon passes through the visible surfaces. Returns the
  // pixels tested one by one.
  std::size_t count_polygon(const ScreenPolygon& s, unsigned bands, TileCounts& t) const {
    const ShadowPolygon& poly = polygons_[s.face];
    const KeyPlane& key = keys_[s.face];
    int ya = std::max(t.y0, s.min_y), yb = std::min(t.y0 + t.h - 1, s.max_y);
    const int xa0 = std::max(t.x0, s.min_x), xb0 = std::min(t.x0 + t.w - 1, s.max_x);
    // Hi-Z: over the tile the key is bounded by its corners; polygons wholly in front of or
    // behind every visible point of the tile settle without a span walk when they add nothing.
    const double k00 = key.at(xa0, ya), k10 = key.at(xb0, ya), k01 = key.at(xa0, yb),
                 k11 = key.at(xb0, yb);
    const Crossing whole =
        classify(std::min({k00, k10, k01, k11}), std::max({k00, k10, k01, k11}), key.slack, t.all);
    if (whole != Crossing::mixed && settled_jump(poly, whole) == 0) return 0;
    if (!overlaps_tile(s, xa0, ya, xb0, yb)) return 0;
    narrow_to_strip(s, true, xa0, xb0, ya, yb);
    if (ya > yb) return 0;
    std::size_t tested = 0;
    for (int first = ya; first <= yb;) {
      const int next = t.y0 + ((first - t.y0) / kBand + 1) * kBand;  // the next band's first row
      if (bands & (1u << ((first - t.y0) / kBand))) {
        tested += count_band(s, poly, key, first, std::min(yb, next - 1), xa0, xb0, t);
      }
      first = next;
    }
    return tested;
  }

  // Adds the walked pixels and spans of rows [first, last] of one triangle: the span walk
  // restarts per band, so that bands which settle as a whole (Hi-Z on kBand rows) are skipped.
  std::size_t count_band(const ScreenPolygon& s, const ShadowPolygon& poly, const KeyPlane& key,
                         int first, int last, int xa0, int xb0, TileCounts& t) const {
    narrow_to_strip(s, false, first, last, xa0, xb0);
    if (xa0 > xb0) return 0;
    const double k00 = key.at(xa0, first), k10 = key.at(xb0, first), k01 = key.at(xa0, last),
                 k11 = key.at(xb0, last);
    const Crossing whole =
        classify(std::min({k00, k10, k01, k11}), std::max({k00, k10, k01, k11}), key.slack,
                 t.band_keys((first - t.y0) / kBand, xa0 - t.x0, xb0 - t.x0));
    if (whole != Crossing::mixed && settled_jump(poly, whole) == 0) return 0;
    std::size_t tested = 0;
    raster::PolygonSpanWalker walker(s, first, last);
    for (int py = first; py <= last; ++py, walker.next_row()) {
      int xa = xa0, xb = xb0;
      if (!walker.span(xa, xb)) continue;
      const int row = py - t.y0;
      const double ka = key.at(xa, py), kb = key.at(xb, py);
      const Crossing c = whole != Crossing::mixed
                             ? whole
                             : classify(std::min(ka, kb), std::max(ka, kb), key.slack,
                                        t.span_keys(row, xa - t.x0, xb - t.x0));
      if (c == Crossing::mixed) {
        tested += std::size_t(xb - xa + 1);
        load_points(row, t);
        const int first_pixel = row * t.w - t.x0;
        count_span(poly, t, t.count, first_pixel + xa, first_pixel + xb);
      } else if (const int jump = settled_jump(poly, c)) {
        int* delta = t.delta + row * (kTile + 1) - t.x0;
        delta[xa] += jump;
        delta[xb + 1] -= jump;
      }
    }
    return tested;
  }

  // Adds the whole-span jumps to the counts; writes the tile's mask pixels (shadow where the
  // count is positive, or where the camera sees the face's unlit side: contract condition 1)
  // and returns the number of negative counts.
  std::size_t finish(TileCounts& t, ShadowMask& mask) const {
    std::size_t negative = 0;
    for (int y = 0; y < t.h; ++y) {
      int jump = 0;
      for (int x = 0; x < t.w; ++x) {
        jump += t.delta[y * (kTile + 1) + x];
        const int k = y * t.w + x;
        if (t.face[k] == kNoFace) continue;
        const int c = t.count[k] + jump;
        negative += c < 0;
        const bool lit = c <= 0 && faces_.lit_side[t.face[k]];
        mask.pixels[surfaces_.index(t.x0 + x, t.y0 + y)] = lit ? kMaskLit : kMaskShadow;
      }
    }
    return negative;
  }

 private:
  // The exact visible points of one row, on first use: most rows settle by keys alone.
  void load_points(int row, TileCounts& t) const {
    if (t.points_loaded[row]) return;
    t.points_loaded[row] = true;
    for (int x = 0; x < t.w; ++x) {
      const std::size_t i = surfaces_.index(t.x0 + x, t.y0 + row);
      const Vec3 p = surfaces_.covered(i) ? surfaces_.point(i) : Vec3{kNaN, kNaN, kNaN};
      const int k = row * t.w + x;
      t.x[k] = p.x, t.y[k] = p.y, t.z[k] = p.z;
    }
  }

  const std::vector<ShadowPolygon>& polygons_;
  const std::vector<KeyPlane>& keys_;
  const FaceTable& faces_;
  const SubObjects& parts_;
  const RayGrid& rays_;
  const VisibleSurfaceBuffer& surfaces_;
  int eye_count_;
};

// Whether the shadow polygons of a sub-object may be skipped over a tile whose visible points
// lie outside its shadow frustum: their crossings there add up to the sub-object's share of
// the eye's count, taken away again (depth-pass), or to nothing (depth-fail). Depth-pass
// sub-objects whose frustum may hold the eye are never skipped.
std::vector<char> tile_cullable(const std::vector<ShadowFrustum>& frusta,
                                const std::vector<ShadowPolygon>& polygons, Vec3 eye) {
  std::vector<char> cullable(frusta.size(), 1);
  const Bounds3 at_eye{eye, eye};
  for (const ShadowPolygon& p : polygons) {
    if (!p.depth_fail && !frusta[p.sub_object].misses(at_eye)) cullable[p.sub_object] = 0;
  }
  return cullable;
}

}  // namespace

StencilStats count_shadow_polygons(const std::vector<ShadowPolygon>& polygons, int eye_count,
                                   const Scene& scene, const Light& light, const SubObjects& parts,
                                   const std::vector<ShadowFrustum>& frusta,
                                   const VisibleSurfaceBuffer& surfaces, ShadowMask& mask) {
  const Camera& cam = scene.camera;
  const RasterProjection view =
      RasterProjection::from_camera(cam, near_plane_for(scene.bounds(), cam.position));
  const std::vector<ScreenPolygon> tris = setup_shadow_polygons(polygons, view);
  const RayGrid rays(cam);
  const std::vector<KeyPlane> keys = polygon_keys(polygons, rays);
  const FaceTable faces(scene, light, rays);
  const TileBins bins(tris, view.width, view.height);
  const TileCounter counter(polygons, keys, faces, parts, rays, surfaces, eye_count);
  const std::vector<char> cullable = tile_cullable(frusta, polygons, cam.position);
  std::atomic<std::size_t> fill = 0, negative = 0, culled = 0;

  tbb::parallel_for(0, bins.tile_count(), [&](int tile) {
    thread_local TileCounts t;
    const int x0 = (tile % bins.tiles_x) * kTile, y0 = (tile / bins.tiles_x) * kTile;
    if (!counter.load(x0, y0, std::min(kTile, view.width - x0), std::min(kTile, view.height - y0),
                      t)) {
      return;
    }
    std::size_t tile_fill = 0, tile_culled = 0;
    std::uint32_t part = kNoSubObject;
    unsigned bands = 0;  // of the tile, those whose visible points the sub-object can shadow
    for (std::uint32_t b = bins.start[tile]; b < bins.start[tile + 1]; ++b) {
      const ScreenPolygon& s = tris[bins.items[b]];
      // Crow's receiver test, once per sub-object: polygons come grouped by sub-object.
      if (const std::uint32_t k = polygons[s.face].sub_object; k != part) {
        part = k;
        bands = ~0u;
        if (cullable[k]) {
          bands = 0;
          if (!frusta[k].misses(t.receivers)) {
            for (int band = 0; band < kTile / kBand; ++band) {
              bands |= unsigned(!frusta[k].misses(t.band_receivers[band])) << band;
            }
          }
        }
        tile_culled += bands == 0;
      }
      if (bands) tile_fill += counter.count_polygon(s, bands, t);
    }
    fill += tile_fill;
    culled += tile_culled;
    negative += counter.finish(t, mask);
  });
  return {fill.load(), negative.load(), culled.load()};
}

}  // namespace shadowkit
