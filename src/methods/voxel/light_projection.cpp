#include "light_projection.h"

#include <algorithm>
#include <cmath>

namespace shadowkit::voxel {
namespace {

// Entry coordinates are stored in 29 bits each, centred for the orthographic plane.
constexpr long kEntryBits = 29;
constexpr long kEntryOffset = 1L << (kEntryBits - 1);
constexpr long kMaxResolution = 1L << 24;

int axis_of(int face) {
  return face / 2;
}
double sign_of(int face) {
  return face % 2 ? -1.0 : 1.0;
}

}  // namespace

LightProjection::LightProjection(const Light& light, const VoxelGrid& grid,
                                 double entries_per_voxel)
    : point_(light.type == Light::Type::point) {
  const Vec3 dims{double(grid.dims[0]), double(grid.dims[1]), double(grid.dims[2])};
  reach_ = 2 * length(dims) + 2;
  if (point_) {
    light_ = grid.to_grid(light.position);
    const double distance = std::max(length(dims * 0.5 - light_), 0.25 * length(dims));
    // A cube face spans [-1, 1] at unit distance: 2 d / R is an entry's width at distance d.
    resolution_ =
        std::clamp(long(std::ceil(2 * distance * entries_per_voxel)), 16L, kMaxResolution);
    return;
  }
  light_ = light.direction;
  const Vec3 d = light.direction;
  const Vec3 hint = std::abs(d.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  right_ = normalize(cross(d, hint));
  up_ = cross(right_, d) * entries_per_voxel;
  right_ = right_ * entries_per_voxel;
}

std::optional<PlanePoint> LightProjection::project_on(int face, Vec3 p) const {
  if (!point_) return PlanePoint{0, dot(p, right_), dot(p, up_)};
  const Vec3 w = p - light_;
  const int a = axis_of(face);
  const double depth = w[a] * sign_of(face);
  if (!(depth > 0)) return std::nullopt;
  const double x = w[(a + 1) % 3] / depth, y = w[(a + 2) % 3] / depth;
  return PlanePoint{face, (x + 1) * 0.5 * double(resolution_), (y + 1) * 0.5 * double(resolution_)};
}

PlanePoint LightProjection::project(Vec3 p) const {
  if (!point_) return *project_on(0, p);
  const Vec3 w = p - light_;
  int a = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(w[k]) > std::abs(w[a])) a = k;
  }
  // The light itself projects nowhere in particular: face +x, centre.
  return project_on(2 * a + (w[a] < 0), p)
      .value_or(PlanePoint{0, 0.5 * double(resolution_), 0.5 * double(resolution_)});
}

std::uint64_t LightProjection::entry(const PlanePoint& q) {
  const auto index = [](double c) {
    return std::uint64_t(std::clamp(long(std::floor(std::clamp(c, -1e15, 1e15))) + kEntryOffset, 0L,
                                    (1L << kEntryBits) - 1));
  };
  return std::uint64_t(q.face) << (2 * kEntryBits) | index(q.x) << kEntryBits | index(q.y);
}

LightProjection::Cell LightProjection::cell(std::uint64_t entry) {
  constexpr std::uint64_t mask = (std::uint64_t(1) << kEntryBits) - 1;
  return {int(entry >> (2 * kEntryBits)), (entry >> kEntryBits) & mask, entry & mask};
}

double LightProjection::entry_width(Vec3 p) const {
  if (!point_) return length(right_);
  const Vec3 w = p - light_;
  const double depth = max_abs_component(w);
  // d(x) = d(lateral) / depth on a face spanning [-1, 1] with R entries.
  return depth > 0 ? 0.5 * double(resolution_) / depth : double(resolution_);
}

double LightProjection::distance(Vec3 p) const {
  return point_ ? length(p - light_) : dot(p, light_);
}

Vec3 LightProjection::toward_light(Vec3 p) const {
  if (!point_) return -light_;
  const Vec3 w = light_ - p;
  const double len = length(w);
  return len > 0 ? w / len : Vec3{};
}

Vec3 LightProjection::to_light(Vec3 p) const {
  return point_ ? light_ - p : -light_ * reach_;
}

}  // namespace shadowkit::voxel
