#pragma once
// shadowmap: Williams 1978 ("Casting curved shadows on curved surfaces") depth-map shadows,
// the image-space baseline. A cube map for point lights, one orthographic map for
// directional lights, a constant plus slope-scaled depth bias and optional percentage-closer
// filtering.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "cube_map.h"
#include "depth_map.h"
#include "shadowkit/methods/shadow_method.h"
#include "texel_batch.h"

namespace shadowkit::shadowmap {

/// \brief Shadow maps: the scene's depth from the light, drawn with the shared scan converter
/// (depth only, its clusters culled per cube face and by what nearer ones hide); shade()
/// transforms each visible point into the light's view and compares its depth with the stored
/// one, in screen tiles. build() sets the maps up and, with `tiles=all`, draws them whole;
/// by default shade() draws the tiles its points look up, once it has found them.
///
/// Options (`--set shadowmap.KEY=VALUE`):
/// - `resolution` (default 2048): texels per side of each cube face (point light) or of the
///   orthographic map (directional light), 16..16384.
/// - `bias` (default 1e-3 x the scene's bounding-box diagonal): constant depth bias in world
///   units, >= 0. It absorbs float rounding of stored depths and visible points and the
///   second-order part of the sampling error, while detaching contact shadows by only 0.1% of
///   the scene's size; relative to the diagonal so it means the same in any units.
/// - `slope_bias` (default 1): scale of the slope term, >= 0. The term is slope_bias x (world
///   size of a texel at the point's depth) x (the receiver's depth slope: tan of the angle
///   between its normal and the light direction for a directional light; for a cube face the
///   slope of the face's depth zv, the same tangent on the face's axis; capped at
///   shadowmap::kMaxSlope = 10, i.e. 84.3°). To first order the depth of a plane varies by
///   at most sqrt(2)/2 of this term at slope_bias 1 between a texel's centre, where the map
///   sampled it, and any point of the texel: 1 covers that with some margin.
/// - `pcf` (default 1: off): percentage-closer filtering kernel width in texels, odd, 1..31.
///   The point is lit when at least half of the kernel's depth tests pass (the mask is
///   binary), every test with the same bias; kernels are clamped at the map's (face's) edge.
/// - `tiles` (default looked_up): `looked_up` draws only the map tiles the camera pass looks
///   up, `all` the whole maps in build(); the masks are the same.
///
/// A point is lit when it passes condition 1 (faces_light) and its depth from the light is
/// not greater than the stored depth plus bias. Setting bias and slope_bias to 0 shows
/// self-shadowing acne; a large bias detaches shadows from their casters (peter-panning);
/// low resolution gives blocky, aliased shadow edges. These are the method's, kept on purpose.
class ShadowMapMethod final : public ShadowMethod {
 public:
  explicit ShadowMapMethod(const MethodOptions& options);
  std::string_view name() const override { return "shadowmap"; }
  void build(const Scene& scene, std::size_t light, const Context& ctx) override;
  void shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
             const Context& ctx) override;
  std::size_t memory_bytes() const override;
  MethodCounters counters() const override;

  /// The depth comparison for a point \p p on a face with \p plane (condition 2 only), with
  /// the light of the last build().
  bool passes_depth_test(const Plane& plane, Vec3 p) const;

  /// The constant bias of the last build(), in world units.
  double bias() const { return bias_; }
  /// The map of the last build() for a directional light.
  const shadowmap::DepthMap& directional_map() const { return ortho_; }
  /// The cube map of the last build() for a point light.
  const shadowmap::CubeMap& cube_map() const { return cube_; }

 private:
  struct Receiver;
  struct Receivers;
  struct TileRow;
  struct CameraPass;
  /// A point kept between the passes: its pixel, its texel (map << 28 | tile << 12 | place in
  /// the tile) and its depth less its bias.
  struct KeptPoint {
    std::uint32_t pixel, texel;
    float depth;
  };
  /// The column parts of the camera's pixel rays, forward + x right, coordinate by coordinate.
  struct ColumnRays {
    std::vector<double> x, y, z;
  };
  /// The maps of the last build(): a cube map's six faces, or the one orthographic map.
  int map_count() const;
  const shadowmap::DepthMap& map(int m) const;
  shadowmap::DepthMap& map(int m);
  /// Draws the tiles wanted_ marks in every map (all of them where it is empty).
  void draw_maps(const Scene& scene, const Context& ctx);
  /// Runs \p fill(y, x0, x1, row, receivers) and then \p finish(row) on every row of every
  /// screen tile of \p surfaces.
  template <class Fill, class Finish>
  void each_tile_row(const VisibleSurfaceBuffer& surfaces, Fill&& fill, Finish&& finish) const;
  void set_up_row(const CameraPass& pass, int y, int x0, int x1, TileRow& r,
                  Receivers& receivers) const;
  void load_row(TileRow& r) const;
  /// Writes each point of a loaded row lit or shadowed into \p mask.
  void decide_row(const TileRow& r, ShadowMask& mask) const;
  std::size_t kept_row_index(int y, int x0) const;
  void keep_row(int y, int x0, const TileRow& r);
  void kept_row(int y, int x0, TileRow& r) const;
  /// What the camera pass keeps of the receiving \p face with \p plane, seen from \p eye.
  Receiver receiver_of(const Plane& plane, Vec3 eye, std::uint32_t face) const;
  /// The bias terms of the depth tests on a receiver with \p plane (Williams's
  /// self-shadowing), in the maps of the last build().
  shadowmap::ReceiverBias bias_of(const Plane& plane) const;
  /// Adds the point \p p on a receiver with \p bias to \p points.
  void add_point(Vec3 p, const shadowmap::ReceiverBias& bias, shadowmap::PointBatch& points) const;
  /// Adds the visible points of columns [\p xa, \p xb) of a row, whose rays are the columns'
  /// plus \p row, on one \p receiver, seen from \p eye, with the light a point or not.
  template <bool kPointLight>
  void add_points(const ColumnRays& columns, Vec3 row, int xa, int xb, Vec3 eye,
                  const Receiver& receiver, shadowmap::PointBatch& points) const;
  /// Where each of \p points is tested, in the maps of the last build().
  void locate(const shadowmap::PointBatch& points, shadowmap::TexelBatch& texels) const;
  /// The map of point \p k of a located batch, and its texel's stored depth.
  const shadowmap::DepthMap& map_of(const shadowmap::TexelBatch& texels, std::size_t k) const;
  const float& stored(const shadowmap::TexelBatch& texels, std::size_t k) const;
  /// Whether point \p k of a located batch passes the depth test (half its PCF kernel).
  bool lit(const shadowmap::TexelBatch& texels, std::size_t k) const;

  int resolution_ = 2048;
  std::optional<double> bias_option_;
  double slope_bias_ = 1.0;
  int pcf_ = 1;
  bool all_tiles_ = false;

  Light light_;
  double bias_ = 0;
  shadowmap::CubeMap cube_;
  shadowmap::DepthMap ortho_;
  /// Per map, the tiles the camera pass looks up; empty: all.
  std::array<std::vector<std::uint8_t>, shadowmap::CubeMap::kFaces> wanted_;
  /// The last camera pass's light-facing points, kept from locating them to testing them: a
  /// row of each screen tile's column after another, each with room for a tile's width.
  std::size_t kept_columns_ = 0, kept_capacity_ = 0;
  std::uint64_t pass_ = 0;  ///< the number of the current camera pass (Receivers)
  std::unique_ptr<KeptPoint[]> kept_;
  std::vector<std::uint8_t> kept_count_;  ///< points per row
};

/// The orthographic view along \p direction that covers the 8 corners of \p bounds, with its
/// eye behind all of them (Williams 1978's view from a light at infinity).
RasterProjection directional_light_view(const Bounds3& bounds, Vec3 direction, int resolution);

}  // namespace shadowkit::shadowmap
