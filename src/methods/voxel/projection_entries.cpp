#include "projection_entries.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace shadowkit::voxel {
namespace {

// Footprints grow by this fraction of an entry, against rounding at entry borders.
constexpr double kFootprintSlack = 1e-3;
// A voxel's footprint is capped at this radius (entries): only voxels within a few voxels
// of a point light reach it, and they would flood the plane.
constexpr double kMaxFootprint = 16;

// Calls \p add with every entry of \p face that [x0, x1] x [y0, y1] overlaps.
template <typename Add>
void add_rectangle(int face, double x0, double x1, double y0, double y1, Add&& add) {
  for (double y = std::floor(y0); y <= std::floor(y1); ++y) {
    for (double x = std::floor(x0); x <= std::floor(x1); ++x) {
      add(LightProjection::entry(PlanePoint{face, x + 0.5, y + 0.5}));
    }
  }
}

// Adds \p leaf to every entry of \p face its projected corners' box overlaps; a corner
// behind the face's plane (a subpatch within a voxel of the light) leaves the face out.
void add_footprint(const LightProjection& projection, const Subpatch& leaf, std::uint32_t id,
                   int face, float distance, std::vector<BlockingSubpatches::Record>& out) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const GridPoint& c : leaf.corner) {
    const auto q = projection.project_on(face, c.vec());
    if (!q) return;
    x0 = std::min(x0, q->x), x1 = std::max(x1, q->x);
    y0 = std::min(y0, q->y), y1 = std::max(y1, q->y);
  }
  add_rectangle(face, x0 - kFootprintSlack, x1 + kFootprintSlack, y0 - kFootprintSlack,
                y1 + kFootprintSlack, [&](std::uint64_t entry) {
                  out.push_back({entry, distance, id});
                });
}

}  // namespace

NearestVoxels::NearestVoxels(const LightProjection& projection, const std::vector<Vec3>& centres,
                             const std::vector<float>& distances, double footprint) {
  using Pair = std::pair<std::uint64_t, float>;
  tbb::enumerable_thread_specific<std::vector<Pair>> parts;
  tbb::parallel_for(std::size_t(0), centres.size(), [&](std::size_t i) {
    const PlanePoint q = projection.project(centres[i]);
    const double radius = std::min(projection.entry_width(centres[i]) * footprint, kMaxFootprint);
    auto& out = parts.local();
    add_rectangle(q.face, q.x - radius, q.x + radius, q.y - radius, q.y + radius,
                  [&](std::uint64_t entry) {
                    out.push_back({entry, distances[i]});
                  });
  });
  std::vector<Pair> pairs;
  for (auto& part : parts) pairs.insert(pairs.end(), part.begin(), part.end());
  tbb::parallel_sort(pairs.begin(), pairs.end());
  for (const auto& [entry, distance] : pairs) {
    if (!entries_.empty() && entries_.back() == entry) continue;  // the first is the nearest
    entries_.push_back(entry);
    nearest_.push_back(distance);
  }
}

std::optional<float> NearestVoxels::nearest(std::uint64_t entry) const {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), entry);
  if (it == entries_.end() || *it != entry) return std::nullopt;
  return nearest_[std::size_t(it - entries_.begin())];
}

BlockingSubpatches::BlockingSubpatches(const LightProjection& projection,
                                       const std::vector<Subpatch>& leaves) {
  tbb::enumerable_thread_specific<std::vector<Record>> parts;
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t l) {
    const Subpatch& leaf = leaves[l];
    auto& out = parts.local();
    float distance = std::numeric_limits<float>::max();
    int faces[4], face_count = 0;
    for (const GridPoint& c : leaf.corner) {
      distance = std::min(distance, float(projection.distance(c.vec())));
      const int face = projection.project(c.vec()).face;
      if (std::find(faces, faces + face_count, face) == faces + face_count)
        faces[face_count++] = face;
    }
    for (int f = 0; f < face_count; ++f) {
      add_footprint(projection, leaf, std::uint32_t(l), faces[f], distance, out);
    }
  });
  for (auto& part : parts) records_.insert(records_.end(), part.begin(), part.end());
  tbb::parallel_sort(records_.begin(), records_.end());
}

std::span<const BlockingSubpatches::Record> BlockingSubpatches::list(std::uint64_t entry) const {
  const auto lo = std::lower_bound(records_.begin(), records_.end(), entry,
                                   [](const Record& r, std::uint64_t e) { return r.entry < e; });
  auto hi = lo;
  while (hi != records_.end() && hi->entry == entry) ++hi;
  return {lo, hi};
}

}  // namespace shadowkit::voxel
