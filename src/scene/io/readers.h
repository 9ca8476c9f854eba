#pragma once
/// \brief The per-format mesh readers behind read_mesh_file(). Each parses a whole file held
/// in memory; \p path labels messages and locates files the mesh refers to (glTF buffers),
/// and \p ctx receives warnings about what is skipped.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/mesh_io.h"

namespace shadowkit::mesh_io {

MeshFile read_obj(std::string_view data, const std::string& path, const Context& ctx);
MeshFile read_ply(std::string_view data, const std::string& path, const Context& ctx);
MeshFile read_off(std::string_view data, const std::string& path, const Context& ctx);
MeshFile read_stl(std::string_view data, const std::string& path, const Context& ctx);
MeshFile read_gltf(std::string_view data, const std::string& path, const Context& ctx);

/// Reads \p path with assimp, in a child process that a crash or a hang cannot take down
/// with shadowkit, within a time and memory budget that grows with the file (limits.h).
MeshFile read_with_assimp(const std::string& path, const Context& ctx);

/// The extensions assimp's importers claim, lower case with the dot (".dae", ".fbx", ...).
std::vector<std::string> assimp_extensions();

/// Why \p path cannot be read as a file ("it is a directory", "it is not a regular file": a
/// device or a pipe may never end, as /dev/zero or a FIFO no one writes to); empty for a
/// regular file or a path that does not exist, which opening it reports.
std::string why_not_a_file(const std::filesystem::path& path);

}  // namespace shadowkit::mesh_io
