#pragma once
/// \brief The per-format mesh readers behind read_mesh_file(). Each parses a whole file held
/// in memory; \p path only labels error messages.
#include <string>
#include <string_view>

#include "shadowkit/scene/mesh.h"

namespace shadowkit::mesh_io {

PolygonSoup read_obj(std::string_view data, const std::string& path);
PolygonSoup read_ply(std::string_view data, const std::string& path);
PolygonSoup read_off(std::string_view data, const std::string& path);
PolygonSoup read_stl(std::string_view data, const std::string& path);

}  // namespace shadowkit::mesh_io
