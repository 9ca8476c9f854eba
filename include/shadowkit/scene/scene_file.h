#pragma once
/// \brief Loading scenes: JSON scene files (scene-format.md plus documented extensions) and
/// built-in procedural scenes by name.
#include <filesystem>
#include <string>

#include "shadowkit/core/context.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// Loads a JSON scene file. Errors name the file and the key or line (InputError).
Scene load_scene_file(const std::filesystem::path& path, const Context& ctx);

/// Loads \p spec: an existing scene file, or a built-in scene name such as "cubes:2000".
Scene load_scene(const std::string& spec, const Context& ctx);

}  // namespace shadowkit
