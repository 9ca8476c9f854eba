#include "multi_light.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "shadowkit/core/error.h"

namespace shadowkit::svbsp {
namespace {

// §6: fragments of a piece that all carry the same mask give way to the piece itself.
void merge_if_uniform(const ConvexPolygon& piece, std::vector<MaskedFragment>& fragments) {
  if (fragments.size() < 2) return;
  const std::uint64_t mask = fragments.front().lit_mask;
  const bool uniform = std::all_of(fragments.begin(), fragments.end(),
                                   [mask](const MaskedFragment& f) { return f.lit_mask == mask; });
  if (uniform) fragments.assign(1, {piece, mask});
}

// Splits the fragments of one piece by the tree of the current light (§5: each fragment
// falling into an OUT cell is marked lit by it).
void split_by_light(ShadowGenerator& generator, std::uint64_t bit, const ConvexPolygon& piece,
                    std::vector<MaskedFragment>& fragments) {
  std::vector<MaskedFragment> next;
  std::vector<Fragment> verdicts;
  for (const MaskedFragment& f : fragments) {
    verdicts.clear();
    generator.classify(f.polygon, verdicts);
    for (Fragment& v : verdicts) {
      next.push_back({std::move(v.polygon), f.lit_mask | (v.lit ? bit : 0)});
    }
  }
  merge_if_uniform(piece, next);
  fragments = std::move(next);
}

}  // namespace

std::vector<std::size_t> light_order(const Scene& scene) {
  std::vector<std::size_t> facing(scene.lights.size());
  for (std::size_t l = 0; l < facing.size(); ++l) {
    facing[l] = front_facing(scene, scene.lights[l]).polygons;
  }
  std::vector<std::size_t> order(scene.lights.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return facing[a] < facing[b]; });
  return order;
}

MultiLightFragments generate_multi_light_shadows(const SceneBsp& bsp, const Scene& scene,
                                                 bool merge_siblings) {
  if (scene.lights.size() > kMaxLights) {
    throw InputError(scene.name, "svbsp keeps one bit per light: at most " +
                                     std::to_string(kMaxLights) + " lights, not " +
                                     std::to_string(scene.lights.size()));
  }
  const std::span<const ConvexPolygon> pieces = bsp.pieces();
  // Fragments stay attached to the BSP piece they came from (§5), so each light can take
  // them in its own front-to-back order.
  std::vector<std::vector<MaskedFragment>> per_piece(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) per_piece[i].push_back({pieces[i], 0});

  MultiLightFragments result;
  std::vector<Fragment> single;
  for (const std::size_t l : light_order(scene)) {
    const Light& light = scene.lights[l];
    const std::uint64_t bit = std::uint64_t(1) << l;
    GeneratorSettings settings;
    settings.merge_siblings = merge_siblings;
    ShadowGenerator generator(scene, light, settings);
    generator.divide(pieces);
    bsp.front_to_back(light, [&](NodePieces node) {
      // Classified before the node's own volumes join the tree, as its pieces are.
      for (const ConvexPolygon& piece : node.pieces) {
        if (generator.in_light_plane(piece)) continue;  // shadowed: the bit stays clear
        split_by_light(generator, bit, piece, per_piece[std::size_t(&piece - pieces.data())]);
      }
      single.clear();
      generator.process(node, single);
    });
    LightPass pass{l, front_facing(scene, light), generator.tree().node_count(), 0};
    for (const auto& fragments : per_piece) pass.fragments += fragments.size();
    result.passes.push_back(pass);
  }
  for (auto& fragments : per_piece) {
    for (MaskedFragment& f : fragments) result.fragments.push_back(std::move(f));
  }
  return result;
}

}  // namespace shadowkit::svbsp
