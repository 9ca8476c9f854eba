#include "shadowkit/scene/scene_assembly.h"

#include <cmath>
#include <sstream>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/limits.h"
#include "shadowkit/scene/subdivision.h"

namespace shadowkit {
namespace {

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

void check_coordinates(const ObjectSource& object) {
  for (const Vec3& p : object.soup.positions) {
    if (!is_finite(p) || max_abs_component(p) > limits::kCoordinate) {
      throw InputError(object.where, "a vertex lies beyond +-1e15, which is not supported");
    }
  }
}

// The geometry must be large enough against its distance from the origin for its
// coordinates to describe it: a millimetre part a billion units out is mostly rounding.
void check_size_against_offset(const Bounds3& geometry, const std::string& where) {
  if (geometry.empty()) return;
  const double offset = std::max(max_abs_component(geometry.lo), max_abs_component(geometry.hi));
  const double size = max_abs_component(geometry.extent());
  if (size < limits::kSmallestSize && offset > 0) {
    throw InputError(where, "the geometry is " + number_text(size) +
                                " across; below 1e-290, "
                                "coordinates lose the precision that describes it");
  }
  if (size < limits::kSizeToOffset * offset) {
    throw InputError(where, "the geometry is " + number_text(size) + " across but lies " +
                                number_text(offset) +
                                " from the origin: its coordinates hold too few digits of its "
                                "shape (the size must be at least 1e-11 of the distance)");
  }
}

// A position in working coordinates; \p key names it when it lies too far from the scene.
Vec3 working_position(const WorldFrame& frame, Vec3 p, const std::string& where,
                      const std::string& key) {
  const Vec3 q = frame.to_working(p);
  if (max_abs_component(q) > limits::kCoordinate) {
    throw InputError(key_location(where, key),
                     "lies more than 1e15 times the scene's size away from it");
  }
  return q;
}

class PolygonBudget {
 public:
  /// Takes \p polygons from the budget; InputError at \p where when it runs out.
  void take(std::size_t polygons, const std::string& where) {
    if (polygons > limits::kPolygons - used_) {
      throw InputError(where, "the scene would hold more than " +
                                  std::to_string(limits::kPolygons) + " polygons (" +
                                  std::to_string(used_ + polygons) + ")");
    }
    used_ += polygons;
  }
  std::size_t left() const { return limits::kPolygons - used_; }

 private:
  std::size_t used_ = 0;
};

// The most triangles one object's tessellation for the view may make: four times the
// 584k-triangle knot of examples/knot-600k.json. Past it the tessellation is coarsened,
// with a warning, rather than refused: the scene still loads.
constexpr std::size_t kViewTessellationTriangles = std::size_t(1) << 22;

// What a tessellation for the view of \p scene's camera must hold to (ViewTolerance).
ViewTolerance view_tolerance(const Scene& scene) {
  ViewTolerance view;
  view.eye = scene.camera.position;
  view.pixel_at_unit_distance = 2 * scene.camera.tan_half_fov() / scene.camera.height;
  for (const Light& light : scene.lights) {
    if (light.type == Light::Type::point) {
      view.point_lights.push_back(light.position);
    } else {
      view.toward_lights.push_back(-light.direction);
    }
  }
  return view;
}

// A Catmull-Clark object tessellated for the view of \p scene (its camera and lights).
SceneObject tessellated_for_view(const ObjectSource& object,
                                 std::shared_ptr<const SubdivisionSurface> surface,
                                 const Scene& scene, PolygonBudget& budget, const Context& ctx) {
  const std::string where = key_location(object.where, "tessellation");
  const ViewTolerance view = view_tolerance(scene);
  ViewTessellation t =
      surface->tessellate_for_view(view, std::min(kViewTessellationTriangles, budget.left()));
  if (t.coarsened) {
    ctx.warning(where + ": within half a pixel of the view it would make " +
                (t.asked_exactly ? "" : "more than ") + std::to_string(t.triangles_asked) +
                " triangles; coarsened to " + std::to_string(t.soup.face_count()) + " (at most " +
                std::to_string(t.finest) + " segments a patch)");
  }
  budget.take(t.soup.face_count(), where);
  const std::string label = object.where + " (" + object.name + ")";
  return {object.name, Mesh::build(t.soup, label, ctx), 0, std::move(surface)};
}

SceneObject build_object(ObjectSource& object, const Scene& scene, PolygonBudget& budget,
                         const Context& ctx) {
  const std::string label = object.where + " (" + object.name + ")";
  if (object.tessellation == 0) {
    budget.take(object.soup.face_count(), object.where);
    return {object.name, Mesh::build(object.soup, label, ctx), 0, {}};
  }
  auto surface = SubdivisionSurface::build(object.soup, label);
  if (object.tessellation == kTessellationForView) {
    return tessellated_for_view(object, std::move(surface), scene, budget, ctx);
  }
  // Two triangles per cell, segments x segments cells per patch: counted before tessellating.
  const std::size_t per_patch = 2 * std::size_t(object.tessellation) * object.tessellation;
  if (surface->patch_count() > limits::kPolygons / per_patch) {
    throw InputError(key_location(object.where, "tessellation"),
                     std::to_string(object.tessellation) + " segments on " +
                         std::to_string(surface->patch_count()) + " patches would make " +
                         std::to_string(surface->patch_count() * per_patch) +
                         " triangles; at most " + std::to_string(limits::kPolygons) +
                         " are allowed");
  }
  budget.take(surface->patch_count() * per_patch, key_location(object.where, "tessellation"));
  return {object.name, Mesh::build(surface->tessellate(object.tessellation), label, ctx), 0,
          std::move(surface)};
}

}  // namespace

WorldFrame WorldFrame::around(const Bounds3& geometry) {
  // The largest extent, not the diagonal: its squares would underflow for tiny scenes.
  const double size = geometry.empty() ? 0.0 : max_abs_component(geometry.extent());
  if (geometry.empty() || !(size > 0)) return {geometry.empty() ? Vec3{} : geometry.center(), 1};
  return {geometry.center(), std::exp2(std::round(std::log2(size)))};
}

void place_view(Scene& scene, const SceneView& view, const std::string& where) {
  Camera camera = view.camera;
  camera.position = working_position(scene.frame, camera.position, where, "camera.position");
  camera.look_at = working_position(scene.frame, camera.look_at, where, "camera.look_at");
  std::vector<Light> lights = view.lights;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    if (lights[l].type == Light::Type::point) {
      lights[l].position = working_position(scene.frame, lights[l].position, where,
                                            "lights[" + std::to_string(l) + "].position");
    }
  }
  scene.camera = camera;
  scene.lights = std::move(lights);
}

SceneView world_view(const Scene& scene) {
  SceneView view{scene.camera, scene.lights};
  view.camera.position = scene.frame.to_world(view.camera.position);
  view.camera.look_at = scene.frame.to_world(view.camera.look_at);
  for (Light& light : view.lights) {
    if (light.type == Light::Type::point) light.position = scene.frame.to_world(light.position);
  }
  return view;
}

Scene assemble_scene(SceneSource source, const Context& ctx) {
  Bounds3 geometry;
  for (const ObjectSource& object : source.objects) {
    check_coordinates(object);
    for (const Vec3& p : object.soup.positions) geometry.add(p);
  }
  check_size_against_offset(geometry, source.where);

  Scene scene;
  scene.name = std::move(source.name);
  scene.frame = WorldFrame::around(geometry);
  place_view(scene, {source.camera, source.lights}, source.where);
  PolygonBudget budget;
  for (std::size_t i = 0; i < source.objects.size(); ++i) {
    ObjectSource& object = source.objects[i];
    for (Vec3& p : object.soup.positions) p = scene.frame.to_working(p);
    scene.objects.push_back(build_object(object, scene, budget, ctx));
    scene.objects.back().input_object = object.input_object.value_or(std::uint32_t(i));
    scene.objects.back().input_first_face = object.input_first_face;
  }
  scene.finalize();
  return scene;
}

}  // namespace shadowkit
