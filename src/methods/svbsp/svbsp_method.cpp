#include "svbsp_method.h"

#include <algorithm>

#include "fragment_raster.h"
#include "shadowkit/core/error.h"

namespace shadowkit {

SvbspMethod::SvbspMethod(const MethodOptions& options) {
  options.expect_only("svbsp", {});
}

void SvbspMethod::prepare(const Scene& scene, const Context& /*ctx*/) {
  bsp_ = svbsp::SceneBsp::build(scene);
}

void SvbspMethod::build(const Scene& scene, std::size_t light, const Context& /*ctx*/) {
  SHADOWKIT_CHECK(bsp_.has_value());
  light_ = scene.lights[light];
  result_ = svbsp::generate_shadows(*bsp_, scene, light_);
}

void SvbspMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                        const Context& /*ctx*/) {
  svbsp::shade_fragments(scene, light_, result_.fragments, surfaces, mask);
}

std::size_t SvbspMethod::memory_bytes() const {
  std::size_t bytes = (bsp_ ? bsp_->memory_bytes() : 0) + result_.svbsp_bytes;
  for (const svbsp::Fragment& f : result_.fragments) {
    bytes += sizeof(f) + f.polygon.vertices.capacity() * sizeof(Vec3) +
             f.polygon.edge_in_tree.capacity();
  }
  return bytes;
}

MethodCounters SvbspMethod::counters() const {
  const auto lit = std::count_if(result_.fragments.begin(), result_.fragments.end(),
                                 [](const svbsp::Fragment& f) { return f.lit; });
  return {{"bsp_nodes", double(bsp_ ? bsp_->node_count() : 0)},
          {"bsp_pieces", double(bsp_ ? bsp_->piece_count() : 0)},
          {"bsp_splits", double(bsp_ ? bsp_->split_count() : 0)},
          {"light_facing", double(result_.light_facing)},
          {"svbsp_nodes", double(result_.svbsp_nodes)},
          {"fragments", double(result_.fragments.size())},
          {"lit_fragments", double(lit)}};
}

}  // namespace shadowkit
