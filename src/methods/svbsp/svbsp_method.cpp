#include "svbsp_method.h"

#include <algorithm>
#include <string>

#include "fragment_raster.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/svbsp.h"
#include "shadowkit/scene/footprints.h"

namespace shadowkit::svbsp {

namespace {

// A 0 or 1 setting, \p fallback when it is not given.
bool switch_setting(const MethodOptions& options, const std::string& key, bool fallback) {
  const double value = options.number(key, fallback ? 1 : 0);
  if (value != 0 && value != 1) throw InputError("option 'svbsp." + key + "'", "expected 0 or 1");
  return value == 1;
}

}  // namespace

SvbspMethod::SvbspMethod(const MethodOptions& options) {
  options.expect_only(
      "svbsp", {"paper", "contour_planes", "far_side", "skip_edges_in_tree", "merge_siblings",
                "whole_pieces", "shadowed_only", "balance", "footprints"});
  // paper=1: Figs. 3 and 4 as written, one-sided; each §6 refinement off unless set.
  const bool paper = switch_setting(options, "paper", false);
  generator_.two_sided = !paper;
  generator_.skip_edges_in_tree = switch_setting(options, "skip_edges_in_tree", !paper);
  generator_.merge_siblings = switch_setting(options, "merge_siblings", !paper);
  generator_.whole_pieces = switch_setting(options, "whole_pieces", !paper);
  generator_.balance = switch_setting(options, "balance", !paper);
  far_side_ = switch_setting(options, "far_side", !paper);
  footprints_ = switch_setting(options, "footprints", !paper);
  contour_planes_ = switch_setting(options, "contour_planes", false);
  shadowed_only_ = switch_setting(options, "shadowed_only", false);
  clusters_ = !paper;
}

void SvbspMethod::prepare(const Scene& scene, const Context& /*ctx*/) {
  if (footprints_) parts_ = SubObjects::of(scene);
  if (!contour_planes_) {
    // Independent: the solids' faces are found while the tree is built.
    bsp_ = svbsp::SceneBsp::build(scene, nullptr, clusters_);
    return;
  }
  // §6, contour edges: the tree keeps each convex solid whole.
  convex_solids_.emplace(scene, scene.outward_solids());
  bsp_ = svbsp::SceneBsp::build(scene, &*convex_solids_, clusters_);
}

void SvbspMethod::build(const Scene& scene, std::size_t light, const Context& /*ctx*/) {
  SHADOWKIT_CHECK(bsp_.has_value());
  light_ = scene.lights[light];
  // The last light's fragments give their room to the new ones: 100k fragments in fresh
  // memory cost more in page faults than in their filtering.
  result_ = svbsp::generate_shadows(*bsp_, scene, light_, generator_, shadowed_whole(scene),
                                    convex_solids_ ? &*convex_solids_ : nullptr,
                                    std::move(result_.fragments));
  if (shadowed_only_) {  // §6: one light at a time, the lit fragments are thrown away
    std::erase_if(result_.fragments, [](const svbsp::Fragment& f) { return f.lit; });
  }
  input_polygons_ = scene.face_count();
  front_facing_ = svbsp::front_facing(scene, light_);
}

// §6 skips filtering where the answer is known: the far sides of outward solids, and the
// sub-objects wholly in the shadow of nearer ones (Crow's footprints), whose volumes lie
// within theirs.
ShadowedWhole SvbspMethod::shadowed_whole(const Scene& scene) {
  const ShadowedWhole far_side = far_side_ ? far_side_of(scene, light_) : ShadowedWhole{};
  if (!footprints_) return far_side;
  shadowed_parts_ = shadowed_sub_objects(parts_, light_, scene.bounds());
  return [this, far_side](std::uint32_t face) {
    return shadowed_parts_[parts_.of_face[face]] || (far_side && far_side(face));
  };
}

void SvbspMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                        const Context& /*ctx*/) {
  svbsp::shade_fragments(scene, light_, result_.fragments, surfaces, shadowed_only_, mask);
}

std::size_t SvbspMethod::memory_bytes() const {
  std::size_t bytes = (bsp_ ? bsp_->memory_bytes() : 0) + result_.svbsp_bytes +
                      parts_.memory_bytes() + shadowed_parts_.capacity();
  for (const svbsp::Fragment& f : result_.fragments) {
    bytes += sizeof(f) + heap_bytes(f.polygon);
  }
  return bytes;
}

MethodCounters SvbspMethod::counters() const {
  const auto lit = std::count_if(result_.fragments.begin(), result_.fragments.end(),
                                 [](const svbsp::Fragment& f) { return f.lit; });
  return {{"bsp_nodes", double(bsp_ ? bsp_->node_count() : 0)},
          {"bsp_pieces", double(bsp_ ? bsp_->piece_count() : 0)},
          {"bsp_splits", double(bsp_ ? bsp_->split_count() : 0)},
          {"convex_units", double(bsp_ ? bsp_->solid_count() : 0)},
          {"input_polygons", double(input_polygons_)},
          {"front_facing_polygons", double(front_facing_.polygons)},
          {"front_facing_edges", double(front_facing_.edges)},
          {"light_facing", double(result_.light_facing)},
          {"svbsp_nodes", double(result_.svbsp_nodes)},
          {"fragments", double(result_.fragments.size())},
          {"lit_fragments", double(lit)}};
}

std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options) {
  return std::make_unique<SvbspMethod>(options);
}

}  // namespace shadowkit::svbsp
