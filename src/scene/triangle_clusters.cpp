#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cstdint>
#include <utility>

#include "shadowkit/scene/scene.h"

namespace shadowkit {
namespace {

// 10 bits of each coordinate, interleaved: z y x z y x ... from the top.
std::uint32_t spread_bits(std::uint32_t v) {
  v = (v | (v << 16)) & 0x030000FFu;
  v = (v | (v << 8)) & 0x0300F00Fu;
  v = (v | (v << 4)) & 0x030C30C3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

std::uint32_t morton_code(Vec3 p, const Bounds3& box) {
  const Vec3 e = box.extent();
  const auto cell = [](double t, double lo, double extent) {
    const double u = extent > 0 ? (t - lo) / extent : 0.0;
    return std::uint32_t(std::clamp(u * 1024.0, 0.0, 1023.0));
  };
  return spread_bits(cell(p.x, box.lo.x, e.x)) | spread_bits(cell(p.y, box.lo.y, e.y)) << 1 |
         spread_bits(cell(p.z, box.lo.z, e.z)) << 2;
}

Vec3 centroid(const TriangleList& list, std::uint32_t t) {
  const auto& [a, b, c] = list.triangles[t];
  return (list.positions[a] + list.positions[b] + list.positions[c]) * (1.0 / 3.0);
}

}  // namespace

TriangleClusters cluster_triangles(const TriangleList& list, const Bounds3& bounds) {
  const std::size_t n = list.triangles.size();
  // Ties in the code keep triangle order, so the clusters do not depend on the sort.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t t) {
    keyed[t] = {morton_code(centroid(list, std::uint32_t(t)), bounds), std::uint32_t(t)};
  });
  tbb::parallel_sort(keyed.begin(), keyed.end());

  TriangleClusters out;
  out.corners.assign(n, {});  // not resize(n): GCC 12 sees a null pointer in that, wrongly
  out.faces.resize(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    out.corners[i] = list.triangles[keyed[i].second];
    out.faces[i] = list.triangle_face[keyed[i].second];
  });
  out.bounds.resize((n + TriangleClusters::kSize - 1) / TriangleClusters::kSize);
  tbb::parallel_for(std::size_t(0), out.bounds.size(), [&](std::size_t c) {
    const auto [first, last] = out.entries(c);
    for (std::uint32_t e = first; e < last; ++e) {
      for (const std::uint32_t v : out.corners[e]) out.bounds[c].add(list.positions[v]);
    }
  });
  return out;
}

}  // namespace shadowkit
