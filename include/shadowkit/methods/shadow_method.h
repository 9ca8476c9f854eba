#pragma once
/// \brief The one interface every shadow method implements, and what they share.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/image.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// Mask values of scene-format.md.
inline constexpr std::uint8_t kMaskBackground = 0;
inline constexpr std::uint8_t kMaskShadow = 128;
inline constexpr std::uint8_t kMaskLit = 255;

/// \brief One light's shadow mask: kMaskBackground, kMaskShadow or kMaskLit per pixel.
using ShadowMask = Image<std::uint8_t>;

/// \brief Named numbers a method reports about its last build/shade (edges, nodes, calls).
using MethodCounters = std::vector<std::pair<std::string, double>>;

/// \brief Method settings from the command line ("--set shadowmap.resolution=4096"),
/// keyed without the method prefix. Methods reject keys they do not know.
class MethodOptions {
 public:
  MethodOptions() = default;
  MethodOptions(std::string method, std::map<std::string, std::string> values)
      : method_(std::move(method)), values_(std::move(values)) {}
  /// Value of \p key parsed as a number, or \p fallback; InputError if it is not a number.
  double number(const std::string& key, double fallback) const;
  /// Value of \p key, or \p fallback.
  std::string text(const std::string& key, const std::string& fallback) const;
  /// Every setting given, by key.
  const std::map<std::string, std::string>& values() const { return values_; }
  /// Throws InputError naming the first key not in \p known.
  void expect_only(std::string_view method, const std::vector<std::string>& known) const;

 private:
  std::string method_;
  std::map<std::string, std::string> values_;
};

/// \brief A shadow algorithm. Data flows one way: prepare (once per scene) -> build (once
/// per light) -> shade (camera pass over the visible-surface buffer).
class ShadowMethod {
 public:
  virtual ~ShadowMethod() = default;
  virtual std::string_view name() const = 0;
  /// Light-independent structures, built once per scene (BVH, scene BSP tree, ...).
  virtual void prepare(const Scene& /*scene*/, const Context& /*ctx*/) {}
  /// False when prepare() used the camera or the lights, so that a new view (SceneView)
  /// needs prepare() again.
  virtual bool prepared_for_every_view() const { return true; }
  /// Per-light structures (shadow map, shadow polygons, SVBSP tree, angular table).
  virtual void build(const Scene& scene, std::size_t light, const Context& ctx) = 0;
  /// Writes kMaskLit or kMaskShadow at every covered pixel of \p surfaces for the light of
  /// the last build(); \p mask arrives sized and cleared to kMaskBackground.
  virtual void shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                     const Context& ctx) = 0;
  /// Bytes held by the structures of prepare() and the last build().
  virtual std::size_t memory_bytes() const = 0;
  /// Counters of the last build()/shade().
  virtual MethodCounters counters() const { return {}; }
};

/// Within this many ulps of the magnitudes involved, a light lies in a face's plane
/// (light_side). Hazard: the light and a face's corners are moved to working coordinates,
/// each coordinate rounded, and the face's plane is computed from its corners, its point as
/// their average and its normal as a sum of products; so a light given exactly in the face's
/// plane in the scene file comes out a few ulps off it, on either side: the face would then
/// face the light, or turn from it, by rounding alone.
inline constexpr double kInPlaneUlps = 64;

/// Which side of \p plane the light is on: the signed distance of a point light, or
/// -dot(n, direction) for a directional one; 0 when the light lies in the plane, to within
/// kInPlaneUlps of the rounding of that distance (of the light's coordinates and the plane's
/// offset; of the unit vectors for a directional light).
inline double light_side(const Plane& plane, const Light& light) {
  const bool point = light.type == Light::Type::point;
  const double side = point ? plane.distance(light.position) : -dot(plane.normal, light.direction);
  const double magnitude = point ? max_abs_component(light.position) + std::abs(plane.d) : 1.0;
  const double rounding = kInPlaneUlps * std::numeric_limits<double>::epsilon() * magnitude;
  return std::abs(side) <= rounding ? 0.0 : side;
}

/// Condition 1 of the contract: the camera at \p eye and the light are strictly on the same
/// side of a face's \p plane. A light in the plane, or behind it, shadows the face.
inline bool faces_light(const Plane& plane, Vec3 eye, const Light& light) {
  const double eye_side = plane.distance(eye);
  const double light_part = light_side(plane, light);
  return (eye_side > 0 && light_part > 0) || (eye_side < 0 && light_part < 0);
}

/// Runs \p classify(index) -> bool lit for every covered pixel, rows in parallel, and
/// writes the mask. The shared camera pass of per-pixel methods.
void shade_each_pixel(const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                      const std::function<bool(std::size_t)>& classify);

}  // namespace shadowkit
