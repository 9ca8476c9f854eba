#pragma once
/// \brief Loading scenes: JSON scene files (scene-format.md plus documented extensions) and
/// built-in procedural scenes by name.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "shadowkit/core/context.h"
#include "shadowkit/scene/mesh_io.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// Loads a JSON scene file. Errors name the file and the key or line (InputError).
Scene load_scene_file(const std::filesystem::path& path, const Context& ctx);

/// The `camera` and `lights` keys of \p json, a scene file's or a request's alike, in world
/// coordinates: camera keys given replace \p view's, `lights` given replaces its list. Checked
/// as a scene file's; InputError names \p where and the key, unknown keys go to ctx.warning.
SceneView read_scene_view(const nlohmann::json& json, SceneView view, const std::string& where,
                          const Context& ctx);

/// A mesh file (any format read_mesh_file() reads) as a scene of its own: the camera looks
/// at its bounds from the front, right and above, and one directional light falls from
/// above and to the left.
Scene load_mesh_as_scene(const std::filesystem::path& path, const Context& ctx);
/// The same for a mesh file already read from \p path.
Scene mesh_scene(MeshFile file, const std::filesystem::path& path, const Context& ctx);

/// Loads \p spec: an existing scene file, a mesh file (load_mesh_as_scene), or a built-in
/// scene name such as "cubes:2000".
Scene load_scene(const std::string& spec, const Context& ctx);

}  // namespace shadowkit
