#pragma once
/// \brief Procedural scenes reproducing the papers' test scenes.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/scene/mesh.h"
#include "shadowkit/scene/scene.h"
#include "shadowkit/scene/scene_assembly.h"

namespace shadowkit {

/// \brief One named piece of generated geometry (before welding).
struct GeneratedObject {
  std::string name;
  PolygonSoup soup;
};

/// \brief Parameters of a generator: a JSON object such as {"generator": "cubes", "count": 8}.
/// \p where labels errors ("scene.json: key 'objects[2]'").
std::vector<GeneratedObject> generate_objects(const nlohmann::json& params,
                                              const std::string& where);

/// A complete built-in scene (camera, lights, objects) from a name with an optional
/// parameter: "cubes", "cubes:2000", "tetra:4", "room", "table", "three-lights", "square".
/// Throws InputError if the name is unknown.
Scene make_builtin_scene(const std::string& spec, const Context& ctx);

/// What make_builtin_scene() assembles, for a scene file to change before assembling;
/// \p where labels errors ("scene.json: key 'generator'").
SceneSource builtin_scene_source(const std::string& spec, const std::string& where);

/// The same from parameters such as {"generator": "cubes", "count": 2000}.
SceneSource builtin_scene_source(const nlohmann::json& params, const std::string& where);

/// Names of the built-in scenes, for help texts and error messages.
std::vector<std::string> builtin_scene_names();

}  // namespace shadowkit
