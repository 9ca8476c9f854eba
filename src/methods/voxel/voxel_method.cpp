#include "voxel_method.h"

#include <cmath>
#include <string>

#include "frame_bound.h"
#include "shadowkit/core/error.h"

namespace shadowkit::voxel {
namespace {

constexpr int kMinResolution = 16, kMaxResolution = 2048;
// Subpatch ids and their corners' sample numbers (subpatch * 4 + corner) are 32-bit.
constexpr double kSubpatchIdLimit = double(1 << 28);
// Empty voxels at a visible point look this far (voxels) for a non-empty one.
constexpr int kNeighbourReach = 2;

[[noreturn]] void bad_option(const std::string& key, const std::string& what,
                             const MethodOptions& options) {
  throw InputError("option 'voxel." + key + "'", what + ", got '" + options.text(key, "") + "'");
}

int resolution_option(const MethodOptions& options) {
  const double m = options.number("resolution", 256);
  const bool power_of_two = m == std::floor(m) && m >= 1 && (long(m) & (long(m) - 1)) == 0;
  if (!power_of_two || m < kMinResolution || m > kMaxResolution) {
    bad_option("resolution", "expected a power of two in 16..2048", options);
  }
  return int(m);
}

int adjacency_option(const MethodOptions& options) {
  const double n = options.number("adjacency", 26);
  if (n != 6 && n != 18 && n != 26) bad_option("adjacency", "expected 6, 18 or 26", options);
  return int(n);
}

voxel::ShadowTest test_option(const MethodOptions& options) {
  const std::string test = options.text("test", "topology");
  if (test == "offset") return voxel::ShadowTest::offset;
  if (test != "topology") bad_option("test", "expected offset or topology", options);
  return voxel::ShadowTest::topology;
}

bool bound_option(const MethodOptions& options) {
  const std::string bound = options.text("bound", "view");
  if (bound != "view" && bound != "scene") bad_option("bound", "expected view or scene", options);
  return bound == "scene";
}

bool paper_option(const MethodOptions& options) {
  const double paper = options.number("paper", 0);
  if (paper != 0 && paper != 1) bad_option("paper", "expected 0 or 1", options);
  return paper == 1;
}

// §5.1 keeps no voxels and no subpatches: the topology test's lists are what it avoids.
bool streamed_option(const MethodOptions& options, voxel::ShadowTest test) {
  const double framebuffer = options.number("framebuffer", 1);
  if (framebuffer != 0 && framebuffer != 1) bad_option("framebuffer", "expected 0 or 1", options);
  if (framebuffer == 0 && test == voxel::ShadowTest::topology) {
    bad_option("framebuffer",
               "0 (Lai & Cheng 5.1) streams the voxels without keeping them or the subpatch "
               "lists the topology test needs: set voxel.test=offset",
               options);
  }
  return framebuffer == 0;
}

std::size_t max_subpatches_option(const MethodOptions& options, std::size_t fallback) {
  const double n = options.number("max_subpatches", double(fallback));
  if (n != std::floor(n) || n < 1 || n > kSubpatchIdLimit) {
    bad_option("max_subpatches", "expected a whole number in 1..268435456", options);
  }
  return std::size_t(n);
}

}  // namespace

VoxelMethod::VoxelMethod(const MethodOptions& options, std::size_t max_subpatches) {
  options.expect_only("voxel", {"resolution", "adjacency", "test", "bound", "framebuffer", "paper",
                                "max_subpatches"});
  resolution_ = resolution_option(options);
  adjacency_ = adjacency_option(options);
  rules_ = {test_option(options), paper_option(options)};
  whole_scene_ = bound_option(options);
  streamed_mode_ = streamed_option(options, rules_.test);
  max_subpatches_ = max_subpatches_option(options, max_subpatches);
}

void VoxelMethod::prepare(const Scene& scene, const Context& /*ctx*/) {
  std::vector<Camera> views{scene.camera};
  views.insert(views.end(), other_views_.begin(), other_views_.end());
  grid_ = voxel::make_grid(voxel::frame_bound(scene, views, whole_scene_), resolution_);
  patches_.emplace(scene);
  // Counted before they are stored: the frame buffer mode keeps every subpatch, and §5.1
  // runs the recursion again for each light.
  const auto too_many = [&] {
    return InputError("scene '" + scene.name + "'",
                      "the voxel method at voxel.resolution=" + std::to_string(resolution_) +
                          " makes more than " + std::to_string(max_subpatches_) +
                          " subpatches (voxel.max_subpatches); lower voxel.resolution or raise "
                          "voxel.max_subpatches");
  };
  if (streamed_mode_) {
    if (!voxel::count_leaves(*patches_, grid_, adjacency_, max_subpatches_)) throw too_many();
    return;
  }
  auto leaves = voxel::voxelize(*patches_, grid_, adjacency_, max_subpatches_);
  if (!leaves) throw too_many();
  leaves_ = std::move(*leaves);
  const voxel::VoxelKeys keys(grid_.dims);
  voxels_ = voxel::SurfaceVoxels::collect(leaves_, grid_, keys, adjacency_, rules_.paper);
  buffer_ = voxel::CubicFrameBuffer(grid_, voxels_.keys);
}

void VoxelMethod::build(const Scene& scene, std::size_t light, const Context& /*ctx*/) {
  light_ = scene.lights.at(light);
  if (streamed_mode_) {
    streamed_.reset();  // the previous light's plane goes before the next one is built
    streamed_.emplace(*patches_, grid_, adjacency_, light_, rules_);
    return;
  }
  stats_ = voxel::determine_shadows(light_, leaves_, voxels_, rules_, buffer_);
}

bool VoxelMethod::serves(const Scene& scene, const Camera& camera) const {
  return voxel::grid_serves(grid_, scene, camera);
}

voxel::VoxelState VoxelMethod::state_at(Vec3 p) const {
  const voxel::VoxelGrid& grid = buffer_.grid();
  const Vec3 g = grid.to_grid(p);
  const voxel::VoxelIndex home = grid.voxel_of(g);
  voxel::VoxelState state = buffer_.state(home);
  // Rings of growing size: the nearest non-empty voxel centre wins.
  for (int reach = 1; state == voxel::VoxelState::empty && reach <= kNeighbourReach; ++reach) {
    double best = INFINITY;
    for (int dz = -reach; dz <= reach; ++dz) {
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          const voxel::VoxelIndex v{home[0] + dx, home[1] + dy, home[2] + dz};
          const voxel::VoxelState s = buffer_.state(v);
          const Vec3 d = voxel::VoxelGrid::center(v) - g;
          if (s != voxel::VoxelState::empty && dot(d, d) < best) best = dot(d, d), state = s;
        }
      }
    }
  }
  return state;
}

void VoxelMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                        const Context& /*ctx*/) {
  const Vec3 eye = scene.camera.position;
  shade_each_pixel(surfaces, mask, [&](std::size_t i) {
    const Plane& plane = scene.face_plane(surfaces.face[i]);
    if (!faces_light(plane, eye, light_)) return false;
    // §5.1: the visible face's own normal stands for the voxel's surface.
    if (streamed_) return !streamed_->shadowed(grid_.to_grid(surfaces.point(i)), plane.normal);
    // A point no voxel is near (outside the bound) has nothing to shadow it: lit.
    return state_at(surfaces.point(i)) != voxel::VoxelState::shadowed;
  });
}

std::size_t VoxelMethod::memory_bytes() const {
  if (streamed_) return streamed_->memory_bytes();
  return buffer_.memory_bytes() + voxels_.memory_bytes() +
         leaves_.capacity() * sizeof(voxel::Subpatch) + stats_.peak_bytes;
}

MethodCounters VoxelMethod::counters() const {
  if (streamed_) {
    return {{"resolution", double(grid_.resolution())},
            {"entries", double(streamed_->entry_count())}};
  }
  return {{"resolution", double(grid_.resolution())},
          {"subpatches", double(leaves_.size())},
          {"voxels", double(voxels_.size())},
          {"frame_buffer_bytes", double(buffer_.memory_bytes())},
          {"entries", double(stats_.entries)},
          {"uncertain", double(stats_.uncertain)},
          {"shadowed", double(stats_.shadowed)},
          {"blocker_records", double(stats_.blocker_records)}};
}

}  // namespace shadowkit::voxel
