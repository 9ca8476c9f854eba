#pragma once
/// \brief Mesh files: Wavefront OBJ, PLY, OFF and STL by shadowkit's own readers (exact error
/// positions), glTF 2.0 through tinygltf, and every other format assimp imports (COLLADA, FBX,
/// 3DS, IFC, X3D, Blender, ...). Polygons keep all their vertices.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/scene/mesh.h"

namespace shadowkit {

/// \brief A mesh file's polygons, placed by the file's node transforms, and what reading
/// them counted.
struct MeshFile {
  PolygonSoup soup;
  /// Polygons as the file stores them, each mesh once however often its nodes place it
  /// (what the format's own tools count).
  std::size_t stored_polygons = 0;
  /// Points and line segments, which bound no surface and are skipped.
  std::size_t skipped_primitives = 0;
};

/// Reads a mesh file, choosing the reader by extension (case-insensitive). Skipped content
/// is reported through \p ctx's warnings, once per kind.
/// Throws InputError("path:line", what) or InputError("path: key 'json.path'", what) for
/// malformed content, non-finite coordinates and out-of-range indices, and
/// InputError("path", what) for unreadable files, unknown formats and files without polygons.
MeshFile read_mesh_file(const std::filesystem::path& path, const Context& ctx);

/// The extensions read_mesh_file() accepts (".obj", ".gltf", ".dae", ...), lower case.
std::vector<std::string> mesh_file_extensions();

/// True when \p path's extension names a mesh format read_mesh_file() reads.
bool is_mesh_file_name(const std::filesystem::path& path);

}  // namespace shadowkit
