#pragma once
/// \brief What every fuzz target shares: the input written to a file in a per-process
/// temporary directory, loaded through the public load_scene_file(), and optionally rendered
/// with every method; or, for the shading-groups target, read by a sun study through the
/// public run_sun_study(). InputError is the expected outcome of bad input; anything else (another
/// exception, a crash, a sanitizer report, a hang) escapes to libFuzzer. docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace shadowkit::fuzz {

/// Sets the target up once per process. \p kind is "scene" (the input is a scene file),
/// "shading_groups" (the input is a sun study's `--shading-groups` file, for a fixed study) or
/// a mesh file extension such as "obj" (the input is a mesh file that fixed scene files
/// reference). With \p render, every scene that loads is also rendered with every method.
void initialize(std::string_view kind, bool render);

/// Runs one input. Returns 0, or -1 (libFuzzer: keep it out of the corpus) when a render
/// target rendered nothing.
int run_one(const std::uint8_t* data, std::size_t size);

}  // namespace shadowkit::fuzz
