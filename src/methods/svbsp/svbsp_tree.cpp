#include "svbsp_tree.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "shadowkit/core/error.h"

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

std::int32_t SvbspTree::chain(std::span<const ShadowPlane> planes, std::int32_t outside,
                              std::int32_t inside) {
  std::int32_t first = inside, last = -1;
  for (const ShadowPlane& s : planes) {
    const std::int32_t index = std::int32_t(nodes_.size());
    nodes_.push_back({s, outside, inside});
    if (last >= 0)
      nodes_[last].positive = index;
    else
      first = index;
    last = index;
  }
  return first;
}

// The shadow volume of a lit fragment as a chain of its shadow planes (buildSVBSPtree of
// Fig. 4 for a convex polygon).
std::int32_t SvbspTree::shadow_volume(const ConvexPolygon& p, std::int32_t outside,
                                      std::int32_t inside) {
  const Vec3 centre = centroid(p);
  const std::size_t n = p.vertices.size();
  absl::InlinedVector<ShadowPlane, ConvexPolygon::kInlineCorners> planes;
  bool undefined = false;
  for (std::size_t i = 0; i < n; ++i) {
    // §6: an edge in a plane that already bounds this cell needs no plane of its own.
    if (skip_edges_in_tree_ && p.edge_in_tree[i]) continue;
    ShadowPlane s;
    if (make_shadow_plane(light_, p.vertices[i], p.vertices[(i + 1) % n], centre, s)) {
      planes.push_back(s);
    } else {
      undefined = true;
    }
  }
  // Every edge on the cell's walls: the volume fills the cell. No plane at all because the
  // fragment is degenerate: it casts nothing.
  return planes.empty() && undefined ? outside : chain(planes, outside, inside);
}

SvbspTree::Verdict SvbspTree::verdict(const ConvexPolygon& p, std::int32_t leaf) const {
  const std::int32_t polygon = split_ ? split_->of_face[p.face] : -1;
  if (leaf == kOut) return {true, polygon < 0 ? kIn : shadow_of(polygon)};
  if (leaf == kIn) return {false, kIn};
  // In the shadow of one split polygon alone: lit if it is p's own, which adds no shadow
  // there; else shadowed, and in p's volume two polygons shadow, which matters only to that
  // polygon's pieces still to come.
  if (leaf == shadow_of(polygon)) return {true, leaf};
  return {false, pending_pieces_[std::size_t(kOut - 1 - leaf)] > 0 ? kIn : leaf};
}

void SvbspTree::enlarge_by_contour(std::vector<Landing> landings,
                                   std::span<const ShadowPlane> contour) {
  const auto leaf = [](const Landing& l) { return std::pair(l.parent, l.positive); };
  std::sort(landings.begin(), landings.end(),
            [&](const Landing& a, const Landing& b) { return leaf(a) < leaf(b); });
  const auto holds = [this](const Plane& plane, Vec3 a, Vec3 b) {
    return std::abs(plane.distance(a)) <= eps_ && std::abs(plane.distance(b)) <= eps_;
  };
  std::vector<char> used(contour.size());
  std::vector<ShadowPlane> walls;
  for (std::size_t i = 0; i < landings.size();) {
    std::fill(used.begin(), used.end(), 0);
    std::size_t end = i;
    for (; end < landings.size() && leaf(landings[end]) == leaf(landings[i]); ++end) {
      const ConvexPolygon& f = landings[end].fragment;
      const std::size_t n = f.vertices.size();
      for (std::size_t e = 0; e < n; ++e) {
        if (skip_edges_in_tree_ && f.edge_in_tree[e]) continue;  // §6: a wall of the cell
        for (std::size_t k = 0; k < contour.size(); ++k) {
          used[k] = used[k] || holds(contour[k].plane, f.vertices[e], f.vertices[(e + 1) % n]);
        }
      }
    }
    walls.clear();
    for (std::size_t k = 0; k < contour.size(); ++k) {
      if (used[k]) walls.push_back(contour[k]);
    }
    // No contour edge in the leaf: the silhouette's cone holds all of it.
    slot(landings[i].parent, landings[i].positive) = chain(walls);
    i = end;
  }
}

void SvbspTree::divide(const LightView& view, std::span<LightView::Coordinates> points,
                       std::size_t levels) {
  SHADOWKIT_CHECK(nodes_.empty() && root_ == kOut);
  root_ = cells(view, points, levels);
  cell_of_slot_.assign(2 * nodes_.size(), -1);
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n].negative == kOut) cell_of_slot_[2 * n] = std::int32_t(cell_count_++);
    if (nodes_[n].positive == kOut) cell_of_slot_[2 * n + 1] = std::int32_t(cell_count_++);
  }
}

std::int32_t SvbspTree::cells(const LightView& view, std::span<LightView::Coordinates> points,
                              std::size_t levels) {
  if (levels == 0 || points.size() < 2) return kOut;
  // The wider coordinate, cut at its median: halves of equal count.
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const LightView::Coordinates& c : points) {
    for (std::size_t k = 0; k < 2; ++k)
      lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
  }
  const std::size_t axis = hi[1] - lo[1] > hi[0] - lo[0] ? 1 : 0;
  const auto mid = points.begin() + std::ptrdiff_t(points.size() / 2);
  std::nth_element(points.begin(), mid, points.end(),
                   [axis](const auto& a, const auto& b) { return a[axis] < b[axis]; });
  const std::int32_t index = std::int32_t(nodes_.size());
  nodes_.push_back({{view.plane(int(axis), (*mid)[axis])}, kOut, kOut});
  const std::int32_t negative = cells(view, points.first(points.size() / 2), levels - 1);
  const std::int32_t positive = cells(view, points.subspan(points.size() / 2), levels - 1);
  nodes_[std::size_t(index)].negative = negative;
  nodes_[std::size_t(index)].positive = positive;
  return index;
}

std::int32_t& SvbspTree::slot(std::int32_t parent, bool positive) {
  return parent < 0 ? root_ : (positive ? nodes_[parent].positive : nodes_[parent].negative);
}

std::int32_t SvbspTree::slot(std::int32_t parent, bool positive) const {
  return parent < 0 ? root_ : (positive ? nodes_[parent].positive : nodes_[parent].negative);
}

std::int32_t SvbspTree::down_to_split(ConvexPolygon& p, std::int32_t& parent, bool& positive,
                                      ConvexPolygon& negative_part,
                                      ConvexPolygon& positive_part) const {
  // Within eps a point is near the plane; within in_plane, in it (kInPlaneShare).
  const double in_plane = eps_ * kInPlaneShare;
  std::int32_t at = slot(parent, positive);
  while (at >= 0) {
    const Plane& plane = nodes_[at].shadow_plane.plane;
    PlaneSides sides = svbsp::classify(p, plane, eps_);
    // Wholly near the plane is not in it: a grazing receiver is told by the finer tolerance.
    const double eps = sides.on() ? in_plane : eps_;
    if (sides.on()) sides = svbsp::classify(p, plane, eps);
    if (sides.spanning()) {
      split_polygon(p, plane, eps, in_plane, negative_part, positive_part);
      return at;
    }
    // On one side (within eps: positive), no copy.
    if (sides.touching) mark_edges_in_plane(p, plane, eps, in_plane);
    parent = at;
    positive = !sides.negative;
    at = slot(parent, positive);
  }
  return at;
}

void SvbspTree::route(ConvexPolygon p, std::int32_t parent, bool positive,
                      std::vector<RouteStep>& steps) const {
  ConvexPolygon negative_part, positive_part;
  const std::int32_t at = down_to_split(p, parent, positive, negative_part, positive_part);
  if (at >= 0) {
    steps.push_back({-1, std::move(p)});
    route(std::move(negative_part), at, false, steps);
    route(std::move(positive_part), at, true, steps);
    return;
  }
  SHADOWKIT_CHECK(at == kOut && parent >= 0);
  steps.push_back({cell_of_slot_[2 * std::size_t(parent) + positive], std::move(p)});
}

void SvbspTree::descend(ConvexPolygon p, std::int32_t parent, bool positive, const Sinks& sinks) {
  // Down the tree, splitting at the first node the piece spans (Fig. 4).
  ConvexPolygon negative_part, positive_part;
  const std::int32_t at = down_to_split(p, parent, positive, negative_part, positive_part);
  if (at >= 0) {
    // Spanning: each side in its own subtree; the tree may grow (and nodes_ move) meanwhile.
    std::vector<Fragment>* out = sinks.out;
    const std::size_t first = out ? out->size() : 0;
    descend(std::move(negative_part), at, false, sinks);
    descend(std::move(positive_part), at, true, sinks);
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
  const Verdict v = verdict(p, at);
  if (sinks.enlarge && v.inside != at) slot(parent, positive) = shadow_volume(p, at, v.inside);
  if (at == kOut && sinks.landings) sinks.landings->push_back({parent, positive, p});
  if (sinks.out) sinks.out->push_back({std::move(p), v.lit});
}

}  // namespace shadowkit::svbsp
