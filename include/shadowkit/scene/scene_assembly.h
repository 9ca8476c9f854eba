#pragma once
/// \brief Turning what a scene file or a generator describes into a Scene: range checks, the
/// working frame, meshes and tessellations.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// ObjectSource::tessellation of a Catmull-Clark object tessellated for the scene's camera
/// and lights (`"tessellation": "view"`, the default): every cell within half a pixel of the
/// limit surface, and a pixel across where a facet may turn from a light.
inline constexpr int kTessellationForView = -1;

/// \brief One object as its source gives it, in world coordinates.
struct ObjectSource {
  std::string name;
  PolygonSoup soup;
  /// Segments per patch edge when \p soup is a Catmull-Clark control mesh, or
  /// kTessellationForView; 0: polygons.
  int tessellation = 0;
  /// Labels the object's errors and warnings ("scene.json: key 'objects[2]'").
  std::string where;
  /// SceneObject::input_object; none: the object's place in SceneSource::objects.
  std::optional<std::uint32_t> input_object = std::nullopt;
  /// SceneObject::input_first_face.
  std::uint32_t input_first_face = 0;
};

/// \brief A scene as described, before its working frame is chosen.
struct SceneSource {
  std::string name;
  Camera camera;
  std::vector<Light> lights;
  std::vector<ObjectSource> objects;
  /// Labels errors about the whole scene (the file, or "scene 'cubes:2000'").
  std::string where;
};

/// Checks every coordinate against limits::kCoordinate and the geometry's size against its
/// distance from the origin (limits::kSizeToOffset), chooses the working frame (Scene::frame),
/// moves camera, lights and objects into it, and builds meshes and tessellations, refusing
/// more than limits::kPolygons polygons before building them. InputError names the object or
/// key at fault.
Scene assemble_scene(SceneSource source, const Context& ctx);

/// Puts \p view (world coordinates) in place of \p scene's camera and lights, in its working
/// frame; InputError at \p where names the key of a position too far from the scene. The
/// scene is otherwise untouched: a new view needs no new finalize().
void place_view(Scene& scene, const SceneView& view, const std::string& where);

/// \p scene's camera and lights in world coordinates: what place_view() takes back.
SceneView world_view(const Scene& scene);

}  // namespace shadowkit
