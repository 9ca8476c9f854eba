// Tests of the shadowmap method against analytic shadows. The scenes are built by hand (the
// "square" scene: a ground quad y = 0 over [-10, 10]^2 and an open 2x2 square at height 1), so
// that these tests do not depend on the generators.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "cube_map.h"
#include "shadow_map_method.h"
#include "shadowkit/core/error.h"
#include "shadowkit/raster/scan_converter.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/mesh.h"
#include "texel_batch.h"

namespace shadowkit::shadowmap {
namespace {

using shadowmap::CubeMap;
using shadowmap::PointBatch;
using shadowmap::TexelBatch;

const Context& quiet() {
  static const Context ctx = [] {
    Context c;
    c.warn = [](const std::string&) {};
    return c;
  }();
  return ctx;
}

void add_object(Scene& scene, const std::string& name, const std::vector<Vec3>& positions,
                const std::vector<std::vector<std::uint32_t>>& faces) {
  PolygonSoup soup;
  soup.positions = positions;
  for (const auto& f : faces) soup.add_face(f);
  scene.objects.push_back({name, Mesh::build(soup, name, quiet()), 0, {}});
}

Camera small_camera(Vec3 position, Vec3 look_at, double fov = 60) {
  Camera c;
  c.position = position;
  c.look_at = look_at;
  c.fov_y_deg = fov;
  c.width = 200;
  c.height = 150;
  return c;
}

// Object 0: ground y = 0 over [-10, 10]^2; object 1 (optional): the square y = 1 over [-1, 1]^2.
Scene square_scene(const Light& light, const Camera& camera, bool with_square = true) {
  Scene scene;
  scene.name = "square";
  scene.camera = camera;
  scene.lights = {light};
  add_object(scene, "ground", {{-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10}},
             {{0, 1, 2, 3}});
  if (with_square) {
    add_object(scene, "square", {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}}, {{0, 1, 2, 3}});
  }
  scene.finalize();
  return scene;
}

struct Rendered {
  VisibleSurfaceBuffer surfaces;
  ShadowMask mask;
};

Rendered render(const Scene& scene, ShadowMapMethod& method) {
  Rendered r;
  r.surfaces = render_visible_surfaces(scene, quiet());
  r.mask = ShadowMask(r.surfaces.width, r.surfaces.height, kMaskBackground);
  method.prepare(scene, quiet());
  method.build(scene, 0, quiet());
  method.shade(scene, r.surfaces, r.mask, quiet());
  return r;
}

ShadowMapMethod make(std::map<std::string, std::string> options) {
  return ShadowMapMethod(MethodOptions("shadowmap", std::move(options)));
}

// Compares the ground's mask with an analytic square shadow [cx +- h] x [cz +- h]: pixels
// deeper than `margin` inside must be shadowed, farther than `margin` outside lit.
struct ShadowCheck {
  int inside = 0, outside = 0;  // pixels tested on either side
  int wrong_inside = 0, wrong_outside = 0;
  int band_errors = 0;  // disagreements with the exact shadow within the margin
};

ShadowCheck check_ground(const Rendered& r, double cx, double cz, double h, double margin) {
  ShadowCheck c;
  for (std::size_t i = 0; i < r.surfaces.face.size(); ++i) {
    if (!r.surfaces.covered(i) || r.surfaces.object(i) != 0) continue;
    const Vec3 p = r.surfaces.point(i);
    const double depth_in = h - std::max(std::abs(p.x - cx), std::abs(p.z - cz));
    const bool lit = r.mask.pixels[i] == kMaskLit;
    if (depth_in > margin) {
      ++c.inside;
      c.wrong_inside += lit;
    } else if (depth_in < -margin) {
      ++c.outside;
      c.wrong_outside += !lit;
    } else {
      c.band_errors += (depth_in > 0) == lit;
    }
  }
  return c;
}

int count_mask(const Rendered& r, std::uint32_t object, std::uint8_t value) {
  int n = 0;
  for (std::size_t i = 0; i < r.mask.pixels.size(); ++i) {
    n += r.surfaces.covered(i) && r.surfaces.object(i) == object && r.mask.pixels[i] == value;
  }
  return n;
}

// Low enough that the square hides none of its shadow.
const Camera kTopCamera = small_camera({0, 2.5, 5}, {0, 0, 0}, 45);

// (1) Point light at (0, 4, 0): the square's shadow is the square scaled by 4/3. A texel of the
// -Y cube face is 2 * 4 / resolution wide on the ground (view depth 4).
TEST(ShadowMap, PointLightShadowMatchesAnalyticSquare) {
  const Scene scene = square_scene(Light::point({0, 4, 0}), kTopCamera);
  int errors_at_16 = 0, errors_at_512 = 0;
  for (int resolution : {16, 64, 512}) {
    SCOPED_TRACE(resolution);
    ShadowMapMethod method = make({{"resolution", std::to_string(resolution)}});
    const Rendered r = render(scene, method);
    const double footprint = 2.0 * 4.0 / resolution;
    const ShadowCheck c = check_ground(r, 0, 0, 4.0 / 3.0, 2 * footprint);
    EXPECT_GT(c.inside, 100);
    EXPECT_GT(c.outside, 1000);
    EXPECT_EQ(c.wrong_inside, 0);
    EXPECT_EQ(c.wrong_outside, 0);
    // The square's top faces the light and nothing is above it.
    EXPECT_GT(count_mask(r, 1, kMaskLit), 100);
    EXPECT_EQ(count_mask(r, 1, kMaskShadow), 0);
    if (resolution == 16) errors_at_16 = c.band_errors;
    if (resolution == 512) errors_at_512 = c.band_errors;
  }
  // Aliasing: a coarse map gets the edge visibly wrong, a fine one much less so.
  EXPECT_GT(errors_at_16, 0);
  EXPECT_LT(errors_at_512, errors_at_16);
}

// (2) Directional light: the shadow is the square translated along the light direction down to
// y = 0. An orthographic texel stretches by 1 / |direction.y| on the ground.
TEST(ShadowMap, DirectionalLightShadowMatchesAnalyticSquare) {
  const Vec3 d = normalize(Vec3{0.3, -1, 0.2});
  const Scene scene = square_scene(Light::directional(d), kTopCamera);
  for (int resolution : {64, 512}) {
    SCOPED_TRACE(resolution);
    ShadowMapMethod method = make({{"resolution", std::to_string(resolution)}});
    const Rendered r = render(scene, method);
    const double footprint = method.directional_map().texel_size(0) / std::abs(d.y);
    const ShadowCheck c = check_ground(r, d.x / -d.y, d.z / -d.y, 1.0, 2 * footprint);
    EXPECT_GT(c.inside, 100);
    EXPECT_GT(c.outside, 1000);
    EXPECT_EQ(c.wrong_inside, 0);
    EXPECT_EQ(c.wrong_outside, 0);
    EXPECT_EQ(count_mask(r, 1, kMaskShadow), 0);
  }
}

// PCF keeps the shadow within the kernel's reach of the exact edge.
TEST(ShadowMap, PercentageCloserFilteringKeepsShadowShape) {
  const Scene scene = square_scene(Light::point({0, 4, 0}), kTopCamera);
  for (int pcf : {3, 5}) {
    SCOPED_TRACE(pcf);
    ShadowMapMethod method = make({{"resolution", "256"}, {"pcf", std::to_string(pcf)}});
    const Rendered r = render(scene, method);
    const double footprint = 2.0 * 4.0 / 256;
    const ShadowCheck c = check_ground(r, 0, 0, 4.0 / 3.0, (2 + pcf / 2) * footprint);
    EXPECT_GT(c.inside, 100);
    EXPECT_EQ(c.wrong_inside, 0);
    EXPECT_EQ(c.wrong_outside, 0);
    EXPECT_EQ(count_mask(r, 1, kMaskShadow), 0);
  }
}

// (3) Every direction, including cube edges and corners, maps onto its face's raster.
TEST(ShadowMap, CubeFaceSelectionCoversAllDirections) {
  EXPECT_EQ(CubeMap::face_of({1, 0, 0}), 0);
  EXPECT_EQ(CubeMap::face_of({-1, 0, 0}), 1);
  EXPECT_EQ(CubeMap::face_of({0, 1, 0}), 2);
  EXPECT_EQ(CubeMap::face_of({0, -1, 0}), 3);
  EXPECT_EQ(CubeMap::face_of({0, 0, 1}), 4);
  EXPECT_EQ(CubeMap::face_of({0, 0, -1}), 5);
  std::vector<Vec3> dirs;
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = -1; z <= 1; ++z) {
        if (x || y || z) dirs.push_back({double(x), double(y), double(z)});
      }
    }
  }
  for (int k = 0; k < 2000; ++k) {  // a deterministic spiral over the sphere
    const double t = (k + 0.5) / 2000, z = 1 - 2 * t, a = k * 2.399963229728653;
    const double s = std::sqrt(1 - z * z);
    dirs.push_back({s * std::cos(a), s * std::sin(a), z});
  }
  constexpr int kRes = 64;
  for (const Vec3& d : dirs) {
    const int f = CubeMap::face_of(d);
    const RasterProjection view = CubeMap::face_view(f, {0, 0, 0}, kRes, 1e-3);
    const Vec3 v = view.to_view(d);
    ASSERT_GT(v.z, 0) << d.x << " " << d.y << " " << d.z;
    EXPECT_LE(std::abs(v.x), v.z * (1 + 1e-12));
    EXPECT_LE(std::abs(v.y), v.z * (1 + 1e-12));
    EXPECT_GE(view.pixel_x(v), -1e-9);
    EXPECT_LE(view.pixel_x(v), kRes + 1e-9);
    EXPECT_GE(view.pixel_y(v), -1e-9);
    EXPECT_LE(view.pixel_y(v), kRes + 1e-9);
  }
}

// The camera pass's batches place every direction as the cube map's own face selection and
// projection do: the same face and, off texel boundaries, the same texel; lanes past a
// batch's size change nothing.
TEST(ShadowMap, BatchesPlaceDirectionsAsTheCubeMapDoes) {
  constexpr int kRes = 64;
  ShadowMapMethod method = make({{"resolution", std::to_string(kRes)}, {"tiles", "all"}});
  method.build(square_scene(Light::point({0, 1, 0}), kTopCamera), 0, quiet());
  const CubeMap& cube = method.cube_map();
  std::vector<Vec3> dirs;
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = -1; z <= 1; ++z) {
        if (x || y || z) dirs.push_back({x * 0.5, y * 0.5, z * 0.5});
      }
    }
  }
  for (int k = 0; k < 500; ++k) {  // a spiral over the sphere, as above
    const double t = (k + 0.5) / 500, z = 1 - 2 * t, a = k * 2.399963229728653;
    const double s = std::sqrt(1 - z * z);
    dirs.push_back({s * std::cos(a), s * std::sin(a), z});
  }
  int checked = 0;
  for (std::size_t first = 0; first < dirs.size(); first += PointBatch::kSize - 1) {
    PointBatch points;
    for (std::size_t k = first; k < std::min(dirs.size(), first + PointBatch::kSize - 1); ++k) {
      points.add(dirs[k], {});
    }
    TexelBatch texels;
    cube_texels(cube, points, texels);
    for (std::size_t k = 0; k < points.size; ++k) {
      const Vec3 d = dirs[first + k];
      const int f = CubeMap::face_of(d);
      ASSERT_EQ(texels.map[k], f) << d.x << " " << d.y << " " << d.z;
      const RasterProjection& view = cube.face(f).view();
      const Vec3 v = view.to_view(view.eye + d);
      const double px = view.pixel_x(v), py = view.pixel_y(v);
      if (std::abs(px - std::round(px)) < 1e-4 || std::abs(py - std::round(py)) < 1e-4) continue;
      EXPECT_EQ(texels.texel_x[k], std::clamp(int(px), 0, kRes - 1));
      EXPECT_EQ(texels.texel_y[k], std::clamp(int(py), 0, kRes - 1));
      EXPECT_FLOAT_EQ(texels.depth[k], float(v.z));  // no bias
      ++checked;
    }
  }
  EXPECT_GT(checked, 450);
}

// A closed box [-5, 5]^3 around a point light at its centre: the cube faces' edges and corners
// fall exactly on the box's edges and corners. Every such point must be lit, and the corner
// behind a small occluder on the (1, 1, 1) diagonal must be shadowed.
Scene box_scene(bool with_occluder) {
  Scene scene;
  scene.camera = small_camera({0.5, 0.3, 0.2}, {1, 0, 0});
  scene.lights = {Light::point({0, 0, 0})};
  std::vector<Vec3> v;
  for (int k = 0; k < 8; ++k)
    v.push_back({k & 1 ? 5.0 : -5.0, k & 2 ? 5.0 : -5.0, k & 4 ? 5.0 : -5.0});
  add_object(scene, "box", v,
             {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
  if (with_occluder) {
    const Vec3 c{1, 1, 1}, a = normalize(Vec3{1, -1, 0}) * 0.3, b = normalize(Vec3{1, 1, -2}) * 0.3;
    add_object(scene, "occluder", {c - a - b, c + a - b, c + a + b, c - a + b}, {{0, 1, 2, 3}});
  }
  scene.finalize();
  return scene;
}

// Object 0: \p n boxes, their faces turned out, scattered over [-10, 10]^3; a point light.
Scene boxes_scene(int n, Vec3 light) {
  Scene scene;
  scene.camera = small_camera({0, 0, 30}, {0, 0, 0});
  scene.lights = {Light::point(light)};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> at(-10, 10), side(0.3, 0.8);
  std::vector<Vec3> v;
  std::vector<std::vector<std::uint32_t>> faces;
  for (int b = 0; b < n; ++b) {
    const Vec3 lo{at(rng), at(rng), at(rng)};
    const Vec3 hi = lo + Vec3{side(rng), side(rng), side(rng)};
    const auto first = std::uint32_t(v.size());
    for (int k = 0; k < 8; ++k)
      v.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
    for (std::vector<std::uint32_t> f : std::vector<std::vector<std::uint32_t>>{
             {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}) {
      for (std::uint32_t& i : f) i += first;
      faces.push_back(f);
    }
  }
  add_object(scene, "boxes", v, faces);
  scene.finalize();
  return scene;
}

// Whether each point, on a face of object 0 whose plane holds it, passes the depth test.
std::vector<bool> depth_tests(const Scene& scene, ShadowMapMethod& method,
                              const std::vector<Vec3>& pts) {
  method.build(scene, 0, quiet());
  std::vector<bool> lit;
  for (const Vec3& p : pts) {
    std::uint32_t face = kNoFace;
    for (std::uint32_t f = 0; f < scene.face_count() && face == kNoFace; ++f) {
      if (scene.object_of_face(f) == 0 && std::abs(scene.face_plane(f).distance(p)) < 1e-9) {
        face = f;
      }
    }
    EXPECT_NE(face, kNoFace);
    lit.push_back(face != kNoFace && method.passes_depth_test(scene.face_plane(face), p));
  }
  return lit;
}

TEST(ShadowMap, CubeMapEdgesAndCornersLookUpCorrectly) {
  std::vector<Vec3> pts;
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = -1; z <= 1; ++z) {
        if (x || y || z) pts.push_back(Vec3{double(x), double(y), double(z)} * 5.0);
      }
    }
  }
  for (int resolution : {16, 64}) {
    SCOPED_TRACE(resolution);
    ShadowMapMethod method = make({{"resolution", std::to_string(resolution)}, {"tiles", "all"}});
    const std::vector<bool> open = depth_tests(box_scene(false), method, pts);
    for (std::size_t k = 0; k < pts.size(); ++k) {
      EXPECT_TRUE(open[k]) << pts[k].x << " " << pts[k].y << " " << pts[k].z;
    }
    const std::vector<bool> occluded = depth_tests(box_scene(true), method, pts);
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const bool behind = pts[k] == Vec3{5, 5, 5};
      EXPECT_EQ(occluded[k], !behind) << pts[k].x << " " << pts[k].y << " " << pts[k].z;
    }
  }
}

// The scan converter's depth of every texel of \p view, converted as the map stores it: what
// a map drawn with depth-only tiles must hold, bit for bit.
std::vector<float> scan_converter_depths(const Scene& scene, const RasterProjection& view) {
  std::vector<float> depth(std::size_t(view.width) * view.height, INFINITY);
  ScanConverter(scene).rasterize_tiles(view, quiet(), [&](const RasterTile& tile) {
    if (tile.empty()) return;
    for (int y = 0; y < tile.height; ++y) {
      for (int x = 0; x < tile.width; ++x) {
        const int k = y * tile.width + x;
        if (tile.face[k] == kNoFace) continue;
        const double key = tile.depth_key[k];
        depth[std::size_t(tile.y0 + y) * view.width + tile.x0 + x] =
            view.orthographic ? DepthMap::linear_depth<true>(key)
                              : DepthMap::linear_depth<false>(key);
      }
    }
  });
  return depth;
}

// Texels of \p map whose bits differ from \p expected's.
int differing_texels(const DepthMap& map, const std::vector<float>& expected) {
  int differ = 0;
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      differ += std::bit_cast<std::uint32_t>(map.depth(x, y)) !=
                std::bit_cast<std::uint32_t>(expected[std::size_t(y) * map.width() + x]);
    }
  }
  return differ;
}

// Each face is drawn with only the clusters its pyramid reaches, depth only: the maps must
// still be the scan converter's. 100 texels leave partial tiles; at 1024 the
// far ground of the third scene lies past the guard band and is clipped there.
TEST(ShadowMap, CubeFacesHoldTheScanConvertersDepths) {
  const struct {
    const char* what;
    Scene scene;
    int faces_drawn;
  } cases[] = {
      // Every triangle of the box crosses four faces, and the faces' edges fall on its edges.
      {"light at the centre of a closed box", box_scene(true), 6},
      // The square's corner (1, 1, 1) lies in the direction (2, -0.5, 2), on the edge between
      // the +X and +Z faces; the square's triangles cross -Y, +X and +Z.
      {"a vertex on a face edge", square_scene(Light::point({-1, 1.5, -1}), kTopCamera), 5},
      // Between the ground and the square: the square above, the ground on five faces, its
      // corners behind the near planes of the side faces.
      {"light inside the scene's bounds", square_scene(Light::point({0.3, 0.5, 0.2}), kTopCamera),
       6},
      // 36,000 triangles, 2,250 clusters, all in the +X face: drawn in batches, each culled
      // against the ones before it (ScanConverter::kCulledClusters).
      {"a light beside thousands of boxes", boxes_scene(3000, {-30, 0, 0}), 1},
  };
  for (const auto& c : cases) {
    for (const int resolution : {100, 1024}) {
      SCOPED_TRACE(std::string(c.what) + " at " + std::to_string(resolution));
      CubeMap cube;
      cube.render(c.scene, c.scene.lights[0].position, resolution, quiet());
      int faces_drawn = 0;
      for (int f = 0; f < CubeMap::kFaces; ++f) {
        const std::vector<float> expected = scan_converter_depths(c.scene, cube.face(f).view());
        EXPECT_EQ(differing_texels(cube.face(f), expected), 0) << "face " << f;
        const auto covered =
            std::count_if(expected.begin(), expected.end(), [](float d) { return d != INFINITY; });
        EXPECT_EQ(cube.face(f).covered_texels(), std::size_t(covered)) << "face " << f;
        faces_drawn += covered > 0;
      }
      EXPECT_EQ(faces_drawn, c.faces_drawn);
    }
  }
}

// The orthographic map of a directional light, drawn from the scan converter's setup.
TEST(ShadowMap, DirectionalMapHoldsTheScanConvertersDepths) {
  const Scene scene = square_scene(Light::directional({0.3, -1, 0.2}), kTopCamera);
  ShadowMapMethod method = make({{"resolution", "100"}, {"tiles", "all"}});
  method.build(scene, 0, quiet());
  const DepthMap& map = method.directional_map();
  const std::vector<float> expected = scan_converter_depths(scene, map.view());
  EXPECT_EQ(differing_texels(map, expected), 0);
  const auto covered =
      std::count_if(expected.begin(), expected.end(), [](float d) { return d != INFINITY; });
  EXPECT_EQ(map.covered_texels(), std::size_t(covered));
  EXPECT_GT(covered, 9000);  // the ground fills most of the view fitted to the scene's box
}

// Counts the covered pixels of \p r where the camera pass decides otherwise than the test of
// one point, and checks that some pixels are lit and some shadowed.
int camera_pass_disagreements(const Scene& scene, const ShadowMapMethod& method,
                              const Rendered& r) {
  const Light& light = scene.lights.at(0);
  int lit = 0, shadowed = 0, differ = 0;
  for (std::size_t i = 0; i < r.mask.pixels.size(); ++i) {
    if (!r.surfaces.covered(i)) {
      EXPECT_EQ(r.mask.pixels[i], kMaskBackground);
      continue;
    }
    const Plane& plane = scene.face_plane(r.surfaces.face[i]);
    const bool expected = faces_light(plane, scene.camera.position, light) &&
                          method.passes_depth_test(plane, r.surfaces.point(i));
    differ += (r.mask.pixels[i] == kMaskLit) != expected;
    (expected ? lit : shadowed)++;
  }
  EXPECT_GT(lit, 1000);
  EXPECT_GT(shadowed, 100);
  return differ;
}

const Light kPassLights[] = {Light::point({-1, 1.5, -1}), Light::point({0.3, 0.5, 0.2}),
                             Light::directional({0.3, -1, 0.2})};

// The camera pass, in screen tiles with a face's points set up a stretch of pixels at a time
// and the texel loads of a row made together, decides every pixel as the test of one point
// does.
TEST(ShadowMap, CameraPassAgreesWithThePointTest) {
  for (const Light& light : kPassLights) {
    for (const int pcf : {1, 3}) {
      SCOPED_TRACE(std::to_string(light.position.x) + " pcf " + std::to_string(pcf));
      const Scene scene = square_scene(light, kTopCamera);
      ShadowMapMethod method = make({{"resolution", "128"}, {"pcf", std::to_string(pcf)}});
      EXPECT_EQ(camera_pass_disagreements(scene, method, render(scene, method)), 0);
    }
  }
}

// The ground of square_scene() under 13 x 13 small pyramids of four sides, seen from above at
// an angle.
Scene pyramid_field(const Light& light) {
  Scene scene = square_scene(light, small_camera({0, 4, 9}, {0, 0, 0}, 70), false);
  for (int i = -6; i <= 6; ++i) {
    for (int j = -6; j <= 6; ++j) {
      const double x = 0.7 * i, z = 0.7 * j, h = 0.6 + 0.1 * ((i + j) & 3);
      add_object(scene, "pyramid",
                 {{x - 0.25, 0, z - 0.25},
                  {x + 0.25, 0, z - 0.25},
                  {x + 0.25, 0, z + 0.25},
                  {x - 0.25, 0, z + 0.25},
                  {x, h, z}},
                 {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
    }
  }
  scene.finalize();
  return scene;
}

// The same where a row of pixels crosses a face every few pixels: a field of small pyramids,
// whose sides turned from the light are shadowed stretches between lit ones, and sky between
// the ground's edge and the top of the image.
TEST(ShadowMap, CameraPassAgreesWithThePointTestAcrossManySmallFaces) {
  for (const Light& light : kPassLights) {
    SCOPED_TRACE(std::to_string(light.position.x));
    const Scene scene = pyramid_field(light);
    ShadowMapMethod method = make({{"resolution", "256"}});
    EXPECT_EQ(camera_pass_disagreements(scene, method, render(scene, method)), 0);
  }
}

double counter(const ShadowMapMethod& method, const std::string& name) {
  for (const auto& [k, v] : method.counters()) {
    if (k == name) return v;
  }
  ADD_FAILURE() << "no counter " << name;
  return 0;
}

// Drawing only the tiles the visible points look up gives the masks of the whole map, PCF
// kernels across tile borders included, with fewer tiles drawn; a second camera pass draws
// its own tiles again.
TEST(ShadowMap, LookedUpTilesGiveTheWholeMapsMasks) {
  const Camera low = small_camera({0, 0.6, 6}, {0, 0.3, 0}, 50);  // half sky
  for (const Light& light : kPassLights) {
    for (const Scene& scene :
         {square_scene(light, kTopCamera), square_scene(light, low), pyramid_field(light)}) {
      for (const int pcf : {1, 5, 31}) {
        SCOPED_TRACE(std::to_string(light.position.x) + " pcf " + std::to_string(pcf));
        const std::map<std::string, std::string> settings{{"resolution", "256"},
                                                          {"pcf", std::to_string(pcf)}};
        std::map<std::string, std::string> all = settings;
        all["tiles"] = "all";
        ShadowMapMethod whole = make(all), looked_up = make(settings);
        const Rendered expected = render(scene, whole);
        const Rendered got = render(scene, looked_up);
        EXPECT_EQ(got.mask.pixels, expected.mask.pixels);
        EXPECT_EQ(counter(whole, "drawn_tiles"), counter(whole, "map_tiles"));
        EXPECT_GT(counter(looked_up, "drawn_tiles"), 0);
        if (pcf < 31) {  // a kernel of 31 texels reaches every tile of a 256-texel map
          EXPECT_LT(counter(looked_up, "drawn_tiles"), counter(looked_up, "map_tiles"));
        }
        ShadowMask again(got.mask.width, got.mask.height, kMaskBackground);
        looked_up.shade(scene, got.surfaces, again, quiet());
        EXPECT_EQ(again.pixels, expected.mask.pixels);
      }
    }
  }
}

// A camera pass keeps what it set up per receiving face for its own light only: a method
// that shades one light and then another, from above the ground and then below it, gives the
// second the masks a fresh method gives, on the square and on faces a few pixels wide.
TEST(ShadowMap, ASecondLightForgetsTheFirstsReceivers) {
  for (const std::string tiles : {"looked_up", "all"}) {
    for (const bool pyramids : {false, true}) {
      SCOPED_TRACE(tiles + (pyramids ? " pyramids" : " square"));
      const auto scene_lit_by = [&](const Light& light) {
        return pyramids ? pyramid_field(light) : square_scene(light, kTopCamera);
      };
      Scene scene = scene_lit_by(Light::directional({0.3, -1, 0.2}));
      scene.lights.push_back(Light::directional({0.2, 1, 0.3}));
      const Scene second = scene_lit_by(scene.lights[1]);
      ShadowMapMethod reused = make({{"resolution", "256"}, {"tiles", tiles}});
      const Rendered first = render(scene, reused);
      ASSERT_GT(count_mask(first, 0, kMaskLit), 0);
      ShadowMask again(first.mask.width, first.mask.height, kMaskBackground);
      reused.build(scene, 1, quiet());
      reused.shade(scene, first.surfaces, again, quiet());
      ShadowMapMethod fresh = make({{"resolution", "256"}, {"tiles", tiles}});
      const Rendered expected = render(second, fresh);
      EXPECT_EQ(count_mask(expected, 0, kMaskLit), 0);  // the ground's top is turned from it
      EXPECT_EQ(again.pixels, expected.mask.pixels);
    }
  }
}

// Nothing to look up draws nothing: a camera that sees no surface, and one that sees only
// faces turned from the light.
TEST(ShadowMap, NoLookupsDrawNoTile) {
  const Camera sky = small_camera({0, 2, 5}, {0, 12, 4});
  const Camera below = small_camera({0, -3, 0.5}, {0, 0, 0});
  for (const Light& light : kPassLights) {
    for (const Camera& camera : {sky, below}) {
      const Scene scene = square_scene(light, camera);
      ShadowMapMethod method = make({{"resolution", "256"}});
      const Rendered r = render(scene, method);
      EXPECT_EQ(counter(method, "drawn_tiles"), 0);
      EXPECT_EQ(count_mask(r, 0, kMaskLit) + count_mask(r, 1, kMaskLit), 0);
    }
  }
}

// (4) A lit ground at grazing incidence: without any bias about half of it shadows itself
// (acne); the default bias removes all of it.
TEST(ShadowMap, ZeroBiasShowsAcneDefaultBiasDoesNot) {
  const Camera camera = small_camera({0, 6, 12}, {0, 0, 0});
  for (const Light& light : {Light::directional({1, -0.2, 0.3}), Light::point({0, 3, 0})}) {
    SCOPED_TRACE(light.type == Light::Type::point ? "point" : "directional");
    const Scene scene = square_scene(light, camera, /*with_square=*/false);
    ShadowMapMethod no_bias = make({{"resolution", "512"}, {"bias", "0"}, {"slope_bias", "0"}});
    const Rendered acne = render(scene, no_bias);
    const int ground = int(acne.surfaces.covered_count());
    EXPECT_GT(ground, 10000);
    EXPECT_GT(count_mask(acne, 0, kMaskShadow), ground / 20);

    ShadowMapMethod defaults = make({{"resolution", "512"}});
    const Rendered clean = render(scene, defaults);
    EXPECT_EQ(count_mask(clean, 0, kMaskShadow), 0);
    EXPECT_DOUBLE_EQ(defaults.bias(), 1e-3 * scene.bounds().diagonal());
  }
}

// A bias larger than the gap between caster and receiver lifts the shadow off: peter-panning.
TEST(ShadowMap, LargeBiasDetachesShadow) {
  const Scene scene = square_scene(Light::point({0, 4, 0}), kTopCamera);
  ShadowMapMethod method = make({{"resolution", "256"}, {"bias", "1.5"}});
  const Rendered r = render(scene, method);
  EXPECT_EQ(count_mask(r, 0, kMaskShadow), 0);
  EXPECT_GT(count_mask(r, 0, kMaskLit), 1000);
}

// (5) Options.
TEST(ShadowMap, RejectsBadOptions) {
  EXPECT_THROW(make({{"size", "512"}}), InputError);
  EXPECT_THROW(make({{"resolution", "0"}}), InputError);
  EXPECT_THROW(make({{"resolution", "15"}}), InputError);
  EXPECT_THROW(make({{"resolution", "16385"}}), InputError);
  EXPECT_THROW(make({{"resolution", "100.5"}}), InputError);
  EXPECT_THROW(make({{"resolution", "big"}}), InputError);
  EXPECT_THROW(make({{"bias", "-1"}}), InputError);
  EXPECT_THROW(make({{"slope_bias", "-1"}}), InputError);
  EXPECT_THROW(make({{"pcf", "2"}}), InputError);
  EXPECT_THROW(make({{"pcf", "0"}}), InputError);
  EXPECT_THROW(make({{"tiles", "some"}}), InputError);
  EXPECT_NO_THROW(make({{"resolution", "16"}, {"bias", "0"}, {"slope_bias", "2"}, {"pcf", "3"}}));
}

// (6) Condition 1: the open square seen from below, with the light above, is in shadow.
TEST(ShadowMap, UndersideOfOpenSquareIsInShadow) {
  const Scene scene = square_scene(Light::point({0, 4, 0}), small_camera({0, 0.5, 2.5}, {0, 1, 0}));
  ShadowMapMethod method = make({{"resolution", "64"}});
  const Rendered r = render(scene, method);
  EXPECT_GT(count_mask(r, 1, kMaskShadow), 100);
  EXPECT_EQ(count_mask(r, 1, kMaskLit), 0);
}

TEST(ShadowMap, MemoryAndCounters) {
  const Scene point = square_scene(Light::point({0, 4, 0}), kTopCamera);
  ShadowMapMethod method = make({{"resolution", "32"}, {"tiles", "all"}});
  render(point, method);
  // A 32 x 32 face is one tile. Nothing is above the light: the +Y face holds only the shared
  // tile of +infinity; the five others hold it and their one drawn tile.
  constexpr std::size_t kTileBytes = DepthMap::kTileTexels * sizeof(float);
  const CubeMap& cube = method.cube_map();
  EXPECT_EQ(cube.face(2).covered_texels(), 0u);
  // Each tile has a slot (4 bytes) and a flag of whether it is drawn (1 byte).
  constexpr std::size_t kPerTile = sizeof(std::uint32_t) + 1;
  EXPECT_EQ(cube.face(2).memory_bytes(), kTileBytes + kPerTile);
  EXPECT_EQ(cube.face(3).covered_texels(), 32u * 32);  // -Y: the ground fills it
  std::size_t maps = 0;
  for (int f = 0; f < CubeMap::kFaces; ++f) maps += cube.face(f).memory_bytes();
  EXPECT_EQ(maps, 6 * kTileBytes + 5 * kTileBytes + 6 * kPerTile);
  EXPECT_EQ(method.memory_bytes(), maps);  // the maps are all a light's build keeps
  std::map<std::string, double> c;
  for (const auto& [k, v] : method.counters()) c[k] = v;
  EXPECT_EQ(c["faces"], 6);
  EXPECT_EQ(c["map_texels"], 6 * 32 * 32);
  EXPECT_EQ(c["map_tiles"], 6);
  EXPECT_EQ(c["drawn_tiles"], 6);
  EXPECT_GT(c["covered_texels"], 0);

  const Scene directional = square_scene(Light::directional({0, -1, 0.1}), kTopCamera);
  render(directional, method);
  EXPECT_EQ(method.memory_bytes(), 2 * kTileBytes + kPerTile);
  c.clear();
  for (const auto& [k, v] : method.counters()) c[k] = v;
  EXPECT_EQ(c["faces"], 1);
  EXPECT_EQ(c["map_texels"], 32 * 32);
}

}  // namespace
}  // namespace shadowkit::shadowmap
