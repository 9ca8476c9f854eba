#include "projection_entries.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "bucket_sort.h"

namespace shadowkit::voxel {
namespace {

// Footprints grow by this fraction of an entry, against rounding at entry borders.
constexpr double kFootprintSlack = 1e-3;
// A voxel's footprint is capped at this radius (entries): only voxels within a few voxels
// of a point light reach it, and they would flood the plane.
constexpr double kMaxFootprint = 16;

// Calls \p add with every entry of \p face that [x0, x1] x [y0, y1] overlaps, or with
// \p corners_only its first and last entry only (enough for EntryRectangles). A cube face
// of a point light is only asked about entries 0..R: the rectangle is clipped to them.
template <typename Add>
void add_rectangle(const LightProjection& projection, int face, double x0, double x1, double y0,
                   double y1, Add&& add, bool corners_only = false) {
  if (projection.point_light()) {
    const double last = double(projection.resolution());
    x0 = std::max(x0, 0.0), y0 = std::max(y0, 0.0);
    x1 = std::min(x1, last), y1 = std::min(y1, last);
  }
  const auto entry = [&](double x, double y) {
    return LightProjection::entry(PlanePoint{face, x + 0.5, y + 0.5});
  };
  const double xa = std::floor(x0), xb = std::floor(x1), ya = std::floor(y0), yb = std::floor(y1);
  if (corners_only) {
    if (xa <= xb && ya <= yb) add(entry(xa, ya)), add(entry(xb, yb));
    return;
  }
  for (double y = ya; y <= yb; ++y) {
    for (double x = xa; x <= xb; ++x) add(entry(x, y));
  }
}

// Calls \p add with every entry of \p face that \p leaf's projected corners' box overlaps;
// a corner behind the face's plane (a subpatch within a voxel of the light) leaves the
// face out.
template <typename Add>
void add_footprint(const LightProjection& projection, const Subpatch& leaf, int face, Add&& add) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const GridPoint& c : leaf.corner) {
    const auto q = projection.project_on(face, c.vec());
    if (!q) return;
    x0 = std::min(x0, q->x), x1 = std::max(x1, q->x);
    y0 = std::min(y0, q->y), y1 = std::max(y1, q->y);
  }
  add_rectangle(projection, face, x0 - kFootprintSlack, x1 + kFootprintSlack, y0 - kFootprintSlack,
                y1 + kFootprintSlack, add);
}

// Every entry \p leaf is listed in: its footprint on the face of each of its corners.
template <typename Add>
void add_leaf_entries(const LightProjection& projection, const Subpatch& leaf, Add&& add) {
  int faces[4], face_count = 0;
  for (const GridPoint& c : leaf.corner) {
    const int face = projection.project(c.vec()).face;
    if (std::find(faces, faces + face_count, face) == faces + face_count)
      faces[face_count++] = face;
  }
  for (int f = 0; f < face_count; ++f) add_footprint(projection, leaf, faces[f], add);
}

// The rectangles of the entries that \p for_each_entry(i, add) gives for items 0..n-1.
template <typename ForEachEntry>
EntryRectangles rectangles_of(std::size_t n, const ForEachEntry& for_each_entry) {
  tbb::enumerable_thread_specific<EntryRectangles> parts;
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    EntryRectangles& part = parts.local();
    for_each_entry(i, [&](std::uint64_t entry) { part.include(entry); });
  });
  EntryRectangles all;
  for (const EntryRectangles& part : parts) all.include(part);
  all.finish();
  return all;
}

void atomic_min(float& slot, float value) {
  std::atomic_ref<float> ref(slot);
  float current = ref.load(std::memory_order_relaxed);
  while (value < current && !ref.compare_exchange_weak(current, value, std::memory_order_relaxed)) {
  }
}

}  // namespace

void EntryRectangles::include(std::uint64_t entry) {
  const auto [face, x, y] = LightProjection::cell(entry);
  Rectangle& r = faces_[std::size_t(std::clamp(face, 0, kFaces - 1))];
  r.x0 = std::min(r.x0, x), r.x1 = std::max(r.x1, x);
  r.y0 = std::min(r.y0, y), r.y1 = std::max(r.y1, y);
}

void EntryRectangles::include(const EntryRectangles& other) {
  for (int f = 0; f < kFaces; ++f) {
    Rectangle& r = faces_[f];
    const Rectangle& o = other.faces_[f];
    r.x0 = std::min(r.x0, o.x0), r.x1 = std::max(r.x1, o.x1);
    r.y0 = std::min(r.y0, o.y0), r.y1 = std::max(r.y1, o.y1);
  }
}

void EntryRectangles::finish() {
  size_ = 0;
  for (Rectangle& r : faces_) {
    r.first = size_;
    if (!r.empty()) size_ += (r.x1 - r.x0 + 1) * (r.y1 - r.y0 + 1);
  }
}

std::optional<std::size_t> EntryRectangles::index(std::uint64_t entry) const {
  const auto [face, x, y] = LightProjection::cell(entry);
  if (face < 0 || face >= kFaces) return std::nullopt;
  const Rectangle& r = faces_[std::size_t(face)];
  if (r.empty() || x < r.x0 || x > r.x1 || y < r.y0 || y > r.y1) return std::nullopt;
  return r.first + (y - r.y0) * (r.x1 - r.x0 + 1) + (x - r.x0);
}

NearestVoxels::NearestVoxels(const LightProjection& projection, std::size_t parts,
                             const VoxelCentres& centres, double footprint) {
  const auto for_each_footprint = [&](Vec3 centre, auto&& add, bool corners_only) {
    const PlanePoint q = projection.project(centre);
    const double radius = std::min(projection.entry_width(centre) * footprint, kMaxFootprint);
    add_rectangle(projection, q.face, q.x - radius, q.x + radius, q.y - radius, q.y + radius, add,
                  corners_only);
  };
  rectangles_ = rectangles_of(parts, [&](std::size_t part, auto&& add) {
    centres(part, [&](Vec3 centre) { for_each_footprint(centre, add, true); });
  });
  nearest_.assign(rectangles_.size(), std::numeric_limits<float>::infinity());
  tbb::parallel_for(std::size_t(0), parts, [&](std::size_t part) {
    centres(part, [&](Vec3 centre) {
      const float distance = float(projection.distance(centre));
      for_each_footprint(
          centre,
          [&](std::uint64_t entry) { atomic_min(nearest_[*rectangles_.index(entry)], distance); },
          false);
    });
  });
  entry_count_ = std::size_t(
      std::count_if(nearest_.begin(), nearest_.end(), [](float d) { return std::isfinite(d); }));
}

std::optional<float> NearestVoxels::nearest(std::uint64_t entry) const {
  const auto index = rectangles_.index(entry);
  if (!index || !std::isfinite(nearest_[*index])) return std::nullopt;
  return nearest_[*index];
}

BlockingSubpatches::BlockingSubpatches(const LightProjection& projection,
                                       const std::vector<Subpatch>& leaves) {
  std::vector<float> distances(leaves.size());
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t l) {
    float distance = std::numeric_limits<float>::max();
    for (const GridPoint& c : leaves[l].corner) {
      distance = std::min(distance, float(projection.distance(c.vec())));
    }
    distances[l] = distance;
  });
  const auto for_each_entry = [&](std::size_t l, auto&& add) {
    add_leaf_entries(projection, leaves[l], add);
  };
  rectangles_ = rectangles_of(leaves.size(), for_each_entry);
  // Per entry, nearest first.
  bucket_sort<Record>(
      rectangles_.size(), leaves.size(),
      [&](std::size_t l, auto&& emit) {
        for_each_entry(l, [&](std::uint64_t entry) {
          emit(*rectangles_.index(entry), Record{distances[l], std::uint32_t(l)});
        });
      },
      first_, records_);
}

std::span<const BlockingSubpatches::Record> BlockingSubpatches::list(std::uint64_t entry) const {
  const auto index = rectangles_.index(entry);
  if (!index) return {};
  return {records_.data() + first_[*index], records_.data() + first_[*index + 1]};
}

}  // namespace shadowkit::voxel
