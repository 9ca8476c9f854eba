#include "svbsp_method.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>

#include "fragment_raster.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/svbsp.h"

namespace shadowkit::svbsp {

SvbspMethod::SvbspMethod(const MethodOptions& options) {
  options.expect_only("svbsp", {"shadowed_only", "merge_siblings"});
  const double shadowed_only = options.number("shadowed_only", 0);
  if (shadowed_only != 0 && shadowed_only != 1) {
    throw InputError("option 'svbsp.shadowed_only'", "expected 0 or 1");
  }
  shadowed_only_ = shadowed_only == 1;
  const double merge_siblings = options.number("merge_siblings", 1);
  if (merge_siblings != 0 && merge_siblings != 1) {
    throw InputError("option 'svbsp.merge_siblings'", "expected 0 or 1");
  }
  merge_siblings_ = merge_siblings == 1;
}

void SvbspMethod::prepare(const Scene& scene, const Context& /*ctx*/) {
  // Independent: the solids' faces are found while the tree is built.
  tbb::parallel_invoke([&] { bsp_ = svbsp::SceneBsp::build(scene); },
                       [&] { solids_.emplace(scene); });
}

void SvbspMethod::build(const Scene& scene, std::size_t light, const Context& /*ctx*/) {
  SHADOWKIT_CHECK(bsp_.has_value() && solids_.has_value());
  light_ = scene.lights[light];
  result_ = svbsp::generate_shadows(*bsp_, scene, light_, merge_siblings_,
                                    svbsp::far_side_of(*solids_, scene, light_));
  if (shadowed_only_) {  // §6: one light at a time, the lit fragments are thrown away
    std::erase_if(result_.fragments, [](const svbsp::Fragment& f) { return f.lit; });
  }
  input_polygons_ = scene.face_count();
  front_facing_ = svbsp::front_facing(scene, light_);
}

void SvbspMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                        const Context& /*ctx*/) {
  svbsp::shade_fragments(scene, light_, result_.fragments, surfaces, shadowed_only_, mask);
}

std::size_t SvbspMethod::memory_bytes() const {
  std::size_t bytes = (bsp_ ? bsp_->memory_bytes() : 0) + result_.svbsp_bytes;
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
