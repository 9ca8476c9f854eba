#include "shadow_map_method.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>
#include <string>

#include "shadowkit/core/error.h"
#include "shadowkit/methods/shadowmap.h"

namespace shadowkit::shadowmap {
namespace {

constexpr double kDefaultBiasPerDiagonal = 1e-3;
constexpr int kMinResolution = 16, kMaxResolution = 16384;
constexpr int kMaxPcf = 31;
// The camera pass's screen tiles: wide, so that the hardware prefetcher follows each row.
constexpr int kShadeTileW = 128, kShadeTileH = 8;

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
  options.expect_only("shadowmap", {"resolution", "bias", "slope_bias", "pcf"});
  resolution_ = integer_option(options, "resolution", 2048, kMinResolution, kMaxResolution);
  const double bias = options.number("bias", std::nan(""));
  if (bias < 0) bad_option("bias", "expected a depth bias >= 0 in world units");
  if (!std::isnan(bias)) bias_option_ = bias;
  slope_bias_ = options.number("slope_bias", 1.0);
  if (slope_bias_ < 0) bad_option("slope_bias", "expected a slope bias factor >= 0");
  pcf_ = integer_option(options, "pcf", 1, 1, kMaxPcf);
  if (pcf_ % 2 == 0) bad_option("pcf", "expected an odd kernel width (1 = off, 3, 5, ...)");
}

void ShadowMapMethod::build(const Scene& scene, std::size_t light, const Context& ctx) {
  light_ = scene.lights.at(light);
  // Default bias: relative to the scene's size, so that it means the same for any units.
  bias_ = bias_option_.value_or(kDefaultBiasPerDiagonal * scene.bounds().diagonal());
  // Only the current light's map is kept; its storage is reused from the last build of the
  // same kind of light.
  if (light_.type == Light::Type::point) {
    ortho_ = {};
    cube_.render(scene, light_.position, resolution_, ctx);
  } else {
    cube_ = {};
    ortho_.render(scene, directional_light_view(scene.bounds(), light_.direction, resolution_),
                  ctx);
  }
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

void ShadowMapMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                            ShadowMask& mask, const Context& /*ctx*/) {
  const bool point_light = light_.type == Light::Type::point;
  SHADOWKIT_CHECK((point_light ? cube_.texel_count() : ortho_.texel_count()) > 0);  // built
  // The contract's pixel rays as VisibleSurfaceBuffer::ray() makes them, (forward + x right)
  // + y up, with the column's part computed once per column and the row's once per row.
  const Camera& camera = scene.camera;
  const Vec3 eye = camera.position;
  const Vec3 forward = camera.forward(), right = camera.right(), up = camera.true_up();
  const Camera::PixelGrid grid = camera.pixel_grid();
  ColumnRays columns;
  for (int c = 0; c < surfaces.width; ++c) {
    const Vec3 ray = forward + (grid.x0 + grid.step * double(c)) * right;
    columns.x.push_back(ray.x), columns.y.push_back(ray.y), columns.z.push_back(ray.z);
  }
  // Screen tiles, so that neighbouring visible points, which look up neighbouring texels, come
  // one after another; a tile's row is one batch.
  static_assert(kShadeTileW <= PointBatch::kSize);
  const int tiles_x = (surfaces.width + kShadeTileW - 1) / kShadeTileW;
  const int tiles_y = (surfaces.height + kShadeTileH - 1) / kShadeTileH;
  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    const int x0 = (tile % tiles_x) * kShadeTileW, y0 = (tile / tiles_x) * kShadeTileH;
    const int x1 = std::min(x0 + kShadeTileW, surfaces.width);
    const int y1 = std::min(y0 + kShadeTileH, surfaces.height);
    Receiver receiver;
    // Sets up row y's points, a stretch of pixels on one face at a time, and starts loading
    // their texels.
    const auto set_up = [&](int y, TileRow& r) {
      const Vec3 row = (grid.y0 - grid.step * double(y)) * up;
      const std::uint32_t* face = surfaces.face.data() + surfaces.index(0, y);
      r.points.size = 0;
      for (int x = surfaces.next_covered(x0, x1, y); x < x1;) {
        const int end = stretch_end(face, x, x1);
        if (face[x] != receiver.face)
          receiver = receiver_of(scene.face_plane(face[x]), eye, face[x]);
        const std::size_t i = surfaces.index(x, y);
        if (!receiver.faces_light) {
          std::fill_n(mask.pixels.begin() + std::ptrdiff_t(i), end - x, kMaskShadow);
        } else {
          std::iota(r.pixel.begin() + std::ptrdiff_t(r.points.size),
                    r.pixel.begin() + std::ptrdiff_t(r.points.size) + (end - x), i);
          if (point_light) {
            add_points<true>(columns, row, x, end, eye, receiver, r.points);
          } else {
            add_points<false>(columns, row, x, end, eye, receiver, r.points);
          }
        }
        x = surfaces.next_covered(end, x1, y);
      }
      locate(r.points, r.texels);
      for (std::size_t k = 0; k < r.points.size; ++k) {
        r.stored[k] = &stored(r.texels, k);
        __builtin_prefetch(r.stored[k]);
      }
    };
    // Rows in a pipeline: a row's texels load while the next row is set up. The thread's own,
    // made once (a frame has thousands of tiles): the body starts no parallel work, so no
    // other tile takes them meanwhile.
    thread_local std::array<TileRow, 2> rows;
    for (int y = y0; y <= y1; ++y) {
      if (y < y1) set_up(y, rows[y % 2]);
      if (y == y0) continue;
      const TileRow& r = rows[(y - 1) % 2];
      for (std::size_t k = 0; k < r.points.size; ++k) {
        const bool lit_k = pcf_ == 1 ? r.texels.depth[k] <= *r.stored[k] : lit(r.texels, k);
        mask.pixels[r.pixel[k]] = lit_k ? kMaskLit : kMaskShadow;
      }
    }
  });
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
  return light_.type == Light::Type::point ? cube_.face(texels.map[k]) : ortho_;
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
  return lit(texels, 0);
}

std::size_t ShadowMapMethod::memory_bytes() const {
  return cube_.memory_bytes() + ortho_.memory_bytes();
}

MethodCounters ShadowMapMethod::counters() const {
  const bool point_light = light_.type == Light::Type::point;
  return {
      {"map_texels", double(point_light ? cube_.texel_count() : ortho_.texel_count())},
      {"covered_texels", double(point_light ? cube_.covered_texels() : ortho_.covered_texels())},
      {"faces", point_light ? 6.0 : 1.0}};
}

std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options) {
  return std::make_unique<ShadowMapMethod>(options);
}

}  // namespace shadowkit::shadowmap
