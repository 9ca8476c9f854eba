#include "face_setup.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <span>

#include "shadowkit/core/error.h"

namespace shadowkit::shadowmap {
namespace {

using raster::FixedPoint;
using raster::kSubpixel;
using raster::kSubpixelBits;
using raster::ScreenTriangle;

constexpr int kFaceBits = 5;
constexpr std::uint32_t kFaceMask = (1u << kFaceBits) - 1;
constexpr std::size_t kChunk = 2048;

std::uint32_t pyramid_outside(const RasterProjection& view, Vec3 d) {
  const Vec3 v = AxisFrame(view).to_view(d);
  return std::uint32_t(v.z < view.near) | std::uint32_t(v.x > v.z) << 1 |
         std::uint32_t(-v.x > v.z) << 2 | std::uint32_t(v.y > v.z) << 3 |
         std::uint32_t(-v.y > v.z) << 4;
}

// raster::setup_triangles' snapping of a view-space point to fixed point.
FixedPoint to_fixed(const RasterProjection& view, Vec3 v) {
  return {std::llround(view.pixel_x(v) * double(kSubpixel)),
          std::llround(view.pixel_y(v) * double(kSubpixel))};
}

// Inside raster::setup_triangles' clip volume with a margin of half its guard band, so that
// its own tests, rounded as they are, agree: such a vertex is set up unclipped there too.
bool well_inside(const RasterProjection& view, Vec3 v) {
  const double reach = 1 + 0.5 * raster::kGuardBand / std::max(view.scale_x, view.scale_y);
  return v.z >= view.near && std::abs(v.x) <= reach * v.z && std::abs(v.y) <= reach * v.z;
}

// The depth-key plane of a face in a perspective view, as raster::setup_triangles computes
// it: key = a px + b py + c at pixel (px, py). False for a plane through the eye (edge-on).
bool key_plane(const Plane& plane, const RasterProjection& p, ScreenTriangle& t) {
  const Vec3 n{dot(plane.normal, p.right), dot(plane.normal, p.up), dot(plane.normal, p.forward)};
  const double dv = plane.distance(p.eye);
  if (dv == 0) return false;
  t.key_a = -n.x / (p.scale_x * dv);
  t.key_b = n.y / (p.scale_y * dv);
  t.key_c = (n.x * p.offset_x / p.scale_x - n.y * p.offset_y / p.scale_y - n.z) / dv;
  t.key_c += 0.5 * (t.key_a + t.key_b);  // sampled at pixel centres
  return true;
}

// Appends the screen triangle (v0, v1, v2) with the depth plane of \p key, as the scan
// converter's setup does: positively oriented, the top-left rule in the edge biases, pixel
// bounds clamped to the raster; nothing if it has no area or misses the raster.
void emit(FixedPoint v0, FixedPoint v1, FixedPoint v2, const ScreenTriangle& key,
          const RasterProjection& view, std::vector<ScreenTriangle>& out) {
  const std::int64_t area = (v1.x - v0.x) * (v2.y - v0.y) - (v1.y - v0.y) * (v2.x - v0.x);
  if (area == 0) return;
  if (area < 0) std::swap(v1, v2);
  ScreenTriangle t = key;
  const FixedPoint v[3] = {v0, v1, v2};
  for (int i = 0; i < 3; ++i) {
    t.x[i] = v[i].x;
    t.y[i] = v[i].y;
    const FixedPoint d{v[(i + 1) % 3].x - v[i].x, v[(i + 1) % 3].y - v[i].y};
    t.bias[i] = (d.y < 0 || (d.y == 0 && d.x > 0)) ? 0 : 1;
  }
  const auto lo = [](std::int64_t a) {
    return int((a - kSubpixel / 2 + kSubpixel - 1) >> kSubpixelBits);
  };
  const auto hi = [](std::int64_t a) { return int((a - kSubpixel / 2) >> kSubpixelBits); };
  t.min_x = std::max(0, lo(std::min({v0.x, v1.x, v2.x})));
  t.min_y = std::max(0, lo(std::min({v0.y, v1.y, v2.y})));
  t.max_x = std::min(view.width - 1, hi(std::max({v0.x, v1.x, v2.x})));
  t.max_y = std::min(view.height - 1, hi(std::max({v0.y, v1.y, v2.y})));
  if (t.min_x > t.max_x || t.min_y > t.max_y) return;
  out.push_back(t);
}

}  // namespace

AxisFrame::AxisFrame(const RasterProjection& view) {
  const Vec3 axes[3] = {view.right, view.up, view.forward};
  for (int k = 0; k < 3; ++k) {
    index_[k] = axes[k].x != 0 ? 0 : (axes[k].y != 0 ? 1 : 2);
    sign_[k] = axes[k][index_[k]];
  }
}

FaceCulling::FaceCulling(const Scene& scene, std::span<const RasterProjection> views)
    : scene_(scene), outside_(scene.triangles().positions.size()) {
  SHADOWKIT_CHECK(views.size() * kFaceBits <= 32);
  const std::vector<Vec3>& positions = scene.triangles().positions;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, positions.size(), 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      std::uint32_t bits = 0;
      for (std::size_t f = 0; f < views.size(); ++f) {
        bits |= pyramid_outside(views[f], positions[i] - views[f].eye) << (kFaceBits * f);
      }
      outside_[i] = bits;
    }
  });
}

bool FaceCulling::reaches(std::size_t t, int face) const {
  const auto& tri = scene_.triangles().triangles[t];
  const std::uint32_t all = outside_[tri[0]] & outside_[tri[1]] & outside_[tri[2]];
  return ((all >> (kFaceBits * face)) & kFaceMask) == 0;
}

void FaceSetup::run(const Scene& scene, const FaceCulling& culling, int face,
                    const RasterProjection& view) {
  const TriangleList& list = scene.triangles();
  const std::size_t nv = list.positions.size(), nt = list.triangles.size();
  const std::size_t chunk_count = (nt + kChunk - 1) / kChunk;

  // The triangles that reach the face, and the vertices they use.
  reaching_.resize(chunk_count);
  used_.assign(nv, 0);
  tbb::parallel_for(std::size_t(0), chunk_count, [&](std::size_t c) {
    reaching_[c].clear();
    for (std::size_t t = c * kChunk; t < std::min(nt, (c + 1) * kChunk); ++t) {
      if (!culling.reaches(t, face)) continue;
      reaching_[c].push_back(std::uint32_t(t));
      // Several threads may store the same value here.
      for (const std::uint32_t v : list.triangles[t]) {
        std::atomic_ref<std::uint8_t>(used_[v]).store(1, std::memory_order_relaxed);
      }
    }
  });

  // Per used vertex, once: whether it is well inside the clip volume, and if so its
  // fixed-point position, so that every triangle sharing it snaps it identically.
  inside_.resize(nv);
  fixed_.resize(nv);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      if (!used_[i]) continue;
      const Vec3 v = view.to_view(list.positions[i]);
      inside_[i] = well_inside(view, v);
      if (inside_[i]) fixed_[i] = to_fixed(view, v);
    }
  });

  chunks_.resize(chunk_count);
  tbb::parallel_for(std::size_t(0), chunk_count, [&](std::size_t c) {
    std::vector<ScreenTriangle>& out = chunks_[c];
    out.clear();
    for (const std::uint32_t t : reaching_[c]) {
      ScreenTriangle key{};
      if (!key_plane(scene.face_plane(list.triangle_face[t]), view, key)) continue;
      key.face = list.triangle_face[t];
      const auto& tri = list.triangles[t];
      if (inside_[tri[0]] && inside_[tri[1]] && inside_[tri[2]]) {
        emit(fixed_[tri[0]], fixed_[tri[1]], fixed_[tri[2]], key, view, out);
        continue;
      }
      // Near the light or far past the face's edges: the scan converter's own clipping.
      const raster::HomogeneousPoint corners[3] = {
          {list.positions[tri[0]], 1}, {list.positions[tri[1]], 1}, {list.positions[tri[2]], 1}};
      const std::vector<FixedPoint> polygon = raster::snapped_polygon(corners, view);
      for (std::size_t i = 2; i < polygon.size(); ++i) {
        emit(polygon[0], polygon[i - 1], polygon[i], key, view, out);
      }
    }
  });

  // The chunks one after another, copied in parallel.
  std::vector<std::size_t> offset(chunk_count + 1, 0);
  for (std::size_t c = 0; c < chunk_count; ++c) offset[c + 1] = offset[c] + chunks_[c].size();
  triangles_.resize(offset.back());
  tbb::parallel_for(std::size_t(0), chunk_count, [&](std::size_t c) {
    std::copy(chunks_[c].begin(), chunks_[c].end(), triangles_.begin() + std::ptrdiff_t(offset[c]));
  });
}

std::size_t FaceSetup::memory_bytes() const {
  std::size_t n = used_.capacity() + inside_.capacity() + fixed_.capacity() * sizeof(FixedPoint) +
                  triangles_.capacity() * sizeof(ScreenTriangle);
  for (const auto& r : reaching_) n += r.capacity() * sizeof(std::uint32_t);
  for (const auto& c : chunks_) n += c.capacity() * sizeof(ScreenTriangle);
  return n;
}

}  // namespace shadowkit::shadowmap
