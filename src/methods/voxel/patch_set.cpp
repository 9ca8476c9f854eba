#include "patch_set.h"

#include <algorithm>
#include <functional>
#include <tuple>
#include <unordered_set>
#include <utility>

namespace shadowkit::voxel {
namespace {

// (u, v) of corner k.
constexpr std::array<std::array<double, 2>, 4> kCornerUv{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

// A sliver's corners turned (winding kept) so that its shortest side comes first. As the
// patch (a, b, c, c), u then runs along that side and v toward the far corner: the u sides
// are soon adjacent and only v is halved further (voxelizer), where with a long side first
// both directions would be halved, for leaves growing with its length squared. Triangles
// whose first side is within twice the shortest keep their corners (and their leaves).
std::array<std::uint32_t, 3> shortest_side_first(std::array<std::uint32_t, 3> t,
                                                 const std::vector<Vec3>& positions) {
  const auto side = [&](int k) {
    const Vec3 d = positions[t[(k + 1) % 3]] - positions[t[k]];
    return dot(d, d);
  };
  const int first =
      side(0) <= side(1) ? (side(0) <= side(2) ? 0 : 2) : (side(1) <= side(2) ? 1 : 2);
  if (side(0) > 4 * side(first)) std::rotate(t.begin(), t.begin() + first, t.end());
  return t;
}

// A triangle's corners in a fixed order, whatever order and winding it was given in.
std::array<Vec3, 3> corner_set(const std::array<std::uint32_t, 3>& t,
                               const std::vector<Vec3>& positions) {
  std::array<Vec3, 3> corners{positions[t[0]], positions[t[1]], positions[t[2]]};
  std::sort(corners.begin(), corners.end(),
            [](Vec3 a, Vec3 b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
  return corners;
}

struct CornerSetHash {
  std::size_t operator()(const std::array<Vec3, 3>& corners) const {
    std::size_t h = 0;
    for (const Vec3& c : corners) {
      for (int a = 0; a < 3; ++a) h = h * 1000003 ^ std::hash<double>()(c[a]);
    }
    return h;
  }
};

}  // namespace

std::array<double, 2> PatchSet::side_uv(int side, double t) {
  const auto& a = kCornerUv[side];
  const auto& b = kCornerUv[(side + 1) % 4];
  // Dyadic t: the coordinates come out exact (one of them is constant along the side).
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t};
}

std::pair<int, double> PatchSet::side_of(double u, double v) {
  if (v == 0) return {0, u};
  if (u == 1) return {1, v};
  if (v == 1) return {2, 1 - u};
  return {3, 1 - v};
}

namespace {

int corner_of(double u, double v) {
  return u == 0 ? (v == 0 ? 0 : 3) : (v == 0 ? 1 : 2);
}

}  // namespace

PatchSet::PatchSet(const Scene& scene) : scene_(&scene) {
  add_triangles(scene);
  // Surface corner ids follow the scene's position ids, one range per surface.
  auto next_id = std::uint32_t(scene.triangles().positions.size());
  for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
    if (scene.objects[o].subdivision) add_surface(o, *scene.objects[o].subdivision, next_id);
  }
  for (std::uint32_t p = 0; p < patches_.size(); ++p) {
    const auto& ids = patches_[p].corner_ids;
    for (std::uint8_t k = 0; k < 4; ++k) {
      corner_owner_.try_emplace(ids[k], Owner{p, k});
      side_owner_.try_emplace(side_key(ids[k], ids[(k + 1) % 4]), Owner{p, k});
    }
  }
}

void PatchSet::add_triangles(const Scene& scene) {
  const TriangleList& triangles = scene.triangles();
  // A triangle with the corners of an earlier one (an object's coincident copy) is the same
  // surface: voxelized again, it would add its subpatches, samples and blocker records, and
  // not one voxel.
  std::unordered_set<std::array<Vec3, 3>, CornerSetHash> seen;
  for (std::uint32_t t = 0; t < triangles.triangles.size(); ++t) {
    const std::uint32_t object = scene.object_of_face(triangles.triangle_face[t]);
    if (scene.objects[object].subdivision) continue;  // its tessellation; the surface is added
    if (!seen.insert(corner_set(triangles.triangles[t], triangles.positions)).second) continue;
    const auto& [a, b, c] = shortest_side_first(triangles.triangles[t], triangles.positions);
    patches_.push_back({object, nullptr, t, {a, b, c, c}});
  }
}

void PatchSet::add_surface(std::uint32_t object, const SubdivisionSurface& surface,
                           std::uint32_t& next_id) {
  std::uint32_t used = 0;
  for (std::uint32_t p = 0; p < surface.patch_count(); ++p) {
    std::array<std::uint32_t, 4> ids = surface.patch_corners(p);
    for (std::uint32_t& id : ids) {
      used = std::max(used, id + 1);
      id += next_id;
    }
    patches_.push_back({object, &surface, p, ids});
  }
  next_id += used;
}

std::uint64_t PatchSet::side_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
}

Vec3 PatchSet::point(std::uint32_t patch, double u, double v) const {
  const bool u_edge = u == 0 || u == 1, v_edge = v == 0 || v == 1;
  const auto& ids = patches_[patch].corner_ids;
  if (u_edge && v_edge) {
    const Owner& o = corner_owner_.at(ids[corner_of(u, v)]);
    const auto& uv = kCornerUv[o.side];
    return evaluate(o.patch, uv[0], uv[1]);
  }
  if (!u_edge && !v_edge) return evaluate(patch, u, v);
  // A side point: the owner evaluates it, measured from the side's lower corner id.
  const auto [side, t] = side_of(u, v);
  const std::uint32_t from = ids[side], to = ids[(side + 1) % 4];
  const Owner& o = side_owner_.at(side_key(from, to));
  const bool same_way = patches_[o.patch].corner_ids[o.side] == from;
  const auto uv = side_uv(o.side, same_way ? t : 1 - t);
  return evaluate(o.patch, uv[0], uv[1]);
}

double PatchSet::canonical_t(std::uint32_t patch, int side, double t) const {
  const auto& ids = patches_[patch].corner_ids;
  return ids[side] <= ids[(side + 1) % 4] ? t : 1 - t;
}

std::uint64_t PatchSet::side_id(std::uint32_t patch, int side) const {
  const auto& ids = patches_[patch].corner_ids;
  return side_key(ids[side], ids[(side + 1) % 4]);
}

Vec3 PatchSet::evaluate(std::uint32_t patch, double u, double v) const {
  const Patch& p = patches_[patch];
  if (p.surface) return p.surface->evaluate(p.index, u, v).position;
  const std::vector<Vec3>& positions = scene_->triangles().positions;
  const Vec3 a = positions[p.corner_ids[0]], b = positions[p.corner_ids[1]];
  const Vec3 c = positions[p.corner_ids[2]];
  // The bilinear patch (a, b, c, c): v = 1 collapses onto c.
  return ((1 - u) * a + u * b) * (1 - v) + c * v;
}

}  // namespace shadowkit::voxel
