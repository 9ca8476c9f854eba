#pragma once
/// \brief Mesh file readers: Wavefront OBJ, PLY (ASCII and binary), OFF and STL (ASCII and
/// binary). Polygons keep all their vertices.
#include <filesystem>

#include "shadowkit/scene/mesh.h"

namespace shadowkit {

/// Reads a mesh file, choosing the format by extension (case-insensitive).
/// Throws InputError("path:line", what) for malformed content, non-finite coordinates and
/// out-of-range indices, and InputError("path", what) for unreadable or unknown files.
PolygonSoup read_mesh_file(const std::filesystem::path& path);

}  // namespace shadowkit
