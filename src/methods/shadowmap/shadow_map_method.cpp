#include "shadow_map_method.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>
#include <string>
#include <utility>

#include "shadowkit/core/error.h"
#include "shadowkit/methods/shadowmap.h"
#include "shadowkit/scene/limits.h"

namespace shadowkit::shadowmap {
namespace {

constexpr double kDefaultBiasPerDiagonal = 1e-3;
constexpr int kMinResolution = 16, kMaxResolution = 16384;
static_assert(kMaxResolution <= limits::kImageSide);  // the scan converter's largest raster
constexpr int kMaxPcf = 31;
// The camera pass's screen tiles: wide, so that the hardware prefetcher follows each row.
constexpr int kShadeTileW = 128, kShadeTileH = 8;
// Camera passes so far, of every ShadowMapMethod: each pass's number marks what it cached.
std::atomic<std::uint64_t> camera_passes{0};

[[noreturn]] void bad_option(const std::string& key, const std::string& what) {
  throw InputError("option 'shadowmap." + key + "'", what);
}

// An integer option within [lo, hi].
int integer_option(const MethodOptions& options, const std::string& key, int fallback, int lo,
                   int hi) {
  const double value = options.number(key, fallback);
  if (value != std::floor(value) || value < lo || value > hi) {
    bad_option(key, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                        ", got " + options.text(key, ""));
  }
  return int(value);
}

// \p normal in the frame of \p view.
Vec3 view_normal(const RasterProjection& view, Vec3 normal) {
  return {dot(normal, view.right), dot(normal, view.up), dot(normal, view.forward)};
}

// A world axis far from \p forward, as the up hint of a view along it.
Vec3 up_hint(Vec3 forward) {
  const double ax = std::abs(forward.x), ay = std::abs(forward.y), az = std::abs(forward.z);
  if (ay <= ax && ay <= az) return {0, 1, 0};
  return ax <= az ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
}

// The end of the stretch of \p face that starts at column \p x, before \p end: where the face
// changes. Four pixels at a time, as VisibleSurfaceBuffer::next_covered() goes.
int stretch_end(const std::uint32_t* face, int x, int end) {
  const std::uint32_t f = face[x++];
  while (x + 4 <= end &&
         ((face[x] ^ f) | (face[x + 1] ^ f) | (face[x + 2] ^ f) | (face[x + 3] ^ f)) == 0) {
    x += 4;
  }
  while (x < end && face[x] == f) ++x;
  return x;
}

}  // namespace

RasterProjection directional_light_view(const Bounds3& bounds, Vec3 direction, int resolution) {
  const Vec3 forward = normalize(direction);
  const Vec3 up0 = up_hint(forward);
  // The frame orthographic_view() derives from (forward, up0).
  const Vec3 right = normalize(cross(forward, up0));
  const Vec3 up = cross(right, forward);
  const bool empty = bounds.empty();
  const Vec3 center = empty ? Vec3{} : bounds.center();
  const double diagonal = empty || bounds.diagonal() == 0 ? 1.0 : bounds.diagonal();
  double half_w = 0, half_h = 0, behind = 0;
  for (int corner = 0; corner < 8 && !empty; ++corner) {
    const Vec3 c{(corner & 1) ? bounds.hi.x : bounds.lo.x, (corner & 2) ? bounds.hi.y : bounds.lo.y,
                 (corner & 4) ? bounds.hi.z : bounds.lo.z};
    const Vec3 r = c - center;
    half_w = std::max(half_w, std::abs(dot(r, right)));
    half_h = std::max(half_h, std::abs(dot(r, up)));
    behind = std::max(behind, -dot(r, forward));
  }
  // A box seen exactly edge-on projects to a segment; keep the map from collapsing.
  const double min_half = 1e-6 * diagonal;
  // The eye sits a little behind the farthest corner toward the light, so every point of the
  // scene has zv > 0 and is drawn (the orthographic near plane is zv = 0).
  const double depth_back = behind + 1e-3 * diagonal;
  return RasterProjection::orthographic_view(center, forward, up0, std::max(half_w, min_half),
                                             std::max(half_h, min_half), depth_back, resolution,
                                             resolution);
}

ShadowMapMethod::ShadowMapMethod(const MethodOptions& options) {
  options.expect_only("shadowmap", {"resolution", "bias", "slope_bias", "pcf", "tiles"});
  resolution_ = integer_option(options, "resolution", 2048, kMinResolution, kMaxResolution);
  const double bias = options.number("bias", std::nan(""));
  if (bias < 0) bad_option("bias", "expected a depth bias >= 0 in world units");
  if (!std::isnan(bias)) bias_option_ = bias;
  slope_bias_ = options.number("slope_bias", 1.0);
  if (slope_bias_ < 0) bad_option("slope_bias", "expected a slope bias factor >= 0");
  pcf_ = integer_option(options, "pcf", 1, 1, kMaxPcf);
  if (pcf_ % 2 == 0) bad_option("pcf", "expected an odd kernel width (1 = off, 3, 5, ...)");
  const std::string tiles = options.text("tiles", "looked_up");
  if (tiles != "looked_up" && tiles != "all") {
    bad_option("tiles", "expected looked_up or all, got " + tiles);
  }
  all_tiles_ = tiles == "all";
}

void ShadowMapMethod::build(const Scene& scene, std::size_t light, const Context& ctx) {
  light_ = scene.lights.at(light);
  // Default bias: relative to the scene's size, so that it means the same for any units.
  bias_ = bias_option_.value_or(kDefaultBiasPerDiagonal * scene.bounds().diagonal());
  // Only the current light's map is kept; its storage is reused from the last build of the
  // same kind of light.
  if (light_.type == Light::Type::point) {
    ortho_ = {};
    cube_.start(scene, light_.position, resolution_);
  } else {
    cube_ = {};
    ortho_.start(directional_light_view(scene.bounds(), light_.direction, resolution_));
  }
  for (int m = 0; m < map_count(); ++m) wanted_[m].clear();
  if (all_tiles_) draw_maps(scene, ctx);
}

int ShadowMapMethod::map_count() const {
  return light_.type == Light::Type::point ? CubeMap::kFaces : 1;
}

const DepthMap& ShadowMapMethod::map(int m) const {
  return light_.type == Light::Type::point ? cube_.face(m) : ortho_;
}

DepthMap& ShadowMapMethod::map(int m) {
  return const_cast<DepthMap&>(std::as_const(*this).map(m));
}

void ShadowMapMethod::draw_maps(const Scene& scene, const Context& ctx) {
  for (int m = 0; m < map_count(); ++m) map(m).draw(scene, ctx, wanted_[m]);
}

// One row of a screen tile in the camera pass: its visible points, where each is tested, and
// the pixel each decides.
struct ShadowMapMethod::TileRow {
  PointBatch points;
  TexelBatch texels;
  std::array<std::size_t, PointBatch::kSize> pixel;
  std::array<const float*, PointBatch::kSize> stored;  ///< each point's texel
};

// What the camera pass knows of the receiving face of the last pixel, kept while a run of
// pixels stays on one face.
struct ShadowMapMethod::Receiver {
  std::uint32_t face = kNoFace;
  const Plane* plane = nullptr;
  bool faces_light = false;
  double eye_distance = 0;
  ReceiverBias bias;
};

// The receivers a thread has met, a slot per face, kept from tile to tile: a triangle of a
// fine mesh spans a few pixels of two or three rows, so most stretches meet a face that a row
// above met. A slot filled in another camera pass (another light, another method) is stale.
struct ShadowMapMethod::Receivers {
  static constexpr std::size_t kSlots = 512;
  std::array<Receiver, kSlots> slots;
  std::array<std::uint64_t, kSlots> pass{};  ///< the camera pass that filled each slot
};

// The frame the camera pass works on, and the contract's pixel rays as
// VisibleSurfaceBuffer::ray() makes them, (forward + x right) + y up, with the column's part
// computed once per column and the row's once per row.
struct ShadowMapMethod::CameraPass {
  const Scene& scene;
  const VisibleSurfaceBuffer& surfaces;
  ShadowMask& mask;
  Vec3 eye, up;
  Camera::PixelGrid grid;
  ColumnRays columns;

  CameraPass(const Scene& s, const VisibleSurfaceBuffer& v, ShadowMask& m)
      : scene(s),
        surfaces(v),
        mask(m),
        eye(s.camera.position),
        up(s.camera.true_up()),
        grid(s.camera.pixel_grid()) {
    const Vec3 forward = s.camera.forward(), right = s.camera.right();
    for (int c = 0; c < v.width; ++c) {
      const Vec3 ray = forward + (grid.x0 + grid.step * double(c)) * right;
      columns.x.push_back(ray.x), columns.y.push_back(ray.y), columns.z.push_back(ray.z);
    }
  }
};

// Williams 1978's second pass. With every tile drawn, in one pass over the visible points.
// Otherwise in three: the points located and kept row by row, with the tiles they read; those
// tiles drawn, and only those; then the tests of the points kept.
void ShadowMapMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                            ShadowMask& mask, const Context& ctx) {
  SHADOWKIT_CHECK(map(0).texel_count() > 0);  // built
  const CameraPass pass(scene, surfaces, mask);
  pass_ = camera_passes.fetch_add(1, std::memory_order_relaxed) + 1;
  const auto decide = [&](const TileRow& r) { decide_row(r, mask); };
  if (all_tiles_) {
    each_tile_row(
        surfaces,
        [&](int y, int x0, int x1, TileRow& r, Receivers& receivers) {
          set_up_row(pass, y, x0, x1, r, receivers);
          load_row(r);
        },
        decide);
    return;
  }
  // Every camera pass draws its own tiles, as if built for it: a frame costs the same
  // however many came before it for the same light.
  for (int m = 0; m < map_count(); ++m) {
    map(m).start(map(m).view());
    wanted_[m].assign(map(m).tile_count(), 0);
  }
  kept_columns_ = std::size_t((surfaces.width + kShadeTileW - 1) / kShadeTileW);
  const std::size_t rows = kept_columns_ * std::size_t(surfaces.height);
  if (kept_capacity_ < rows) {
    // Left uninitialized: a row's points are written before they are read.
    kept_ = std::make_unique_for_overwrite<KeptPoint[]>(rows * kShadeTileW);
    kept_capacity_ = rows;
  }
  kept_count_.resize(rows);
  each_tile_row(
      surfaces,
      [&](int y, int x0, int x1, TileRow& r, Receivers& receivers) {
        set_up_row(pass, y, x0, x1, r, receivers);
        keep_row(y, x0, r);
      },
      [](const TileRow&) {});
  draw_maps(scene, ctx);
  each_tile_row(
      surfaces,
      [&](int y, int x0, int /*x1*/, TileRow& r, Receivers&) {
        kept_row(y, x0, r);
        load_row(r);
      },
      decide);
}

// Runs over screen tiles, so that neighbouring visible points, which look up neighbouring
// texels, come one after another; \p fill sets up a tile's row as one batch and \p finish
// takes it one row later, so that a row's texels load while the next row is set up.
template <class Fill, class Finish>
void ShadowMapMethod::each_tile_row(const VisibleSurfaceBuffer& surfaces, Fill&& fill,
                                    Finish&& finish) const {
  static_assert(kShadeTileW <= PointBatch::kSize);
  const int tiles_x = (surfaces.width + kShadeTileW - 1) / kShadeTileW;
  const int tiles_y = (surfaces.height + kShadeTileH - 1) / kShadeTileH;
  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    const int x0 = (tile % tiles_x) * kShadeTileW, y0 = (tile / tiles_x) * kShadeTileH;
    const int x1 = std::min(x0 + kShadeTileW, surfaces.width);
    const int y1 = std::min(y0 + kShadeTileH, surfaces.height);
    // The thread's own, made once (a frame has thousands of tiles): the body starts no
    // parallel work, so no other tile takes them meanwhile.
    thread_local std::array<TileRow, 2> rows;
    thread_local Receivers receivers;
    for (int y = y0; y <= y1; ++y) {
      if (y < y1) fill(y, x0, x1, rows[y % 2], receivers);
      if (y > y0) finish(rows[(y - 1) % 2]);
    }
  });
}

// Sets up the light-facing points of row \p y's columns [x0, x1), a stretch of pixels on one
// face at a time, and locates them; shadows the pixels whose face is turned from the light.
void ShadowMapMethod::set_up_row(const CameraPass& pass, int y, int x0, int x1, TileRow& r,
                                 Receivers& receivers) const {
  const VisibleSurfaceBuffer& surfaces = pass.surfaces;
  const Vec3 row = (pass.grid.y0 - pass.grid.step * double(y)) * pass.up;
  const std::uint32_t* face = surfaces.face.data() + surfaces.index(0, y);
  r.points.size = 0;
  for (int x = surfaces.next_covered(x0, x1, y); x < x1;) {
    const int end = stretch_end(face, x, x1);
    const std::size_t slot = face[x] % Receivers::kSlots;
    Receiver& receiver = receivers.slots[slot];
    if (face[x] != receiver.face || receivers.pass[slot] != pass_) {
      receiver = receiver_of(pass.scene.face_plane(face[x]), pass.eye, face[x]);
      receivers.pass[slot] = pass_;
    }
    const std::size_t i = surfaces.index(x, y);
    if (!receiver.faces_light) {
      std::fill_n(pass.mask.pixels.begin() + std::ptrdiff_t(i), end - x, kMaskShadow);
    } else {
      std::iota(r.pixel.begin() + std::ptrdiff_t(r.points.size),
                r.pixel.begin() + std::ptrdiff_t(r.points.size) + (end - x), i);
      if (light_.type == Light::Type::point) {
        add_points<true>(pass.columns, row, x, end, pass.eye, receiver, r.points);
      } else {
        add_points<false>(pass.columns, row, x, end, pass.eye, receiver, r.points);
      }
    }
    x = surfaces.next_covered(end, x1, y);
  }
  locate(r.points, r.texels);
}

// Starts loading the texels of a located row.
void ShadowMapMethod::load_row(TileRow& r) const {
  for (std::size_t k = 0; k < r.points.size; ++k) {
    r.stored[k] = &stored(r.texels, k);
    __builtin_prefetch(r.stored[k]);
  }
}

void ShadowMapMethod::decide_row(const TileRow& r, ShadowMask& mask) const {
  for (std::size_t k = 0; k < r.points.size; ++k) {
    const bool lit_k = pcf_ == 1 ? r.texels.depth[k] <= *r.stored[k] : lit(r.texels, k);
    mask.pixels[r.pixel[k]] = lit_k ? kMaskLit : kMaskShadow;
  }
}

// KeptPoint::texel's fields: a map, a tile of it and a texel of the tile.
static_assert(kMaxResolution / DepthMap::kTile * (kMaxResolution / DepthMap::kTile) <= 1 << 16 &&
              DepthMap::kTileTexels <= 1 << 12 && CubeMap::kFaces <= 8);

// Where the points of row y of the screen tiles' column starting at x0 are kept.
std::size_t ShadowMapMethod::kept_row_index(int y, int x0) const {
  return std::size_t(y) * kept_columns_ + std::size_t(x0 / kShadeTileW);
}

// Keeps a located row's points, and wants the tiles their tests read: with PCF, those of each
// kernel's corners, which span at most two tiles a side.
void ShadowMapMethod::keep_row(int y, int x0, const TileRow& r) {
  const std::size_t row = kept_row_index(y, x0);
  kept_count_[row] = std::uint8_t(r.points.size);
  KeptPoint* kept = kept_.get() + row * kShadeTileW;
  const auto want = [&](int m, std::size_t tile) {
    std::atomic_ref<std::uint8_t> w(wanted_[m][tile]);
    if (!w.load(std::memory_order_relaxed)) w.store(1, std::memory_order_relaxed);
  };
  const int reach = pcf_ / 2;
  static_assert(kMaxPcf / 2 < DepthMap::kTile);
  std::uint32_t last = ~0u;  // neighbouring points mostly read one tile
  for (std::size_t k = 0; k < r.points.size; ++k) {
    const int m = r.texels.map[k];
    const std::uint32_t tile = std::uint32_t(m) << 16 | std::uint32_t(r.texels.tile[k]);
    kept[k] = {std::uint32_t(r.pixel[k]), tile << 12 | std::uint32_t(r.texels.in_tile[k]),
               r.texels.depth[k]};
    if (tile == last) continue;
    last = tile;
    if (reach == 0) {
      want(m, std::size_t(r.texels.tile[k]));
      continue;
    }
    const DepthMap& face = map(m);
    const int x = r.texels.texel_x[k], y_k = r.texels.texel_y[k];
    const int xa = std::max(x - reach, 0) / DepthMap::kTile,
              xb = std::min(x + reach, face.width() - 1) / DepthMap::kTile;
    const int ya = std::max(y_k - reach, 0) / DepthMap::kTile,
              yb = std::min(y_k + reach, face.height() - 1) / DepthMap::kTile;
    for (const int ty : {ya, yb}) {
      for (const int tx : {xa, xb}) want(m, std::size_t(ty) * face.tiles_x() + tx);
    }
  }
}

// The located row keep_row() kept.
void ShadowMapMethod::kept_row(int y, int x0, TileRow& r) const {
  const std::size_t row = kept_row_index(y, x0);
  const KeptPoint* kept = kept_.get() + row * kShadeTileW;
  r.points.size = kept_count_[row];
  for (std::size_t k = 0; k < r.points.size; ++k) {
    const std::uint32_t texel = kept[k].texel;
    const int m = int(texel >> 28), tile = int(texel >> 12 & 0xffff), in_tile = int(texel & 0xfff);
    r.pixel[k] = kept[k].pixel;
    r.texels.map[k] = m, r.texels.tile[k] = tile, r.texels.in_tile[k] = in_tile;
    r.texels.depth[k] = kept[k].depth;
    if (pcf_ > 1) {
      const int tiles_x = map(m).tiles_x();
      r.texels.texel_x[k] = tile % tiles_x * DepthMap::kTile + in_tile % DepthMap::kTile;
      r.texels.texel_y[k] = tile / tiles_x * DepthMap::kTile + in_tile / DepthMap::kTile;
    }
  }
}

ShadowMapMethod::Receiver ShadowMapMethod::receiver_of(const Plane& plane, Vec3 eye,
                                                       std::uint32_t face) const {
  Receiver receiver;
  receiver.face = face;
  receiver.plane = &plane;
  // Contract condition 1: a surface is two-sided, lit only on the side the light is on.
  receiver.faces_light = faces_light(plane, eye, light_);
  receiver.eye_distance = plane.distance(eye);
  if (receiver.faces_light) receiver.bias = bias_of(plane);
  return receiver;
}

ReceiverBias ShadowMapMethod::bias_of(const Plane& plane) const {
  // The map sampled each surface at texel centres, so a plane's stored depth differs from
  // its depth at p by up to its slope times half a texel, and float storage adds rounding:
  // without a bias surfaces shadow themselves, the self-shadowing problem Williams 1978
  // describes ("acne").
  const Vec3 n = plane.normal;
  if (light_.type == Light::Type::point) {
    const DepthMap& face_map = cube_.face(0);
    const double distance = plane.distance(light_.position);
    return {float(bias_),
            float(slope_bias_ * face_map.texel_size(1)),
            {float(face_map.slope_factor({n.y, n.z, 0}, distance)),
             float(face_map.slope_factor({n.x, n.z, 0}, distance)),
             float(face_map.slope_factor({n.x, n.y, 0}, distance))}};
  }
  const double slope = std::min(kMaxSlope, ortho_.slope_factor(view_normal(ortho_.view(), n), 0));
  return {float(bias_ + slope_bias_ * ortho_.texel_size(0) * slope), 0, {}};
}

// Williams 1978, second pass: the visible point in the light's view (for a cube map, its
// offset from the light, which CubeMap::face_of places).
inline void ShadowMapMethod::add_point(Vec3 p, const ReceiverBias& bias, PointBatch& points) const {
  points.add(light_.type == Light::Type::point ? p - light_.position : ortho_.view().to_view(p),
             bias);
}

// The points of columns [xa, xb) of a row on one receiver, each exactly as add_point() stores
// VisibleSurfaceBuffer::point(): a stretch of a face at a time, in a loop the compiler
// vectorizes, with the receiver's bias the same for all.
template <bool kPointLight>
void ShadowMapMethod::add_points(const ColumnRays& columns, Vec3 row, int xa, int xb, Vec3 eye,
                                 const Receiver& receiver, PointBatch& points) const {
  const Vec3 normal = receiver.plane->normal;
  const double eye_distance = receiver.eye_distance;
  const RasterProjection& view = ortho_.view();
  const std::size_t first = points.size, n = std::size_t(xb - xa);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t c = std::size_t(xa) + k;
    const Vec3 ray = Vec3{columns.x[c], columns.y[c], columns.z[c]} + row;
    const Vec3 p = eye + ray * (-eye_distance / dot(normal, ray));
    const Vec3 q = kPointLight ? p - light_.position : view.to_view(p);
    points.x[first + k] = float(q.x), points.y[first + k] = float(q.y);
    points.z[first + k] = float(q.z);
  }
  const ReceiverBias& bias = receiver.bias;
  std::fill_n(&points.constant[first], n, bias.constant);
  std::fill_n(&points.per_texel[first], n, bias.per_texel);
  std::fill_n(&points.slope_x[first], n, bias.slope_factor[0]);
  std::fill_n(&points.slope_y[first], n, bias.slope_factor[1]);
  std::fill_n(&points.slope_z[first], n, bias.slope_factor[2]);
  points.size += n;
}

void ShadowMapMethod::locate(const PointBatch& points, TexelBatch& texels) const {
  if (light_.type == Light::Type::point) {
    cube_texels(cube_, points, texels);
  } else {
    orthographic_texels(ortho_, points, texels);
  }
}

inline const float& ShadowMapMethod::stored(const TexelBatch& texels, std::size_t k) const {
  return map_of(texels, k).tile_texels(std::size_t(texels.tile[k]))[texels.in_tile[k]];
}

inline const DepthMap& ShadowMapMethod::map_of(const TexelBatch& texels, std::size_t k) const {
  return map(texels.map[k]);
}

inline bool ShadowMapMethod::lit(const TexelBatch& texels, std::size_t k) const {
  const DepthMap& map = map_of(texels, k);
  // Lit if half the tests pass.
  return 2 * map.passing_tests(texels.texel_x[k], texels.texel_y[k], texels.depth[k], pcf_) >=
         pcf_ * pcf_;
}

bool ShadowMapMethod::passes_depth_test(const Plane& plane, Vec3 p) const {
  PointBatch points;
  add_point(p, bias_of(plane), points);
  TexelBatch texels;
  locate(points, texels);
  SHADOWKIT_CHECK(map_of(texels, 0).drawn(texels.texel_x[0], texels.texel_y[0]));
  return lit(texels, 0);
}

std::size_t ShadowMapMethod::memory_bytes() const {
  std::size_t wanted = 0;
  for (const std::vector<std::uint8_t>& w : wanted_) wanted += w.capacity();
  return cube_.memory_bytes() + ortho_.memory_bytes() + wanted +
         kept_capacity_ * kShadeTileW * sizeof(KeptPoint) + kept_count_.capacity();
}

MethodCounters ShadowMapMethod::counters() const {
  double texels = 0, covered = 0, tiles = 0, drawn = 0;
  for (int m = 0; m < map_count(); ++m) {
    texels += double(map(m).texel_count()), covered += double(map(m).covered_texels());
    tiles += double(map(m).tile_count()), drawn += double(map(m).drawn_tiles());
  }
  return {{"map_texels", texels},
          {"covered_texels", covered},
          {"map_tiles", tiles},
          {"drawn_tiles", drawn},
          {"faces", double(map_count())}};
}

std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options) {
  return std::make_unique<ShadowMapMethod>(options);
}

}  // namespace shadowkit::shadowmap
