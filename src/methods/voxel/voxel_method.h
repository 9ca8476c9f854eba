#pragma once
// voxel: Lai & Cheng 2007, "Shadow generation for objects represented by Catmull-Clark
// subdivision surfaces". The scene's patches are voxelized in parameter space (§3) into
// one cubic frame buffer; per light, the voxels are projected once onto a plane
// perpendicular to the light and decided lit or shadowed (§4); a visible point takes the
// state of its voxel.
#include <memory>
#include <optional>
#include <vector>

#include "cubic_frame_buffer.h"
#include "patch_set.h"
#include "shadow_determination.h"
#include "shadowkit/methods/shadow_method.h"
#include "streamed_shadows.h"
#include "surface_voxels.h"
#include "voxelizer.h"

namespace shadowkit::voxel {

/// \brief Options (`--set voxel.KEY=VALUE`):
/// - `resolution` M (default 256): voxels along the longest side of the frame buffer's box,
///   a power of two in 16..2048.
/// - `adjacency` N (default 26): the stopping rule's N-adjacency, 6, 18 or 26.
/// - `test` (default topology): `offset` (§4.1) or `topology` (§4.2).
/// - `bound` (default view): `view` (what can be seen or shadow what is seen,
///   voxel::frame_bound) or `scene` (the scene's box).
/// - `framebuffer` (default 1): 1 keeps the voxels' states in the cubic frame buffer (§5.2);
///   0 streams the voxels onto the projection plane and decides each visible point on the
///   fly (§5.1, voxel::StreamedShadows), offset test only.
/// - `paper` (default 0): 1 runs §3 and §4 as the paper writes them (voxel::ShadowRules;
///   with N = 6, the corners' voxels alone, no tunnels closed).
/// - `max_subpatches` (default kMaxSubpatches): the most leaves the voxelization may make;
///   prepare() counts them before keeping more than voxel::kKeptWhileCounting, and more is
///   an InputError.
class VoxelMethod final : public ShadowMethod {
 public:
  /// The default bound on the subpatches: every structure but the frame buffer grows with
  /// them (about 140 bytes a subpatch at the peak of prepare, docs/methods/voxel.md).
  static constexpr std::size_t kMaxSubpatches = std::size_t(1) << 25;

  /// \p max_subpatches: the bound when the `max_subpatches` setting is not given.
  explicit VoxelMethod(const MethodOptions& options, std::size_t max_subpatches = kMaxSubpatches);
  std::string_view name() const override { return "voxel"; }
  void prepare(const Scene& scene, const Context& ctx) override;
  /// `bound=view` fits the frame buffer to the camera and the lights (frame_bound.h).
  bool prepared_for_every_view() const override { return whole_scene_; }
  void build(const Scene& scene, std::size_t light, const Context& ctx) override;
  void shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
             const Context& ctx) override;
  std::size_t memory_bytes() const override;
  MethodCounters counters() const override;

  /// Views besides the scene's camera that the frame buffer must serve (§5.2: a new view
  /// needs no new shadow work): with `bound=view`, prepare() bounds the grid to hold them.
  void serve_views(std::vector<Camera> views) { other_views_ = std::move(views); }
  /// Whether the frame buffer prepared for \p scene holds every voxel the view of \p camera
  /// needs, so that a render from there drops no geometry.
  bool serves(const Scene& scene, const Camera& camera) const;

  const voxel::VoxelGrid& grid() const { return grid_; }
  const voxel::PatchSet& patches() const { return *patches_; }
  int adjacency() const { return adjacency_; }
  /// Whether the states are kept in the frame buffer (§5.2), which the two accessors below
  /// describe; with `framebuffer=0` (§5.1) they are empty and streamed_shadows() decides.
  bool keeps_frame_buffer() const { return !streamed_mode_; }
  const voxel::CubicFrameBuffer& frame_buffer() const { return buffer_; }
  const std::vector<voxel::Subpatch>& subpatches() const { return leaves_; }
  /// §5.1: the current light's projection plane, after build().
  const voxel::StreamedShadows& streamed_shadows() const { return *streamed_; }
  /// The state at world point \p p: its voxel's, or for an empty voxel (the voxelization
  /// marks only subpatch corners) the nearest non-empty voxel's within two voxels.
  voxel::VoxelState state_at(Vec3 p) const;

 private:
  int resolution_ = 256;
  int adjacency_ = 26;
  voxel::ShadowRules rules_;
  bool whole_scene_ = false;
  bool streamed_mode_ = false;
  std::size_t max_subpatches_ = kMaxSubpatches;
  std::vector<Camera> other_views_;

  voxel::VoxelGrid grid_;
  std::optional<voxel::PatchSet> patches_;  ///< §5.1: voxelized again per light
  std::optional<voxel::StreamedShadows> streamed_;

  std::vector<voxel::Subpatch> leaves_;
  voxel::SurfaceVoxels voxels_;
  voxel::CubicFrameBuffer buffer_;
  voxel::ShadowStatistics stats_;
  Light light_;
};

}  // namespace shadowkit::voxel
