#include "shadow_map_method.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
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

// What the camera pass knows of the receiving face of the last pixel, kept while a run of
// pixels stays on one face and one map.
struct ShadowMapMethod::Receiver {
  std::uint32_t face = kNoFace;
  const Plane* plane = nullptr;
  bool faces_light = false;
  double eye_distance = 0;
  const DepthMap* map = nullptr;
  double slope_factor = 0;  ///< DepthMap::slope_factor of the plane in the map's view
};

// A point's depth test, ready to be made: where the point falls in which map, and its bias.
struct ShadowMapMethod::DepthTest {
  const DepthMap* map;
  DepthMap::Sample s;
  double bias;
};

void ShadowMapMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                            ShadowMask& mask, const Context& /*ctx*/) {
  const bool point_light = light_.type == Light::Type::point;
  SHADOWKIT_CHECK((point_light ? cube_.texel_count() : ortho_.texel_count()) > 0);  // built
  // The contract's pixel rays as VisibleSurfaceBuffer::ray() makes them, (forward + x right)
  // + y up, with the column's part computed once per column and the row's once per row.
  const Camera& camera = scene.camera;
  const Vec3 forward = camera.forward(), right = camera.right(), up = camera.true_up();
  const Camera::PixelGrid grid = camera.pixel_grid();
  std::vector<Vec3> column(std::size_t(surfaces.width));
  for (int c = 0; c < surfaces.width; ++c) {
    column[c] = forward + (grid.x0 + grid.step * double(c)) * right;
  }
  // Screen tiles, so that neighbouring visible points, which look up neighbouring texels, come
  // one after another.
  const int tiles_x = (surfaces.width + kShadeTileW - 1) / kShadeTileW;
  const int tiles_y = (surfaces.height + kShadeTileH - 1) / kShadeTileH;
  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    const int x0 = (tile % tiles_x) * kShadeTileW, y0 = (tile / tiles_x) * kShadeTileH;
    const int x1 = std::min(x0 + kShadeTileW, surfaces.width);
    const int y1 = std::min(y0 + kShadeTileH, surfaces.height);
    Receiver receiver;
    // A row's one-texel comparisons wait until the row is set up, their texels prefetched: a
    // texel not in cache then no longer stalls the setup of the points after it.
    struct Comparison {
      std::size_t pixel;
      const float* stored;
      double z, bias;
    };
    std::array<Comparison, kShadeTileW> pending;
    for (int y = y0; y < y1; ++y) {
      const Vec3 row = (grid.y0 - grid.step * double(y)) * up;
      std::size_t waiting = 0;
      for (int x = x0; x < x1; ++x) {
        const std::size_t i = surfaces.index(x, y);
        if (!surfaces.covered(i)) continue;
        const Vec3 ray = column[x] + row;
        const std::optional<DepthTest> test = depth_test_at(scene, surfaces.face[i], ray, receiver);
        if (test && pcf_ == 1) {
          const float* stored = &test->map->stored(test->s);
          __builtin_prefetch(stored);
          pending[waiting++] = {i, stored, test->s.v.z, test->bias};
        } else {
          mask.pixels[i] = test && passes(*test) ? kMaskLit : kMaskShadow;
        }
      }
      for (std::size_t k = 0; k < waiting; ++k) {
        const Comparison& c = pending[k];
        mask.pixels[c.pixel] = DepthMap::passes(c.z, *c.stored, c.bias) ? kMaskLit : kMaskShadow;
      }
    }
  });
}

// The per-pixel path is declared inline, down to the depth test, so that the compiler folds it
// into the camera pass's loop: without the calls (and their results passed in memory) it
// overlaps the divisions and loads of neighbouring pixels.
inline std::optional<ShadowMapMethod::DepthTest> ShadowMapMethod::depth_test_at(
    const Scene& scene, std::uint32_t face, Vec3 ray, Receiver& receiver) const {
  const Vec3 eye = scene.camera.position;
  if (face != receiver.face) {
    receiver = Receiver{};
    receiver.face = face;
    receiver.plane = &scene.face_plane(face);
    // Contract condition 1: a surface is two-sided, lit only on the side the light is on.
    receiver.faces_light = faces_light(*receiver.plane, eye, light_);
    receiver.eye_distance = receiver.plane->distance(eye);
  }
  if (!receiver.faces_light) return std::nullopt;
  // The visible point as VisibleSurfaceBuffer::point() computes it.
  const Vec3 p = eye + ray * (-receiver.eye_distance / dot(receiver.plane->normal, ray));
  Vec3 v;
  const DepthMap& map = locate(p, v);
  if (&map != receiver.map) {
    receiver.map = &map;
    receiver.slope_factor = slope_factor(map, *receiver.plane);
  }
  return depth_test(map, receiver.slope_factor, v);
}

bool ShadowMapMethod::passes_depth_test(const Plane& plane, Vec3 p) const {
  Vec3 v;
  const DepthMap& map = locate(p, v);
  return passes(depth_test(map, slope_factor(map, plane), v));
}

double ShadowMapMethod::slope_factor(const DepthMap& map, const Plane& plane) {
  return map.slope_factor(view_normal(map.view(), plane.normal), plane.distance(map.view().eye));
}

inline const DepthMap& ShadowMapMethod::locate(Vec3 p, Vec3& v) const {
  // Williams 1978, second pass: transform the visible point into the light's view.
  if (light_.type == Light::Type::point) return cube_.locate(p, v);
  v = ortho_.view().to_view(p);
  return ortho_;
}

inline ShadowMapMethod::DepthTest ShadowMapMethod::depth_test(const DepthMap& map,
                                                              double slope_factor, Vec3 v) const {
  const DepthMap::Sample s = map.sample(v);
  // The map sampled each surface at texel centres, so a plane's stored depth differs from
  // its depth at p by up to its slope times half a texel, and float storage adds rounding:
  // without a bias surfaces shadow themselves, the self-shadowing problem Williams 1978
  // describes ("acne").
  const double bias =
      bias_ + slope_bias_ * map.texel_size(s.v.z) * map.depth_slope(slope_factor, s.v.z);
  return {&map, s, bias};
}

bool ShadowMapMethod::passes(const DepthTest& test) const {
  // Lit if half the tests pass.
  return 2 * test.map->passing_tests(test.s, test.bias, pcf_) >= pcf_ * pcf_;
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
