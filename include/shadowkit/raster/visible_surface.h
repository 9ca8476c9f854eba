#pragma once
/// \brief The visible-surface buffer: what the camera sees at each pixel. Every method's
/// camera pass consumes it.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/vec.h"
#include "shadowkit/raster/scan_converter.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief Per pixel (row-major, row 0 at the top): the nearest face and its distance along
/// the pixel's unit ray. The visible point is not stored but computed on demand, exactly in
/// double, as the intersection of the contract's pixel ray with the face plane; this keeps
/// the buffer at 8 bytes a pixel. Background pixels have face == kNoFace.
class VisibleSurfaceBuffer {
 public:
  int width = 0, height = 0;
  std::vector<float> depth;         ///< distance along the unit pixel ray; +inf: background
  std::vector<std::uint32_t> face;  ///< global face id or kNoFace

  /// Columns a coverage block spans: a scan converter's tile.
  static constexpr int kCoverageBlock = ScanConverter::kTileSize;
  /// Per row, per block of kCoverageBlock columns: whether a pixel there shows a face.
  std::vector<std::uint8_t> block_covered;

  std::size_t index(int x, int y) const { return std::size_t(y) * width + x; }
  bool covered(std::size_t i) const { return face[i] != kNoFace; }
  int blocks_per_row() const { return (width + kCoverageBlock - 1) / kCoverageBlock; }
  /// Fills block_covered from face, for a buffer filled by other means than
  /// render_visible_surfaces().
  void summarize_coverage();
  /// The first column from \p x, before \p end, where row \p y shows a face, or \p end.
  /// Background goes a block at a time where the block shows no face, else eight pixels at a
  /// time: kNoFace is all ones, and so is their AND.
  int next_covered(int x, int end, int y) const {
    const std::uint32_t* f = face.data() + index(0, y);
    if (x < end && f[x] != kNoFace) return x;  // most often, inside a face's stretch
    const std::uint8_t* blocks = block_covered.data() + std::size_t(y) * blocks_per_row();
    while (x < end) {
      const int block_end = std::min(end, (x / kCoverageBlock + 1) * kCoverageBlock);
      if (blocks[x / kCoverageBlock]) {
        while (x + 8 <= block_end && (f[x] & f[x + 1] & f[x + 2] & f[x + 3] & f[x + 4] & f[x + 5] &
                                      f[x + 6] & f[x + 7]) == kNoFace) {
          x += 8;
        }
        while (x < block_end && f[x] == kNoFace) ++x;
        if (x < block_end) return x;
      }
      x = block_end;
    }
    return end;
  }
  std::size_t covered_count() const;

  /// The object seen at pixel \p i (kNoFace for background).
  std::uint32_t object(std::size_t i) const {
    return covered(i) ? scene_->object_of_face(face[i]) : kNoFace;
  }
  /// Object ids of all pixels, for comparisons that look at neighbourhoods.
  std::vector<std::uint32_t> object_ids() const;
  /// The visible point of covered pixel \p i: its pixel ray against its face plane.
  Vec3 point(std::size_t i) const;
  /// The plane of the face seen at covered pixel \p i.
  const Plane& plane(std::size_t i) const { return scene_->face_plane(face[i]); }
  /// The unnormalised contract ray f + x r + y u through the centre of pixel \p i.
  Vec3 ray(std::size_t i) const;

  /// Binds the buffer to the scene whose camera and faces it describes.
  void bind(const Scene& scene);

 private:
  const Scene* scene_ = nullptr;
  Vec3 forward_, right_, up_;
  Camera::PixelGrid grid_{};
};

/// Scan-converts the scene from its camera into \p out, reusing its storage (a new frame of
/// the same size allocates nothing). \p out refers to \p scene afterwards.
void render_visible_surfaces(const Scene& scene, const Context& ctx, VisibleSurfaceBuffer& out);

/// The same, into a new buffer.
VisibleSurfaceBuffer render_visible_surfaces(const Scene& scene, const Context& ctx);

}  // namespace shadowkit
