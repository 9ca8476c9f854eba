#pragma once
/// \brief Chin & Feiner 1989 shadow-volume BSP trees: the scene's faces split into lit and
/// shadowed fragments in object space, one SVBSP tree per light.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <vector>

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

class SceneBsp;
struct Fragment;
struct SplitPolygons;

/// \brief The lit area of every scene face for one directional light after another, as the
/// sun study needs it: the scene BSP tree is built once (Chin & Feiner §3: its front-to-back
/// walk serves any light) and each call grows one light's SVBSP tree from it (§4).
class SunlitAreas {
 public:
  explicit SunlitAreas(const Scene& scene);
  ~SunlitAreas();
  SunlitAreas(const SunlitAreas&) = delete;
  SunlitAreas& operator=(const SunlitAreas&) = delete;

  /// Per global face id of the scene, the area of the face that a directional light
  /// arriving from \p toward_light (a unit vector toward the light) reaches, in world units
  /// (scene units squared). Surfaces are two-sided: every face casts shadows, whichever side
  /// the light sees, and the lit area is that of the side facing the light; a face whose
  /// plane holds the light has none. The sun study's polygons never shade themselves: the
  /// triangles of a warped input polygon (Mesh::input_faces) cast no shadow on one another. The sum
  /// runs over the face's lit fragments in a fixed order, so the result does not depend on threads.
  /// Thread-safe: calls share the scene BSP tree read-only.
  std::vector<double> lit_areas(Vec3 toward_light) const;

  /// The same, and in \p mask the light's shadow mask for \p surfaces (the scene camera's
  /// visible surfaces, at any size): the svbsp method's camera pass over this light's lit
  /// fragments. A pixel is lit where the sun reaches the visible point on the side the
  /// camera sees.
  std::vector<double> lit_areas(Vec3 toward_light, const VisibleSurfaceBuffer& surfaces,
                                ShadowMask& mask) const;

 private:
  std::vector<double> filter(Vec3 toward_light, std::vector<Fragment>* lit) const;

  const Scene& scene_;
  std::unique_ptr<const SceneBsp> bsp_;
  std::unique_ptr<const SplitPolygons> split_;  ///< warped polygons (svbsp_tree.h), or null
  std::vector<char> outward_solid_faces_;       ///< per face: skipped when turned from the light
};

}  // namespace shadowkit::svbsp
