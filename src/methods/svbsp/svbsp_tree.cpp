#include "svbsp_tree.h"

#include <cmath>
#include <utility>

namespace shadowkit::svbsp {

bool make_shadow_plane(const Light& light, Vec3 a, Vec3 b, Vec3 inside, ShadowPlane& out) {
  const bool point = light.type == Light::Type::point;
  const Vec3 n =
      point ? cross(a - light.position, b - light.position) : cross(b - a, light.direction);
  const double len = length(n);
  // Hazard: an edge (nearly) aligned with the light ray has no plane; its polygon is seen
  // edge-on and the neighbouring edges' planes close the volume.
  const double scale =
      point ? length(a - light.position) * length(b - light.position) : length(b - a);
  if (!(len > 1e-12 * scale)) return false;
  Plane plane{n / len, 0};
  plane.d = -dot(plane.normal, a);
  if (plane.distance(inside) < 0) plane = {-plane.normal, -plane.d};
  out.plane = plane;
  return true;
}

// The shadow volume of a lit fragment as a chain of its shadow planes (buildSVBSPtree of
// Fig. 4 for a convex polygon): outside any plane is OUT, inside all of them IN.
std::int32_t SvbspTree::shadow_volume(const ConvexPolygon& p) {
  Vec3 centroid;
  for (const Vec3& v : p.vertices) centroid += v;
  centroid = centroid / double(p.vertices.size());
  const std::size_t n = p.vertices.size();
  std::int32_t first = kIn, last = -1;
  bool undefined = false;
  for (std::size_t i = 0; i < n; ++i) {
    // §6: an edge in a plane that already bounds this cell needs no plane of its own.
    if (p.edge_in_tree[i]) continue;
    ShadowPlane s;
    if (!make_shadow_plane(light_, p.vertices[i], p.vertices[(i + 1) % n], centroid, s)) {
      undefined = true;
      continue;
    }
    const std::int32_t index = std::int32_t(nodes_.size());
    nodes_.push_back({s, kOut, kIn});
    if (last >= 0)
      nodes_[last].positive = index;
    else
      first = index;
    last = index;
  }
  // Every edge on the cell's walls: the volume fills the cell. No plane at all because the
  // fragment is degenerate: it casts nothing.
  return first == kIn && undefined ? kOut : first;
}

void SvbspTree::filter(const ConvexPolygon& p, std::vector<Fragment>* out, bool enlarge) {
  descend(p, -1, false, out, enlarge);
}

void SvbspTree::descend(ConvexPolygon p, std::int32_t parent, bool positive,
                        std::vector<Fragment>* out, bool enlarge) {
  const auto slot = [&](std::int32_t node, bool pos) -> std::int32_t& {
    return node < 0 ? root_ : (pos ? nodes_[node].positive : nodes_[node].negative);
  };
  std::int32_t at = slot(parent, positive);
  ConvexPolygon negative_part, positive_part;
  // Down the tree, splitting at each node the piece spans (Fig. 4).
  while (at >= 0) {
    const Plane& plane = nodes_[at].shadow_plane.plane;
    const PlaneSides sides = svbsp::classify(p, plane, eps_);
    if (!sides.touching && !sides.spanning()) {  // wholly on one side: no copy
      parent = at;
      positive = sides.positive;
      at = sides.positive ? nodes_[at].positive : nodes_[at].negative;
      continue;
    }
    split_polygon(p, plane, eps_, true, negative_part, positive_part);
    const bool has_neg = !negative_part.vertices.empty();
    const bool has_pos = !positive_part.vertices.empty();
    if (has_neg && has_pos) {
      // Each side in its own subtree; the tree may grow (and nodes_ move) meanwhile.
      const std::size_t first = out ? out->size() : 0;
      const std::int32_t node = at;
      descend(std::move(negative_part), node, false, out, enlarge);
      descend(std::move(positive_part), node, true, out, enlarge);
      // §6: two sibling fragments in the same state are the polygon before the split. The
      // pieces are exactly its halves (the cut shares its points), so no area changes; the
      // verdicts and the tree are those of the halves.
      if (merge_siblings_ && out && out->size() == first + 2 &&
          (*out)[first].lit == (*out)[first + 1].lit) {
        (*out)[first].polygon = std::move(p);
        out->pop_back();
      }
      return;
    }
    p = std::move(has_pos ? positive_part : negative_part);
    parent = at;
    positive = has_pos;
    at = has_pos ? nodes_[at].positive : nodes_[at].negative;
  }
  const bool lit = at == kOut;
  if (lit && enlarge) {
    const std::int32_t volume = shadow_volume(p);
    slot(parent, positive) = volume;
  }
  if (out) out->push_back({std::move(p), lit});
}

}  // namespace shadowkit::svbsp
