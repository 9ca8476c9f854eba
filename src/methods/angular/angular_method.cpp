#include "angular_method.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include "angular_lookup.h"
#include "occluders.h"
#include "ridge_edges.h"
#include "scan_line_run.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/angular.h"
#include "shadowkit/scene/footprints.h"

namespace shadowkit::angular {

namespace {

// A 0/1 setting.
bool flag(const MethodOptions& options, const std::string& key, bool fallback) {
  const double value = options.number(key, fallback ? 1 : 0);
  if (value != 0 && value != 1) {
    throw InputError("option 'angular." + key + "'", "expected 0 or 1");
  }
  return value == 1;
}

// angular.resolution: R, 0 (automatic: the view's scan-line step), or eq4 (Sec. 3, eq. 4 as
// written).
void parse_resolution(const MethodOptions& options, AngularTableOptions& table) {
  const std::string text = options.text("resolution", "0");
  if (text == "eq4") {
    table.eq4 = true;
    return;
  }
  char* end = nullptr;
  const double r = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || r < 0 || r != std::floor(r) || r > 1e6) {
    throw InputError("option 'angular.resolution'",
                     "expected a whole number of theta entries, 0 (automatic) to 1000000, or eq4");
  }
  table.resolution = int(r);
}

// angular.light_inside: one table over the turn, or Sec. 11.2's two hemispheres.
bool hemispheres(const MethodOptions& options) {
  const std::string value = options.text("light_inside", "turn");
  if (value != "turn" && value != "hemispheres") {
    throw InputError("option 'angular.light_inside'", "expected turn or hemispheres");
  }
  return value == "hemispheres";
}

// angular.pairing: the far-sheet walk, or the RE-loops paper's branch pairs (Sec. 3.2).
bool paper_pairing(const MethodOptions& options) {
  const std::string value = options.text("pairing", "walk");
  if (value != "walk" && value != "paper") {
    throw InputError("option 'angular.pairing'", "expected walk or paper");
  }
  return value == "paper";
}

// angular.fallback: with paper pairing, whether the pairs its rules cannot make are walked.
bool walk_fallback(const MethodOptions& options, bool paper) {
  const bool fallback = flag(options, "fallback", true);
  if (!fallback && !paper) {
    throw InputError("option 'angular.fallback'", "0 needs angular.pairing=paper");
  }
  return fallback;
}

}  // namespace

AngularMethod::AngularMethod(const MethodOptions& options) {
  options.expect_only("angular",
                      {"resolution", "saturated", "exact", "light_inside", "pairing", "fallback"});
  parse_resolution(options, table_options_);
  table_options_.saturated = flag(options, "saturated", true);
  table_options_.hemispheres = hemispheres(options);
  table_options_.paper_pairing = paper_pairing(options);
  table_options_.walk_fallback = walk_fallback(options, table_options_.paper_pairing);
  exact_ = flag(options, "exact", true);
}

void AngularMethod::prepare(const Scene& scene, const Context& /*ctx*/) {
  parts_ = SubObjects::of(scene);
}

void AngularMethod::build(const Scene& scene, std::size_t light, const Context& /*ctx*/) {
  SHADOWKIT_CHECK(parts_.of_face.size() == scene.face_count());  // prepare() came first
  light_ = scene.lights[light];
  const Bounds3& box = scene.bounds();
  frame_.emplace(light_, scene.camera, (box.lo + box.hi) * 0.5);
  // Sec. 7, step 1: the RE loops of every object sliced entry by entry; but of the parts
  // wholly in the shadow of nearer ones (Crow's footprints), which add no shadow.
  const std::vector<char> shadowed = shadowed_sub_objects(parts_, light_, box);
  shadowed_sub_objects_ = double(std::count(shadowed.begin(), shadowed.end(), 1));
  std::vector<FarSheets> sheets = occluding_sheets(scene, light_);
  leave_out_shadowed(scene, parts_, shadowed, sheets);
  table_.recycle(table_buffers_);
  table_ = AngularTable::build(scene, *frame_, sheets, table_options_, &table_buffers_);
  boundaries_ = ThetaBoundaries(*frame_, table_.theta());
  depth_tolerance_ = 1e-7 * std::max(box.diagonal(), 1e-12);
  // A block's boundary planes bound it only while it spans less than half a turn.
  block_runs_ = !table_.blocks().start.empty() &&
                kBlockEntries * table_.theta().widest() < std::numbers::pi / 2;
  lookup_calls_ = 0;
}

namespace {

// The column after a run from \p x that ends at \p end, within its stretch of one face.
int run_stop(double end, int x, int face_end) {
  return int(std::clamp(std::ceil(end), double(x + 1), double(face_end)));
}

}  // namespace

std::optional<int> AngularMethod::lit_block_run(const ScanLineRun& run, const LookupQuery& query,
                                                int k, int face_end) const {
  if (grazed(query, frame_->point_light())) return std::nullopt;
  const std::optional<double> lit = lit_across_block(table_, run, query);
  if (!lit) return std::nullopt;
  // The block's unwrapped entries [first, first + n): the run holds while it stays between
  // their outer boundaries, like eq. 7's run within one entry.
  const int first = k - query.entry % kBlockEntries;
  const int n = std::min(kBlockEntries,
                         table_.theta().resolution - (query.entry - query.entry % kBlockEntries));
  const double x = query.column;
  const int stop = run_stop(std::min({*lit, run.crossing(boundaries_.lower(first), x),
                                      run.crossing(boundaries_.lower(first + n), x)}),
                            int(x), face_end);
  // A point light grazes a face where it is far from the light, and along the run the
  // distance is largest at an end: the run's last pixel must not be grazed either.
  LookupQuery last = query;
  last.local = run.local(stop - 1);
  if (grazed(last, frame_->point_light())) return std::nullopt;
  return stop;
}

int AngularMethod::extend_run(const ScanLineRun& run, const LookupQuery& query, int k,
                              const LookupResult& result, bool left_entry, int stop, int face_end,
                              BlockTries& tries) const {
  const int x = int(query.column);
  tries.tried = false;
  // A run that ends within its entry ends where its pair does or the run crosses a face's
  // plane: the shadowing face's shadow mostly ends there too.
  if (!left_entry) return stop;
  if (result.shadowed) {
    if (!exact_) return stop;
    // The face that shadows the point may shadow the run further.
    const std::optional<double> exact =
        exact_shadow_end(table_, *frame_, run, query, result.hidden);
    return exact ? std::max(stop, run_stop(*exact, x, face_end)) : stop;
  }
  if (!tries.stretch || tries.credit < -kBlockEntries) return stop;
  tries.tried = true;
  const std::optional<int> lit = lit_block_run(run, query, k, face_end);
  // A block that does not answer here is no likelier to further along the stretch, nearer
  // the same shadow.
  tries.stretch = lit.has_value();
  tries.credit += lit.value_or(stop) - stop - 2 * (stop - x);
  return std::max(stop, lit.value_or(stop));
}

std::size_t AngularMethod::shade_row(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                                     ShadowMask& mask, int row) const {
  const Camera& cam = scene.camera;
  const ThetaQuantization& quant = table_.theta();
  const Vec3 eye = frame_->local(cam.position);
  std::size_t lookups = 0;
  BlockTries tries;
  int x = 0;
  while (x < surfaces.width) {
    const std::size_t i = surfaces.index(x, row);
    if (!surfaces.covered(i)) {
      x = surfaces.next_covered(x, surfaces.width, row);
      continue;
    }
    // One face's stretch of the scan line.
    const std::uint32_t face = surfaces.face[i];
    int face_end = x + 1;
    while (face_end < surfaces.width && surfaces.face[surfaces.index(face_end, row)] == face) {
      ++face_end;
    }
    const Plane& plane = scene.face_plane(face);
    if (!faces_light(plane, cam.position, light_)) {  // contract condition 1
      std::fill_n(&mask.pixels[i], face_end - x, kMaskShadow);
      x = face_end;
      continue;
    }
    const ScanLineRun run(*frame_, cam, plane, row);
    const SceneObject& object = scene.objects[scene.object_of_face(face)];
    const OwnFace own_face{&object.mesh, scene.local_face(face), &*frame_, eye};
    const FrameAffine face_plane = frame_->plane(plane);
    const double face_light_side = light_side(plane, light_) > 0 ? 1 : -1;
    int k = -2;  // the entry of the previous run, unknown at the start of the stretch
    tries.stretch = block_runs_;
    while (x < face_end) {
      // Sec. 7, step 2: query the first pixel of the run.
      LookupQuery query;
      query.local = run.local(x);
      k = boundaries_.locate(query.local, k);
      query.entry = quant.entry(k);
      query.phi = frame_->phi_local(query.local);
      query.face = face;
      query.face_plane = face_plane;
      query.face_light_side = face_light_side;
      query.column = x;
      query.phi_increasing = run.phi_increasing(x);
      query.depth_tolerance = depth_tolerance_;
      query.cull_faces_behind = exact_;
      query.own_face = exact_ ? &own_face : nullptr;
      const LookupResult result =
          exact_ ? lookup_on_sheets(table_, *frame_, run, query, k,
                                    grazed(query, frame_->point_light(), kRecheckSine))
                 : lookup(table_, run, query);
      lookups += std::size_t(result.lookups);
      // Steps 3-4: hold the answer until nextX or the end of the maximum run (eq. 7), or
      // further across entries.
      const double entry_end = max_run_end(run, boundaries_, k, x);
      int stop = run_stop(std::min(result.next_x, entry_end), x, face_end);
      if (stop < face_end) {
        stop = extend_run(run, query, k, result, entry_end < result.next_x, stop, face_end, tries);
        lookups += tries.tried;
      }
      std::fill_n(&mask.pixels[surfaces.index(x, row)], stop - x,
                  result.shadowed ? kMaskShadow : kMaskLit);
      x = stop;
    }
  }
  return lookups;
}

void AngularMethod::shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                          ShadowMask& mask, const Context& /*ctx*/) {
  tbb::combinable<std::size_t> lookups;
  tbb::parallel_for(0, surfaces.height,
                    [&](int row) { lookups.local() += shade_row(scene, surfaces, mask, row); });
  lookup_calls_ = double(lookups.combine(std::plus<>()));
}

MethodCounters AngularMethod::counters() const {
  const RidgeEdgeStats& loops = table_.loop_stats();
  MethodCounters out{{"ridge_edges", loops.ridge_edges},
                     {"re_loops", loops.loops},
                     {"open_re_loops", loops.open_loops},
                     {"theta_resolution", double(table_.theta().resolution)},
                     {"table_pairs", double(table_.pair_count())},
                     {"saturated_pairs", double(table_.saturated_count())},
                     {"table_bytes", double(table_.memory_bytes())},
                     {"lookup_calls", lookup_calls_},
                     {"shadowed_sub_objects", shadowed_sub_objects_}};
  if (table_options_.paper_pairing) {
    const PairingCounts& p = table_.pairing();
    out.insert(out.end(), {{"paper_objects", p.paper_objects},
                           {"walked_objects", p.walked_objects},
                           {"re_pairs", p.re_pairs},
                           {"pairing_fallbacks", p.fallbacks},
                           {"vrepips", p.vrepips}});
  }
  return out;
}

std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options) {
  return std::make_unique<AngularMethod>(options);
}

}  // namespace shadowkit::angular
