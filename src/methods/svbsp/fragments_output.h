#pragma once
// Object-space output, what sets svbsp apart: the fragmented scene as a PLY file and the lit
// and shadowed area of every original polygon per light as JSON.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "multi_light.h"

namespace shadowkit::svbsp {

/// Writes \p result as an ASCII PLY file: per face (fragment) its vertices, `uint polygon`
/// (the original polygon's global id) and one `uchar lit_L<l>` (1 lit, 0 shadowed) per light
/// l of \p scene. Fragments keep their own vertices: they are split independently.
/// InputError when the file cannot be written.
void write_fragments_ply(const std::filesystem::path& path, const Scene& scene,
                         const MultiLightFragments& result);

/// Per original polygon: its object, area, fragment count and, per light (in scene order),
/// the lit and shadowed areas of its fragments; plus the light order and each light's
/// Table 1 statistics.
nlohmann::json fragment_areas_json(const Scene& scene, const MultiLightFragments& result);

}  // namespace shadowkit::svbsp
