#include "raytrace_method.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ray_packet.h"
#include "shadowkit/methods/raytrace.h"

namespace shadowkit::raytrace {
namespace {

constexpr int kTile = 16;  // 16x16 pixel tiles, each row in packets of the native width

// About 64 float ulps: float storage of the point and of the triangles each err by less
// than one ulp, and Embree's own intersection test by a few.
constexpr double kOffsetUlps = 64.0 * std::numeric_limits<float>::epsilon();

// One packet of shadow rays for up to kLanes consecutive pixels of a row.
template <int kLanes>
class ShadowPacket {
 public:
  void clear() {
    for (int& v : valid_) v = 0;
    any_ = false;
  }
  void set(int k, Vec3 origin, Vec3 dir, float tfar) {
    rays_.org_x[k] = float(origin.x), rays_.org_y[k] = float(origin.y);
    rays_.org_z[k] = float(origin.z);
    rays_.dir_x[k] = float(dir.x), rays_.dir_y[k] = float(dir.y), rays_.dir_z[k] = float(dir.z);
    rays_.tnear[k] = 0.0f;
    rays_.tfar[k] = tfar;
    rays_.time[k] = 0.0f;
    rays_.mask[k] = 0xFFFFFFFFu;
    rays_.id[k] = unsigned(k);
    rays_.flags[k] = 0;
    valid_[k] = -1;
    any_ = true;
  }
  /// Traces the packet; afterwards blocked(k) tells whether lane k hit anything.
  bool trace(RTCScene scene, RTCIntersectContext* context) {
    if (any_) RayPacket<kLanes>::occluded(valid_, scene, context, &rays_);
    return any_;
  }
  bool valid(int k) const { return valid_[k] != 0; }
  bool blocked(int k) const { return rays_.tfar[k] == -std::numeric_limits<float>::infinity(); }

 private:
  alignas(64) typename RayPacket<kLanes>::Rays rays_;
  alignas(64) int valid_[kLanes];
  bool any_ = false;
};

// An intersection context that knows which triangles' planes pass through the light.
struct ShadowRayContext {
  RTCIntersectContext context;  // first, so that Embree's pointer to it is one to this
  const char* through_light = nullptr;
};

// By the contract a shadow ray's segment meets a plane through the light only at the light,
// or, for a point in that plane, has condition 1 fail before any ray: such a face never
// blocks. In float, a ray that runs to a light in a face's plane at a grazing angle can
// still hit the face just short of the light (speckled shadow on walls under a ceiling
// holding the light), so those hits are dropped.
void skip_faces_through_light(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const ShadowRayContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != 0 && context->through_light[RTCHitN_primID(args->hit, args->N, i)]) {
      args->valid[i] = 0;
    }
  }
}

}  // namespace

double face_offset(const Mesh& mesh, std::size_t face, Vec3 origin) {
  double magnitude = 0, deviation = 0;
  for (std::uint32_t k = 0; k < mesh.face_size(face); ++k) {
    const Vec3 v = mesh.vertices[mesh.face_vertex(face, k)];
    magnitude = std::max(magnitude, max_abs_component(v - origin));
    deviation = std::max(deviation, std::abs(mesh.planes[face].distance(v)));
  }
  return kOffsetUlps * magnitude + 2 * deviation;
}

double shadow_ray_offset(Vec3 p, double face_part) {
  return std::max(
      {kOffsetUlps * max_abs_component(p), face_part, double(std::numeric_limits<float>::min())});
}

RaytraceMethod::RaytraceMethod(const MethodOptions& options) {
  options.expect_only("raytrace", {});
}

void RaytraceMethod::prepare(const Scene& scene, const Context& /*ctx*/) {
  embree_ = std::make_unique<EmbreeScene>(scene);
  face_offset_.resize(scene.face_count());
  for (const SceneObject& object : scene.objects) {
    for (std::size_t f = 0; f < object.mesh.face_count(); ++f) {
      face_offset_[object.first_face + f] = float(face_offset(object.mesh, f, embree_->origin()));
    }
  }
}

void RaytraceMethod::build(const Scene& scene, std::size_t light, const Context& /*ctx*/) {
  light_ = scene.lights.at(light);
  const Vec3 eye = scene.camera.position;
  lit_side_offset_.resize(scene.face_count());
  for (std::uint32_t f = 0; f < scene.face_count(); ++f) {
    const Plane& plane = scene.face_plane(f);
    const float side = plane.distance(eye) > 0 ? 1.0f : -1.0f;
    // Never 0 for a lit face, even if its offset underflows float.
    const float offset = std::max(face_offset_[f], std::numeric_limits<float>::min());
    lit_side_offset_[f] = faces_light(plane, eye, light_) ? side * offset : 0.0f;
  }
  const std::vector<std::uint32_t>& triangle_face = scene.triangles().triangle_face;
  through_light_.resize(triangle_face.size());
  any_through_light_ = false;
  for (std::size_t t = 0; t < triangle_face.size(); ++t) {
    through_light_[t] = light_side(scene.face_plane(triangle_face[t]), light_) == 0;
    any_through_light_ = any_through_light_ || through_light_[t];
  }
}

void RaytraceMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                           ShadowMask& mask, const Context& /*ctx*/) {
  with_packet_width(embree_->packet_width(), [&]<int kLanes>(RayPacket<kLanes>) {
    shade_in_packets<kLanes>(scene, surfaces, mask);
  });
}

template <int kLanes>
void RaytraceMethod::shade_in_packets(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                                      ShadowMask& mask) {
  const bool point_light = light_.type == Light::Type::point;
  const Vec3 origin = embree_->origin(), light_position = light_.position - origin;
  // A point light sits at t = 1 on an unnormalised ray; stop just short of it.
  const float tfar = point_light ? 1.0f - 1e-6f : std::numeric_limits<float>::infinity();
  const int tiles_x = (surfaces.width + kTile - 1) / kTile;
  const int tiles_y = (surfaces.height + kTile - 1) / kTile;
  tbb::combinable<std::size_t> ray_count;

  // Returns the number of shadow rays cast.
  auto shade_row = [&](ShadowPacket<kLanes>& packet, ShadowRayContext& context, int y, int x0,
                       int lanes) -> std::size_t {
    packet.clear();
    for (int k = 0; k < lanes; ++k) {
      const std::size_t i = surfaces.index(x0 + k, y);
      if (!surfaces.covered(i)) continue;
      const float signed_offset = lit_side_offset_[surfaces.face[i]];
      if (signed_offset == 0.0f) {  // contract condition 1 fails
        mask.pixels[i] = kMaskShadow;
        continue;
      }
      const Vec3 p = surfaces.point(i) - origin;
      const double offset =
          std::copysign(shadow_ray_offset(p, std::abs(signed_offset)), signed_offset);
      const Vec3 o = p + scene.face_plane(surfaces.face[i]).normal * offset;
      packet.set(k, o, point_light ? light_position - o : -light_.direction, tfar);
    }
    if (!packet.trace(embree_->handle(), &context.context)) return 0;
    std::size_t rays = 0;
    for (int k = 0; k < lanes; ++k) {
      if (!packet.valid(k)) continue;
      ++rays;
      mask.pixels[surfaces.index(x0 + k, y)] = packet.blocked(k) ? kMaskShadow : kMaskLit;
    }
    return rays;
  };

  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    const int x0 = (tile % tiles_x) * kTile, y0 = (tile / tiles_x) * kTile;
    ShadowRayContext context;
    rtcInitIntersectContext(&context.context);
    context.context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    if (any_through_light_) {
      context.context.filter = skip_faces_through_light;
      context.through_light = through_light_.data();
    }
    ShadowPacket<kLanes> packet;
    const int x_end = std::min(x0 + kTile, surfaces.width);
    std::size_t rays = 0;
    for (int y = y0; y < std::min(y0 + kTile, surfaces.height); ++y) {
      for (int x = x0; x < x_end; x += kLanes) {
        rays += shade_row(packet, context, y, x, std::min(kLanes, x_end - x));
      }
    }
    ray_count.local() += rays;
  });
  rays_ = double(ray_count.combine(std::plus<>()));
}

std::size_t RaytraceMethod::memory_bytes() const {
  return (embree_ ? embree_->memory_bytes() : 0) +
         (face_offset_.size() + lit_side_offset_.size()) * sizeof(float);
}

MethodCounters RaytraceMethod::counters() const {
  return {{"shadow_rays", rays_}};
}

std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options) {
  return std::make_unique<RaytraceMethod>(options);
}

}  // namespace shadowkit::raytrace
