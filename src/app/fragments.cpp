// The fragments command: svbsp's fragments of every light written as geometry and areas.
#include <cstdio>
#include <filesystem>

#include "shadowkit/app/commands.h"
#include "shadowkit/core/error.h"
#include "shadowkit/core/files.h"
#include "shadowkit/methods/svbsp.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {

int run_fragments(const FragmentsOptions& options, const Context& ctx) {
  const auto svbsp_settings = options.settings.find("svbsp");
  if (svbsp_settings != options.settings.end()) {
    svbsp::make_method(svbsp_settings->second);  // unknown keys and bad values
    if (svbsp_settings->second.number("shadowed_only", 0) != 0) {
      throw InputError("option 'svbsp.shadowed_only'",
                       "fragments writes lit and shadowed fragments; the option applies to "
                       "render, compare and bench");
    }
  }
  const std::filesystem::path ply = options.out;
  std::filesystem::path json = ply;
  json.replace_extension(".json");
  if (json == ply) throw InputError("--out " + options.out, "the PLY file cannot end in .json");
  const Scene scene = load_scene(options.scene, ctx);
  create_parent_directories(ply);
  const svbsp::FragmentsWritten written = svbsp::write_fragments(scene, ply, json);
  std::printf("%zu fragments of %u polygons, %zu light(s): %s, %s\n", written.fragments,
              scene.face_count(), scene.lights.size(), ply.c_str(), json.c_str());
  return 0;
}

}  // namespace shadowkit
