#include "subpatch_render.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadowkit/core/error.h"
#include "shadowkit/core/palette.h"
#include "shadowkit/raster/visible_surface.h"

namespace shadowkit::voxel {
namespace {

constexpr double kHighlight = 0.25;
constexpr double kShininess = 32;

}  // namespace

CornerShading corner_shading(int shadowed_corners) {
  if (shadowed_corners >= 4) return {0, false};
  return {1.0 / double(1 << shadowed_corners), shadowed_corners == 0};
}

namespace {

// How many corners of \p leaf are in voxels \p shadowed says are.
template <class Shadowed>
std::uint8_t count_shadowed(const Subpatch& leaf, const Shadowed& shadowed) {
  int n = 0;
  for (const GridPoint& c : leaf.corner) n += shadowed(voxel_floor(c.vec()));
  return std::uint8_t(n);
}

}  // namespace

std::vector<std::uint8_t> shadowed_corners(const VoxelMethod& method) {
  if (!method.keeps_frame_buffer()) {
    // §5.1: the recursion again, each corner decided as the recursion reaches it.
    const StreamedShadows& streamed = method.streamed_shadows();
    const VoxelGrid& grid = method.grid();
    return concatenate(map_leaves<std::uint8_t>(
        method.patches(), grid, method.adjacency(), [&](const Subpatch& leaf, const Domain&) {
          const Vec3 normal = leaf_normal(leaf);
          return count_shadowed(leaf, [&](const VoxelIndex& v) {
            return grid.contains(v) && streamed.voxel_shadowed(v, normal);
          });
        }));
  }
  const std::vector<Subpatch>& leaves = method.subpatches();
  const CubicFrameBuffer& buffer = method.frame_buffer();
  std::vector<std::uint8_t> counts(leaves.size());
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t l) {
    counts[l] = count_shadowed(
        leaves[l], [&](const VoxelIndex& v) { return buffer.state(v) == VoxelState::shadowed; });
  });
  return counts;
}

std::vector<std::vector<std::uint8_t>> shadowed_corners_per_light(const Scene& scene,
                                                                  VoxelMethod& method,
                                                                  const Context& ctx) {
  method.prepare(scene, ctx);
  std::vector<std::vector<std::uint8_t>> shadowed;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    method.build(scene, l, ctx);
    shadowed.push_back(shadowed_corners(method));
  }
  return shadowed;
}

SubpatchView::SubpatchView(const Scene& scene, const PatchSet& patches,
                           const SubpatchTessellation& tessellation) {
  view_.name = scene.name;
  view_.lights = scene.lights;
  // One object per scene object, so that colours follow the objects.
  std::vector<PolygonSoup> soups(scene.objects.size());
  std::vector<std::vector<std::uint32_t>> leaves(scene.objects.size());
  const PolygonSoup& all = tessellation.triangles;
  for (std::size_t t = 0; t < tessellation.leaf.size(); ++t) {
    const std::uint32_t leaf = tessellation.leaf[t];
    const std::uint32_t object = patches[tessellation.patch_of(leaf)].object;
    PolygonSoup& soup = soups[object];
    const auto first = std::uint32_t(soup.positions.size());
    for (std::uint32_t k = all.face_start[t]; k < all.face_start[t + 1]; ++k) {
      soup.positions.push_back(all.positions[all.indices[k]]);
    }
    soup.add_face({first, first + 1, first + 2});
    leaves[object].push_back(leaf);
  }
  Context quiet;
  quiet.warn = [](const std::string&) {};
  for (std::uint32_t o = 0; o < soups.size(); ++o) {
    if (leaves[o].empty()) continue;
    view_.objects.push_back(
        {scene.objects[o].name, Mesh::build(soups[o], scene.objects[o].name, quiet), 0, nullptr});
    // Triangles without area were left out by the tessellation: none is dropped here.
    SHADOWKIT_CHECK(view_.objects.back().mesh.face_count() == leaves[o].size());
    object_.push_back(o);
    leaf_.insert(leaf_.end(), leaves[o].begin(), leaves[o].end());
  }
  view_.finalize();
}

void SubpatchView::draw(const Camera& camera,
                        const std::vector<std::vector<std::uint8_t>>& shadowed, Image<Rgb8>& image,
                        std::vector<float>& depth) {
  view_.camera = camera;
  const Scene& view = view_;
  const VisibleSurfaceBuffer surfaces = render_visible_surfaces(view, {});
  const double diffuse_share = (1.0 - kAmbient) / double(std::max<std::size_t>(1, shadowed.size()));
  tbb::parallel_for(0, surfaces.height, [&](int y) {
    for (int x = 0; x < surfaces.width; ++x) {
      const std::size_t i = surfaces.index(x, y);
      if (!surfaces.covered(i) || !(surfaces.depth[i] < depth[i])) continue;
      depth[i] = surfaces.depth[i];
      const std::uint32_t leaf = leaf_[surfaces.face[i]];
      const Plane& plane = view.face_plane(surfaces.face[i]);
      const Vec3 p = surfaces.point(i);
      const Vec3 to_eye = normalize(camera.position - p);
      const Vec3 n = dot(plane.normal, to_eye) >= 0 ? plane.normal : -plane.normal;
      double light = kAmbient, highlight = 0;
      for (std::size_t l = 0; l < shadowed.size(); ++l) {
        const Vec3 to_light = view.lights[l].direction_to(p);
        const double lambert = dot(n, to_light);
        if (lambert <= 0) continue;
        const CornerShading share = corner_shading(shadowed[l][leaf]);
        light += diffuse_share * lambert * share.diffuse;
        if (share.highlight) {
          highlight += kHighlight *
                       std::pow(std::max(0.0, dot(n, normalize(to_light + to_eye))), kShininess);
        }
      }
      const Vec3 c = object_colour(object_[surfaces.object(i)]) * light + Vec3{1, 1, 1} * highlight;
      image.pixels[i] = to_rgb8(c);
    }
  });
}

Frame::Frame(const Camera& camera)
    : image(camera.width, camera.height, kBackground),
      depth(image.pixels.size(), std::numeric_limits<float>::infinity()) {}

SubpatchImage::SubpatchImage(const Scene& scene, const PatchSet& patches,
                             const SubpatchTessellation& tessellation,
                             std::vector<std::vector<std::uint8_t>> shadowed_per_light)
    : view_(scene, patches, tessellation), shadowed_(std::move(shadowed_per_light)) {}

Image<Rgb8> SubpatchImage::render(const Camera& camera) {
  Frame frame(camera);
  view_.draw(camera, shadowed_, frame.image, frame.depth);
  return std::move(frame.image);
}

SubpatchImage make_subpatch_image(const Scene& scene, VoxelMethod& method, const Context& ctx) {
  auto shadowed = shadowed_corners_per_light(scene, method, ctx);
  const SubpatchTessellation tessellation =
      tessellate_subpatches(method.patches(), method.grid(), method.adjacency());
  return SubpatchImage(scene, method.patches(), tessellation, std::move(shadowed));
}

StillImage render_still(const Scene& scene, VoxelMethod& method, const Context& ctx,
                        std::size_t batch_triangles) {
  const auto shadowed = shadowed_corners_per_light(scene, method, ctx);
  Frame frame(scene.camera);
  StillImage out;
  tessellate_in_batches(method.patches(), method.grid(), method.adjacency(), batch_triangles,
                        [&](SubpatchTessellation batch) {
                          SubpatchView view(scene, method.patches(), batch);
                          batch = {};  // the view has its own copy of the triangles
                          view.draw(scene.camera, shadowed, frame.image, frame.depth);
                          out.triangles += view.triangle_count();
                          ++out.batches;
                        });
  out.image = std::move(frame.image);
  return out;
}

}  // namespace shadowkit::voxel
