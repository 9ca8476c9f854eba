#pragma once
/// \brief Chin & Feiner 1989 shadow-volume BSP trees: the scene's faces split into lit and
/// shadowed fragments in object space, one SVBSP tree per light.
#include <cstddef>
#include <filesystem>
#include <memory>

#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::svbsp {

/// The method with \p options (its settings, docs/methods/svbsp.md); InputError for an unknown
/// key or a bad value.
std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options);

/// \brief What write_fragments() wrote.
struct FragmentsWritten {
  std::size_t fragments = 0;
};

/// The fragments of every light of \p scene, from one scene BSP tree: \p ply holds each
/// fragment with its original polygon and a lit flag per light; \p json the lit and shadowed
/// area of every original polygon per light (docs/commands.md, fragments). World
/// coordinates and units. InputError when a file cannot be written.
FragmentsWritten write_fragments(const Scene& scene, const std::filesystem::path& ply,
                                 const std::filesystem::path& json);

}  // namespace shadowkit::svbsp
