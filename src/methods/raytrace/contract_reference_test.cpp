// An independent Embree ray caster written from scene-format.md alone (primary rays, nearest
// hit, Embree's own geometric normal, single shadow rays) checks the raytrace method and the
// scan converter together on every example scene and the built-in scenes.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "raytrace_method.h"
#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit::raytrace {
namespace {

struct ReferenceImage {
  ShadowMask mask;
  std::vector<std::uint32_t> object;
};

class ContractCaster {
 public:
  explicit ContractCaster(const Scene& scene) : scene_(scene), device_(rtcNewDevice(nullptr)) {
    rtc_ = rtcNewScene(device_);
    const TriangleList& t = scene.triangles();
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, t.positions.size()));
    for (std::size_t i = 0; i < t.positions.size(); ++i) {
      v[3 * i] = float(t.positions[i].x), v[3 * i + 1] = float(t.positions[i].y);
      v[3 * i + 2] = float(t.positions[i].z);
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, t.triangles.size()));
    for (std::size_t i = 0; i < t.triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = t.triangles[i][k];
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(rtc_, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(rtc_);
  }
  ~ContractCaster() {
    rtcReleaseScene(rtc_);
    rtcReleaseDevice(device_);
  }

  ReferenceImage render(std::size_t light_index) const {
    const Camera& c = scene_.camera;
    const Light& light = scene_.lights[light_index];
    ReferenceImage out{ShadowMask(c.width, c.height, kMaskBackground),
                       std::vector<std::uint32_t>(std::size_t(c.width) * c.height, kNoFace)};
    // The contract's camera frame and pixel rays, written out again on purpose.
    const Vec3 f = normalize(c.look_at - c.position), r = normalize(cross(f, c.up));
    const Vec3 u = cross(r, f);
    const double t = std::tan(c.fov_y_deg * std::numbers::pi / 360.0);
    const double eps = 1e-5 * scene_.bounds().diagonal();
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (int w = 0; w < c.height; ++w) {
      for (int col = 0; col < c.width; ++col) {
        const double x = (2 * (col + 0.5) / c.width - 1) * t * c.width / c.height;
        const double y = (1 - 2 * (w + 0.5) / c.height) * t;
        const Vec3 d = normalize(f + x * r + y * u);
        RTCRayHit hit{};
        set_ray(hit.ray, c.position, d, INFINITY);
        hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(rtc_, &ctx, &hit);
        if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        const std::size_t i = std::size_t(w) * c.width + col;
        const std::uint32_t face = scene_.triangles().triangle_face[hit.hit.primID];
        out.object[i] = scene_.object_of_face(face);
        const Vec3 n = normalize(Vec3{hit.hit.Ng_x, hit.hit.Ng_y, hit.hit.Ng_z});
        const Vec3 p = c.position + d * double(hit.ray.tfar);
        const Vec3 to_light =
            light.type == Light::Type::point ? light.position - p : -light.direction;
        const double eye_side = dot(n, c.position - p), light_side = dot(n, to_light);
        if (eye_side * light_side <= 0) {
          out.mask.pixels[i] = kMaskShadow;
          continue;
        }
        const Vec3 o = p + n * (eye_side > 0 ? eps : -eps);
        const double dist =
            light.type == Light::Type::point ? length(light.position - o) : INFINITY;
        RTCRay shadow{};
        set_ray(shadow, o,
                light.type == Light::Type::point ? normalize(light.position - o) : -light.direction,
                float(dist));
        rtcOccluded1(rtc_, &ctx, &shadow);
        out.mask.pixels[i] = shadow.tfar < 0 ? kMaskShadow : kMaskLit;
      }
    }
    return out;
  }

 private:
  static void set_ray(RTCRay& ray, Vec3 o, Vec3 d, float tfar) {
    ray.org_x = float(o.x), ray.org_y = float(o.y), ray.org_z = float(o.z);
    ray.dir_x = float(d.x), ray.dir_y = float(d.y), ray.dir_z = float(d.z);
    ray.tnear = 0, ray.tfar = tfar, ray.mask = ~0u, ray.flags = 0;
  }

  const Scene& scene_;
  RTCDevice device_;
  RTCScene rtc_;
};

void expect_agreement(const Scene& scene) {
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  RaytraceMethod method({});
  method.prepare(scene, {});
  const ContractCaster reference(scene);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    method.build(scene, l, {});
    ShadowMask mask(vsb.width, vsb.height, kMaskBackground);
    method.shade(scene, vsb, mask, {});
    const ReferenceImage ref = reference.render(l);
    const MaskComparison c = compare_masks(ref.mask, mask, ref.object);
    EXPECT_LT(c.interior_pct(), 0.01) << scene.name << " light " << l;
    EXPECT_GT(c.interior_pixels, c.surface_pixels / 2) << scene.name;
    std::printf("%-24s L%zu raw %.4f%% interior %.4f%% (%zu of %zu interior pixels differ)\n",
                scene.name.c_str(), l, c.raw_pct(), c.interior_pct(), c.interior_mismatched,
                c.interior_pixels);
  }
}

TEST(ContractReference, AgreesOnEveryExampleScene) {
  const Context quiet{0, [](const std::string&) {}};
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SHADOWKIT_SOURCE_DIR "/examples")) {
    if (entry.path().extension() != ".json") continue;
    expect_agreement(load_scene_file(entry.path(), quiet));
    ++scenes;
  }
  EXPECT_GE(scenes, 5);
}

TEST(ContractReference, AgreesOnTheBuiltInScenes) {
  const Context quiet{0, [](const std::string&) {}};
  for (const char* name : {"cubes:125", "tetra:3", "room", "table", "three-lights", "square"}) {
    Scene scene = load_scene(name, quiet);
    scene.camera.width = 480;
    scene.camera.height = 270;
    expect_agreement(scene);
  }
}

}  // namespace
}  // namespace shadowkit::raytrace
