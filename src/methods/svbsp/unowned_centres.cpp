#include "unowned_centres.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace shadowkit::svbsp {
namespace {

// How deep \p point lies inside convex \p polygon, in its plane: the least distance to the
// lines of its edges, negative outside.
double depth_inside(const ConvexPolygon& polygon, Vec3 point) {
  const auto& v = polygon.vertices;
  Vec3 normal;  // the polygon's own winding, whichever way its face turns
  for (std::size_t i = 1; i + 1 < v.size(); ++i) normal += cross(v[i] - v[0], v[i + 1] - v[0]);
  const double area2 = length(normal);
  if (area2 == 0) return -std::numeric_limits<double>::infinity();
  double depth = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 edge = v[(i + 1) % v.size()] - v[i];
    const double len = length(edge);
    if (len == 0) continue;
    depth = std::min(depth, dot(cross(edge, point - v[i]), normal) / (len * area2));
  }
  return depth;
}

// The verdict the neighbours of pixel \p i owned by fragments of its face agree on, if they
// do: the crack a snapped cut point leaves is less than a pixel wide.
std::optional<std::uint8_t> neighbours_verdict(const VisibleSurfaceBuffer& surfaces,
                                               const ShadowMask& mask, std::size_t i) {
  const int x = int(i % std::size_t(surfaces.width)), y = int(i / std::size_t(surfaces.width));
  bool lit = false, shadowed = false;
  for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, surfaces.height - 1); ++ny) {
    for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, surfaces.width - 1); ++nx) {
      const std::size_t j = surfaces.index(nx, ny);
      if (surfaces.face[j] != surfaces.face[i]) continue;
      lit = lit || mask.pixels[j] == kMaskLit;
      shadowed = shadowed || mask.pixels[j] == kMaskShadow;
    }
  }
  if (lit == shadowed) return std::nullopt;
  return lit ? kMaskLit : kMaskShadow;
}

// The covered pixels still owned by none, rows in parallel.
std::vector<std::size_t> unowned_pixels(const ShadowMask& mask) {
  tbb::combinable<std::vector<std::size_t>> found;
  tbb::parallel_for(tbb::blocked_range<int>(0, mask.height, 16), [&](const auto& rows) {
    const auto row = [&](int y) { return mask.pixels.begin() + std::ptrdiff_t(y) * mask.width; };
    const auto end = row(rows.end());
    for (auto at = std::find(row(rows.begin()), end, kUnowned); at != end;
         at = std::find(at + 1, end, kUnowned)) {
      found.local().push_back(std::size_t(at - mask.pixels.begin()));
    }
  });
  std::vector<std::size_t> all;
  found.combine_each([&](const auto& part) { all.insert(all.end(), part.begin(), part.end()); });
  return all;
}

// An unowned centre its neighbours do not decide, and the fragment of its face found so far
// to hold its visible point deepest.
struct Pending {
  std::size_t unowned;  ///< its index among the unowned centres
  std::uint32_t face;
  Vec3 point;
  double reach;  ///< how far off a fragment's box the point may be and still be nearest it
  double deepest = -std::numeric_limits<double>::infinity();
  std::uint8_t verdict = kMaskShadow;
};

// Whether \p point lies within \p reach of the box of \p polygon.
bool near_box(const ConvexPolygon& polygon, Vec3 point, double reach) {
  Vec3 lo = polygon.vertices[0], hi = lo;
  for (const Vec3& v : polygon.vertices) lo = min(lo, v), hi = max(hi, v);
  return point.x >= lo.x - reach && point.x <= hi.x + reach && point.y >= lo.y - reach &&
         point.y <= hi.y + reach && point.z >= lo.z - reach && point.z <= hi.z + reach;
}

// Decides each of \p pending by the fragment of its face holding its visible point deepest:
// one pass over \p candidates (which hold every fragment of its face), each fragment tried
// only against the points near its box when \p near_only.
void deepest_fragments(const std::vector<Fragment>& fragments,
                       std::span<const std::uint32_t> candidates, std::uint32_t faces,
                       std::vector<Pending>& pending, bool near_only) {
  std::vector<std::uint32_t> first(std::size_t(faces) + 1, 0);  // pending by face
  for (const Pending& p : pending) ++first[p.face + 1];
  for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
  std::sort(pending.begin(), pending.end(),
            [](const Pending& a, const Pending& b) { return a.face < b.face; });
  for (const std::uint32_t c : candidates) {
    const Fragment& f = fragments[c];
    const std::uint32_t face = f.polygon.face;
    for (std::uint32_t k = first[face]; k < first[face + 1]; ++k) {
      Pending& p = pending[k];
      if (near_only && !near_box(f.polygon, p.point, p.reach)) continue;
      const double depth = depth_inside(f.polygon, p.point);
      if (depth > p.deepest) p.deepest = depth, p.verdict = f.lit ? kMaskLit : kMaskShadow;
    }
  }
}

}  // namespace

void resolve_unowned(const Scene& scene, const std::vector<Fragment>& fragments,
                     std::span<const std::uint32_t> candidates,
                     const VisibleSurfaceBuffer& surfaces, ShadowMask& mask) {
  const std::vector<std::size_t> unowned = unowned_pixels(mask);
  std::vector<std::uint8_t> verdicts(unowned.size(), kMaskShadow);
  std::vector<Pending> pending;
  const double step = scene.camera.pixel_grid().step;
  for (std::size_t k = 0; k < unowned.size(); ++k) {
    const std::size_t i = unowned[k];
    if (const auto verdict = neighbours_verdict(surfaces, mask, i)) {
      verdicts[k] = *verdict;
      continue;
    }
    // The point may lie off its face by the snapping, a fraction of a pixel, stretched
    // where the face is seen at a grazing angle.
    const Vec3 ray = surfaces.ray(i);
    const double cosine = std::abs(dot(ray, surfaces.plane(i).normal)) / length(ray);
    const double reach = 2 * surfaces.depth[i] * step / std::max(cosine, 1e-3);
    pending.push_back({k, surfaces.face[i], surfaces.point(i), reach});
  }
  if (!pending.empty()) {
    deepest_fragments(fragments, candidates, scene.face_count(), pending, true);
    std::vector<Pending> unplaced;  // near no fragment's box: all of its face's fragments
    for (const Pending& p : pending) {
      if (p.deepest == -std::numeric_limits<double>::infinity()) unplaced.push_back(p);
    }
    if (!unplaced.empty())
      deepest_fragments(fragments, candidates, scene.face_count(), unplaced, false);
    for (const std::vector<Pending>* list : {&pending, &unplaced}) {
      for (const Pending& p : *list) verdicts[p.unowned] = p.verdict;
    }
  }
  for (std::size_t k = 0; k < unowned.size(); ++k) mask.pixels[unowned[k]] = verdicts[k];
}

}  // namespace shadowkit::svbsp
