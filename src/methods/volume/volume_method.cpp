#include "volume_method.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <optional>

#include "contour_edges.h"
#include "eye_count.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/volume.h"
#include "shadowkit/scene/footprints.h"
#include "stencil_count.h"

namespace shadowkit::volume {
namespace {

// What a run of sub-objects contributes for the current light, made by one task.
struct VolumeChunk {
  static constexpr std::uint32_t kSubObjects = 64;
  std::vector<ShadowPolygon> polygons;
  std::vector<raster::ScreenPolygon> screen;  ///< face: the index into polygons
  int eye_count = 0;
  std::size_t depth_fail = 0;                                ///< sub-objects counted depth-fail
  std::size_t contour_edges = 0, loops = 0, open_loops = 0;  ///< Fig. 2, for the counters
  /// The first sub-object whose eye's count a forced depth-pass needs and cannot have.
  std::optional<std::uint32_t> no_eye_count;
};

// Whether mesh face \p f may come within \p radius of point \p p: its plane and its box do.
bool face_near(const Mesh& mesh, std::uint32_t f, Vec3 p, double radius) {
  if (std::abs(mesh.planes[f].distance(p)) > radius) return false;
  Bounds3 box;
  for (std::uint32_t k = 0; k < mesh.face_size(f); ++k)
    box.add(mesh.vertices[mesh.face_vertex(f, k)]);
  return box.distance(p) <= radius;
}

// Depth-pass misses crossings the near plane clips away, so it needs every shadow polygon
// farther from the eye than the near part of the view; and every face, or the view shows
// points behind a clipped face with the eye's count (a light inside a closed mesh: points
// inside it, counted 1). And it needs the eye's own count. The polygons themselves are
// tested, not their planes: of a mesh of 500,000 faces, some face's plane passes within the
// near plane's reach of almost any eye.
bool needs_depth_fail(const Mesh& mesh, std::span<const ContourEdge> edges,
                      std::span<const std::uint32_t> faces, const Light& light, Vec3 eye,
                      const ViewFrustum& view, std::optional<int> eye_count) {
  if (!eye_count) return true;
  const double reach = 2 * view.near_radius;
  return std::any_of(
             edges.begin(), edges.end(),
             [&](const ContourEdge& e) { return side_polygon_near(mesh, e, light, eye, reach); }) ||
         std::any_of(faces.begin(), faces.end(),
                     [&](std::uint32_t f) { return face_near(mesh, f, eye, reach); });
}

// The scene triangles of global face \p f: they follow face order.
std::pair<std::uint32_t, std::uint32_t> face_triangles(const Scene& scene, std::uint32_t f) {
  const auto& faces = scene.triangles().triangle_face;
  const auto lo = std::lower_bound(faces.begin(), faces.end(), f);
  const auto hi = std::upper_bound(lo, faces.end(), f);
  return {std::uint32_t(lo - faces.begin()), std::uint32_t(hi - faces.begin())};
}

// Sub-object \p k's volume, into \p v: depth-pass or depth-fail, decided for it alone (its
// volume is closed on its own, SubObjects), so one caster near the eye leaves the rest of its
// mesh to depth-pass, without caps. Returns whether every contour edge has its polygon.
bool add_sub_object_volume(const Scene& scene, const SubObjects& parts, std::uint32_t k,
                           const Light& light, const Reach& reach, const ViewFrustum& view,
                           const RasterProjection& projection, VolumeMethod::Counting counting,
                           VolumeChunk& v) {
  const SceneObject& object = scene.objects[scene.object_of_face(parts.faces(k)[0])];
  const Mesh& mesh = object.mesh;
  const Vec3 eye = scene.camera.position;
  // No contour edges is no reason to stop: a closed mesh around a point light has none, and
  // its faces alone bound its volume, all space outside it (Crow Sec. VII: the polygons
  // facing the light with the shadow polygons bound the volume). No pixel ray crosses a
  // face before its visible point, so depth-pass gives every point the eye's count through
  // those faces ("the eye is in shadow"); depth-fail counts them as caps.
  thread_local std::vector<std::uint32_t> faces;  // mesh face ids
  faces.clear();
  for (std::uint32_t f : parts.faces(k)) faces.push_back(f - object.first_face);
  thread_local std::vector<ContourEdge> edges;
  find_contour_edges(mesh, faces, light, edges);
  const std::vector<ContourLoop> loops = chain_contour_loops(edges);
  v.contour_edges += edges.size();
  v.loops += loops.size();
  v.open_loops += std::size_t(
      std::count_if(loops.begin(), loops.end(), [](const ContourLoop& l) { return !l.closed; }));
  const std::optional<int> eye_count =
      faces_between_eye_and_light(mesh, faces, parts.bounds[k], eye, light);
  const bool depth_fail = counting == VolumeMethod::Counting::depth_fail ||
                          (counting == VolumeMethod::Counting::automatic &&
                           needs_depth_fail(mesh, edges, faces, light, eye, view, eye_count));
  if (!depth_fail && !eye_count) {
    // Only a forced depth-pass gets here: auto counts depth-fail where the eye's count is open.
    if (!v.no_eye_count) v.no_eye_count = k;
    return false;
  }
  v.eye_count += depth_fail ? 0 : *eye_count;
  v.depth_fail += depth_fail;
  // Shadow polygons (Fig. 4), and the caps that close the volume for depth-fail.
  const std::size_t first = v.polygons.size();
  thread_local std::vector<PolygonCorners> corners;
  corners.clear();
  bool complete = true;
  for (const ContourEdge& e : edges) {
    PolygonCorners c;
    if (auto p = side_polygon(mesh, e, light, reach, eye, depth_fail, c)) {
      p->sub_object = k;
      for (std::uint32_t& f : p->edge_faces) f = f == kNoFace ? f : object.first_face + f;
      v.polygons.push_back(*p);
      corners.push_back(c);
    } else {
      complete = false;
    }
  }
  if (depth_fail) {
    for (std::uint32_t f : parts.faces(k)) {
      const auto [t0, t1] = face_triangles(scene, f);
      for (std::uint32_t t = t0; t < t1; ++t) {
        cap_polygons(scene, t, k, light, eye, v.polygons, corners);
      }
    }
  }
  // On screen now: the corners, 320 bytes a polygon, need not be kept.
  for (std::size_t i = 0; i < corners.size(); ++i) {
    raster::setup_convex_polygon(corners[i].span(), std::uint32_t(first + i), projection, v.screen);
  }
  return complete;
}

// The chunks' polygons and screen polygons, in order, into \p polygons and \p screen (their
// storage kept from the last light); each sub-object's together: the counting pass culls
// them per sub-object. Copied in parallel.
void gather(std::vector<VolumeChunk>& chunks, std::vector<ShadowPolygon>& polygons,
            std::vector<raster::ScreenPolygon>& screen) {
  std::vector<std::size_t> polygon_at(chunks.size() + 1, 0), screen_at(chunks.size() + 1, 0);
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    polygon_at[c + 1] = polygon_at[c] + chunks[c].polygons.size();
    screen_at[c + 1] = screen_at[c] + chunks[c].screen.size();
  }
  polygons.resize(polygon_at.back());
  screen.resize(screen_at.back());
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    std::copy(chunks[c].polygons.begin(), chunks[c].polygons.end(),
              polygons.begin() + std::ptrdiff_t(polygon_at[c]));
    std::transform(chunks[c].screen.begin(), chunks[c].screen.end(),
                   screen.begin() + std::ptrdiff_t(screen_at[c]), [&](raster::ScreenPolygon s) {
                     s.face += std::uint32_t(polygon_at[c]);
                     return s;
                   });
    chunks[c] = {};
  });
}

VolumeMethod::Counting parse_counting(const MethodOptions& options) {
  const std::string text = options.text("count", "auto");
  if (text == "auto") return VolumeMethod::Counting::automatic;
  if (text == "pass") return VolumeMethod::Counting::depth_pass;
  if (text == "fail") return VolumeMethod::Counting::depth_fail;
  throw InputError("option 'volume.count'", "expected auto, pass or fail, got '" + text + "'");
}

}  // namespace

VolumeMethod::VolumeMethod(const MethodOptions& options) {
  options.expect_only("volume", {"count"});
  counting_ = parse_counting(options);
}

void VolumeMethod::prepare(const Scene& scene, const Context& /*ctx*/) {
  parts_ = SubObjects::of(scene);
}

void VolumeMethod::build(const Scene& scene, std::size_t light, const Context& /*ctx*/) {
  SHADOWKIT_CHECK(parts_.of_face.size() == scene.face_count());  // prepare() came first
  light_ = scene.lights.at(light);
  const Camera& cam = scene.camera;
  const Reach reach = Reach::of(scene, light_);
  const ViewFrustum view = ViewFrustum::of(cam, near_plane_for(scene.bounds(), cam.position));
  // Crow's footprints: a sub-object wholly in the shadow of nearer ones adds no shadow.
  const std::vector<char> shadowed = shadowed_sub_objects(parts_, light_, scene.bounds());
  shadowed_sub_objects_ = double(std::count(shadowed.begin(), shadowed.end(), 1));
  // Crow's bounding boxes: of the others, one whose volume misses the view shadows nothing
  // visible (and, missing the eye, adds nothing to the eye's count).
  std::vector<char> casting(parts_.size(), 0);
  for (std::size_t k = 0; k < parts_.size(); ++k) casting[k] = !shadowed[k];
  frusta_.assign(casting);
  tbb::parallel_for(std::size_t(0), parts_.size(), [&](std::size_t k) {
    if (!casting[k]) return;
    frusta_[k] = ShadowFrustum(parts_.bounds[k], light_, reach, &view);
    casting[k] = frusta_[k].reaches_view() || !frusta_[k].misses({cam.position, cam.position});
  });
  const RasterProjection projection =
      RasterProjection::from_camera(cam, near_plane_for(scene.bounds(), cam.position));
  std::vector<char> complete(parts_.size(), 1);
  const std::uint32_t parts = std::uint32_t(parts_.size());
  std::vector<VolumeChunk> chunks((parts + VolumeChunk::kSubObjects - 1) /
                                  VolumeChunk::kSubObjects);
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    const std::uint32_t first = std::uint32_t(c) * VolumeChunk::kSubObjects;
    for (std::uint32_t k = first; k < std::min(parts, first + VolumeChunk::kSubObjects); ++k) {
      if (!casting[k]) continue;
      complete[k] = add_sub_object_volume(scene, parts_, k, light_, reach, view, projection,
                                          counting_, chunks[c]);
    }
  });
  // Refused by the first such sub-object in order, whichever thread met it first.
  for (const VolumeChunk& chunk : chunks) {
    if (!chunk.no_eye_count) continue;
    const std::string& name =
        scene.objects[scene.object_of_face(parts_.faces(*chunk.no_eye_count)[0])].name;
    throw InputError("option 'volume.count'",
                     "pass needs the count at the eye, which object '" + name +
                         "' leaves undefined (the camera lies in one of its face planes, or its "
                         "ray to the light grazes an edge); use auto or fail");
  }
  eye_count_ = 0;
  depth_fail_sub_objects_ = contour_edges_ = contour_loops_ = open_loops_ = 0;
  for (const VolumeChunk& chunk : chunks) {
    eye_count_ += chunk.eye_count;
    depth_fail_sub_objects_ += double(chunk.depth_fail);
    contour_edges_ += double(chunk.contour_edges);
    contour_loops_ += double(chunk.loops);
    open_loops_ += double(chunk.open_loops);
  }
  gather(chunks, polygons_, screen_);
  culled_sub_objects_ =
      double(std::count(casting.begin(), casting.end(), 0)) - shadowed_sub_objects_;
  cut_frusta(scene, complete);
}

void VolumeMethod::cut_frusta(const Scene& scene, const std::vector<char>& complete) {
  // The planes of a sub-object's shadow polygons and faces bound its volume where its
  // vertices lie on one side: the receiver test then knows the volume of a closed convex
  // sub-object exactly, if each of its contour edges has its polygon (\p complete).
  std::vector<std::size_t> runs;  // where each sub-object's polygons begin
  for (std::size_t i = 0; i < polygons_.size(); ++i) {
    if (i == 0 || polygons_[i].sub_object != polygons_[i - 1].sub_object) runs.push_back(i);
  }
  runs.push_back(polygons_.size());
  // A sub-object that is not convex never gets its exact volume: its cuts only tighten the
  // receiver test, so it tries only its first planes. (The knot, one part of 576k faces,
  // spent 14 ms on one thread trying them all, nearly all of them refused.)
  constexpr std::size_t kNotConvexTries = 256;
  tbb::parallel_for(std::size_t(0), runs.size() - 1, [&](std::size_t r) {
    const std::uint32_t k = polygons_[runs[r]].sub_object;
    const std::span<const Vec3> corners = parts_.corners(k);
    std::size_t tries =
        parts_.convex[k] ? std::numeric_limits<std::size_t>::max() : kNotConvexTries;
    for (std::size_t i = runs[r]; i < runs[r + 1] && tries > 0; ++i, --tries) {
      frusta_[k].cut(corners, {polygons_[i].normal, polygons_[i].d});
    }
    for (auto f = parts_.faces(k).begin(); f != parts_.faces(k).end() && tries > 0; ++f, --tries) {
      frusta_[k].cut(corners, scene.face_plane(*f));
    }
    if (parts_.convex[k] && complete[k]) frusta_[k].make_exact();
  });
}

void VolumeMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                         const Context& /*ctx*/) {
  const StencilStats stats = count_shadow_polygons(polygons_, screen_, eye_count_, scene, light_,
                                                   parts_, frusta_, surfaces, mask, items_);
  fill_ = double(stats.fill);
  negative_counts_ = double(stats.negative);
  receiver_culled_ = double(stats.receiver_culled);
  convex_volumes_ = double(stats.convex_volumes);
  shadowed_cells_ = double(stats.shadowed_cells);
}

std::size_t VolumeMethod::memory_bytes() const {
  return items_.capacity() * sizeof(const raster::ScreenPolygon*) +
         screen_.capacity() * sizeof(raster::ScreenPolygon) +
         polygons_.capacity() * sizeof(ShadowPolygon) + frusta_.memory_bytes() +
         parts_.memory_bytes();
}

MethodCounters VolumeMethod::counters() const {
  return {{"contour_edges", contour_edges_},
          {"contour_loops", contour_loops_},
          {"open_contour_loops", open_loops_},
          {"shadow_polygons", double(polygons_.size())},
          {"depth_fail_sub_objects", depth_fail_sub_objects_},
          {"culled_sub_objects", culled_sub_objects_},
          {"shadowed_sub_objects", shadowed_sub_objects_},
          {"receiver_culled", receiver_culled_},
          {"fill", fill_},
          {"negative_counts", negative_counts_},
          {"convex_volumes", convex_volumes_},
          {"shadowed_cells", shadowed_cells_}};
}

std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options) {
  return std::make_unique<VolumeMethod>(options);
}

}  // namespace shadowkit::volume
