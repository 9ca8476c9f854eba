#include "volume_method.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <optional>

#include "contour_edges.h"
#include "eye_count.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/volume.h"
#include "stencil_count.h"

namespace shadowkit::volume {
namespace {

// What one caster contributes for the current light.
struct CasterVolume {
  std::vector<ShadowPolygon> polygons;
  int eye_count = 0;
  std::size_t contour_edges = 0, loops = 0, open_loops = 0;
  bool depth_fail = false;
  std::vector<std::uint32_t> incomplete;  ///< sub-objects with a contour edge but no polygon
};

// Depth-pass misses crossings the near plane clips away, so it needs every shadow polygon
// farther from the eye than the near part of the view; and every face, or the view shows
// points behind a clipped face with the eye's count (a light inside a closed mesh: points
// inside it, counted 1). And it needs the eye's own count.
bool needs_depth_fail(const Mesh& mesh, const std::vector<ContourEdge>& edges, const Light& light,
                      Vec3 eye, const ViewFrustum& view, std::optional<int> eye_count) {
  if (!eye_count) return true;
  const auto near_eye = [&](const Plane& plane) {
    return std::abs(plane.distance(eye)) <= 2 * view.near_radius;
  };
  return std::any_of(edges.begin(), edges.end(),
                     [&](const ContourEdge& e) { return near_eye(side_plane(mesh, e, light)); }) ||
         std::any_of(mesh.planes.begin(), mesh.planes.end(), near_eye);
}

// Indices of the scene triangles of object \p o (they follow face order).
std::pair<std::uint32_t, std::uint32_t> object_triangles(const Scene& scene, std::uint32_t o) {
  const auto& faces = scene.triangles().triangle_face;
  const std::uint32_t first = scene.objects[o].first_face;
  const std::uint32_t last = first + std::uint32_t(scene.objects[o].mesh.face_count());
  const auto lo = std::lower_bound(faces.begin(), faces.end(), first);
  const auto hi = std::lower_bound(lo, faces.end(), last);
  return {std::uint32_t(lo - faces.begin()), std::uint32_t(hi - faces.begin())};
}

// The sub-object of a mesh edge: that of any face along it.
std::uint32_t edge_sub_object(const SceneObject& object, const SubObjects& parts,
                              std::uint32_t edge) {
  const Mesh& mesh = object.mesh;
  return parts.of_face[object.first_face + mesh.edge_uses[mesh.edges[edge].first_use].face];
}

CasterVolume caster_volume(const Scene& scene, const SubObjects& parts,
                           const std::vector<char>& casting, std::uint32_t o, const Light& light,
                           const Reach& reach, const ViewFrustum& view,
                           VolumeMethod::Counting counting) {
  CasterVolume v;
  const SceneObject& object = scene.objects[o];
  const Mesh& mesh = object.mesh;
  const Vec3 eye = scene.camera.position;
  // Contour edges of the sub-objects whose volumes can be seen, and their loops (Fig. 2).
  std::vector<ContourEdge> edges = find_contour_edges(mesh, light);
  std::erase_if(edges, [&](const ContourEdge& e) {
    return !casting[edge_sub_object(object, parts, e.edge)];
  });
  // No contour edges is no reason to stop: a closed mesh around a point light has none, and
  // its faces alone bound its volume, all space outside it (Crow Sec. VII: the polygons
  // facing the light with the shadow polygons bound the volume). No pixel ray crosses a
  // face before its visible point, so depth-pass gives every point the eye's count through
  // those faces ("the eye is in shadow"); depth-fail counts them as caps.
  const std::vector<ContourLoop> loops = chain_contour_loops(edges);
  v.contour_edges = edges.size();
  v.loops = loops.size();
  v.open_loops = std::size_t(
      std::count_if(loops.begin(), loops.end(), [](const ContourLoop& l) { return !l.closed; }));
  // Depth-pass or depth-fail for this caster. Culled sub-objects add nothing to the eye's
  // count: their volumes miss the eye.
  const std::optional<int> eye_count = faces_between_eye_and_light(mesh, eye, light);
  v.depth_fail = counting == VolumeMethod::Counting::depth_fail ||
                 (counting == VolumeMethod::Counting::automatic &&
                  needs_depth_fail(mesh, edges, light, eye, view, eye_count));
  if (!v.depth_fail && !eye_count) {
    // Only a forced depth-pass gets here: auto counts depth-fail where the eye's count is open.
    throw InputError("option 'volume.count'",
                     "pass needs the count at the eye, which object '" + object.name +
                         "' leaves undefined (the camera lies in one of its face planes, or its "
                         "ray to the light grazes an edge); use auto or fail");
  }
  v.eye_count = v.depth_fail ? 0 : *eye_count;
  // Shadow polygons (Fig. 4), and the caps that close the volumes for depth-fail.
  for (const ContourEdge& e : edges) {
    const std::uint32_t part = edge_sub_object(object, parts, e.edge);
    if (auto p = side_polygon(mesh, e, light, reach, eye, v.depth_fail)) {
      p->sub_object = part;
      for (std::uint32_t& f : p->edge_faces) f = f == kNoFace ? f : object.first_face + f;
      v.polygons.push_back(*p);
    } else {
      v.incomplete.push_back(part);
    }
  }
  if (v.depth_fail) {
    const auto [t0, t1] = object_triangles(scene, o);
    for (std::uint32_t t = t0; t < t1; ++t) {
      const std::uint32_t part = parts.of_face[scene.triangles().triangle_face[t]];
      if (casting[part]) cap_polygons(scene, t, part, light, eye, v.polygons);
    }
  }
  // Each sub-object's polygons together: the counting pass culls them per sub-object.
  const auto by_sub_object = [](const ShadowPolygon& a, const ShadowPolygon& b) {
    return a.sub_object < b.sub_object;
  };
  if (!std::is_sorted(v.polygons.begin(), v.polygons.end(), by_sub_object)) {
    std::stable_sort(v.polygons.begin(), v.polygons.end(), by_sub_object);
  }
  return v;
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
  // Crow's bounding boxes: a sub-object whose volume misses the view shadows nothing visible
  // (and, missing the eye, adds nothing to the eye's count).
  frusta_.assign(parts_.size(), ShadowFrustum{});
  std::vector<char> casting(parts_.size());
  tbb::parallel_for(std::size_t(0), parts_.size(), [&](std::size_t k) {
    frusta_[k] = ShadowFrustum(parts_.bounds[k], light_, reach);
    casting[k] = frusta_[k].reaches(view) || !frusta_[k].misses({cam.position, cam.position});
  });
  std::vector<CasterVolume> casters(scene.objects.size());
  tbb::parallel_for(std::size_t(0), casters.size(), [&](std::size_t o) {
    casters[o] =
        caster_volume(scene, parts_, casting, std::uint32_t(o), light_, reach, view, counting_);
  });

  polygons_.clear();
  eye_count_ = 0;
  contour_edges_ = contour_loops_ = open_loops_ = depth_fail_objects_ = 0;
  culled_sub_objects_ = double(std::count(casting.begin(), casting.end(), 0));
  std::vector<char> complete(parts_.size(), 1);
  for (const CasterVolume& v : casters) {
    for (std::uint32_t k : v.incomplete) complete[k] = 0;
    polygons_.insert(polygons_.end(), v.polygons.begin(), v.polygons.end());
    eye_count_ += v.eye_count;
    contour_edges_ += double(v.contour_edges);
    contour_loops_ += double(v.loops);
    open_loops_ += double(v.open_loops);
    depth_fail_objects_ += v.depth_fail;
  }
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
  tbb::parallel_for(std::size_t(0), runs.size() - 1, [&](std::size_t r) {
    const std::uint32_t k = polygons_[runs[r]].sub_object;
    const std::span<const Vec3> corners = parts_.corners(k);
    for (std::size_t i = runs[r]; i < runs[r + 1]; ++i) {
      frusta_[k].cut(corners, {polygons_[i].normal, polygons_[i].d});
    }
    for (std::uint32_t f : parts_.faces(k)) frusta_[k].cut(corners, scene.face_plane(f));
    if (parts_.convex[k] && complete[k]) frusta_[k].make_exact();
  });
}

void VolumeMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                         const Context& /*ctx*/) {
  const StencilStats stats = count_shadow_polygons(polygons_, eye_count_, scene, light_, parts_,
                                                   frusta_, surfaces, mask, stencil_buffers_);
  fill_ = double(stats.fill);
  negative_counts_ = double(stats.negative);
  receiver_culled_ = double(stats.receiver_culled);
  convex_volumes_ = double(stats.convex_volumes);
  shadowed_cells_ = double(stats.shadowed_cells);
}

std::size_t VolumeMethod::memory_bytes() const {
  return stencil_buffers_.memory_bytes() + polygons_.capacity() * sizeof(ShadowPolygon) +
         frusta_.capacity() * sizeof(ShadowFrustum) +
         parts_.of_face.capacity() * sizeof(std::uint32_t) +
         parts_.bounds.capacity() * sizeof(Bounds3);
}

MethodCounters VolumeMethod::counters() const {
  return {
      {"contour_edges", contour_edges_},           {"contour_loops", contour_loops_},
      {"open_contour_loops", open_loops_},         {"shadow_polygons", double(polygons_.size())},
      {"depth_fail_objects", depth_fail_objects_}, {"culled_sub_objects", culled_sub_objects_},
      {"receiver_culled", receiver_culled_},       {"fill", fill_},
      {"negative_counts", negative_counts_},       {"convex_volumes", convex_volumes_},
      {"shadowed_cells", shadowed_cells_}};
}

std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options) {
  return std::make_unique<VolumeMethod>(options);
}

}  // namespace shadowkit::volume
