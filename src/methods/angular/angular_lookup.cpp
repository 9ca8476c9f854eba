#include "angular_lookup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace shadowkit::angular {
namespace {

// How far beyond a pair's face a point may lie for the test against its own face's outline
// (OwnFace) to be made, in depth tolerances: the scan converter's rounding puts a point
// outside its face by far less, and the test is rare.
constexpr double kOffFaceReach = 1000;

// Whether \p h passes no farther beyond the queried point than the point lies outside its
// own face, and the camera sees it from the light's side: the neighbour across the edge,
// truly seen there, is then lit by condition 1, not a shadow on the point. Seen from the
// other side, it stays a shadow, as condition 1 would have it.
bool within_off_face_rounding(const HiddenFace& h, const LookupQuery& query) {
  if (!query.own_face) return false;
  const double beyond = -h.plane.at(query.local) * h.light_side;  // in |a| units
  const double reach = kOffFaceReach * query.depth_tolerance;
  if (!(beyond * beyond < reach * reach * dot(h.plane.a, h.plane.a))) return false;
  if (!(h.plane.at(query.own_face->eye) * h.light_side > 0)) return false;
  return beyond / length(h.plane.a) <= query.own_face->outside(query.local) + query.depth_tolerance;
}

// The column where the run from the queried point leaves the exact shadow of occluding face
// \p i, which blocks the point (the next column where it does not by the tolerance).
double exact_end(const AngularTable& table, const LightFrame& frame, const ScanLineRun& run,
                 const LookupQuery& query, std::uint32_t i) {
  return exact_shadow_end(table, frame, run, query, i).value_or(query.column + 1);
}

// The unwrapped entry whose centre lies on the other side of the queried point's theta from
// the centre of its own, unwrapped entry \p k.
int entry_beside(const ThetaQuantization& q, const LightFrame& frame, const LookupQuery& query,
                 int k) {
  double past_centre = frame.angular_local(query.local).theta - q.centre(k);
  if (frame.point_light()) past_centre = std::remainder(past_centre, 2 * std::numbers::pi);
  return past_centre < 0 ? k - 1 : k + 1;
}

// On a grazed face, a neighbour across a concave edge casts a sliver of shadow thinner than
// an entry, which no pair of the entries around a point may hold: the occluding face across a
// side of the point's own face that blocks it.
std::optional<std::uint32_t> neighbour_blocking(const AngularTable& table, bool point_light,
                                                const LookupQuery& query) {
  if (!query.own_face) return std::nullopt;
  const Mesh& mesh = *query.own_face->mesh;
  const std::uint32_t own = query.own_face->face, first_face = query.face - own;
  for (std::uint32_t c = mesh.face_start[own]; c < mesh.face_start[own + 1]; ++c) {
    const MeshEdge& edge = mesh.edges[mesh.corner_edge[c]];
    for (std::uint32_t u = edge.first_use; u < edge.first_use + edge.use_count; ++u) {
      const std::uint32_t i = table.hidden_of(first_face + mesh.edge_uses[u].face);
      if (i != kNoFace && table.hidden(i).face != query.face &&
          table.blocks(i, query.local, point_light, query.depth_tolerance) &&
          table.reaches_front_of(i, query.face_plane, query.face_light_side,
                                 query.depth_tolerance)) {
        return i;
      }
    }
  }
  return std::nullopt;
}

// Sec. 7's lookup in list \p k of \p lists (an entry of the table, or a block of entries);
// with \p sheet_frame, its shadows checked on their far sheets (lookup_on_sheets).
LookupResult lookup_in(const AngularTable& table, const PairLists& lists, int k,
                       const ScanLineRun& run, const LookupQuery& query,
                       const LightFrame* sheet_frame = nullptr) {
  const double phi = query.phi;
  const bool up = query.phi_increasing;
  double next_x = std::numeric_limits<double>::infinity();
  bool refuted = false;
  // The nearest pair boundary ahead along the run.
  double next_phi = up ? next_x : -next_x;
  const auto ahead = [&](double boundary) {
    next_phi = up ? std::min(next_phi, boundary) : std::max(next_phi, boundary);
  };
  // One pair holding phi: the occluding face that shadows the point through it, if any,
  // with next_x where that may end.
  const auto shadows = [&](const AngularPair& pair) -> std::optional<std::uint32_t> {
    // Sec. 5: the pair is one hidden face's cut, so its depth is the face's plane.
    const HiddenFace& h = table.hidden(pair.hidden);
    if (h.face == query.face) return std::nullopt;  // a planar face never shadows itself
    if (h.behind(query.local, query.depth_tolerance) &&
        (!query.cull_faces_behind ||
         table.reaches_front_of(pair.hidden, query.face_plane, query.face_light_side,
                                query.depth_tolerance)) &&
        !within_off_face_rounding(h, query)) {
      if (sheet_frame && !table.blocks(pair.hidden, query.local, sheet_frame->point_light(),
                                       query.depth_tolerance)) {
        const std::optional<std::uint32_t> face =
            blocker_on_sheet(table, *sheet_frame, query, pair.hidden);
        if (face) {
          next_x = exact_end(table, *sheet_frame, run, query, *face);
          return face;
        }
        refuted = true;  // nor is the answer taken past this pixel
        next_x = std::min(next_x, query.column + 1);
        return std::nullopt;
      }
      const double end = run.phi_crossing(up ? pair.phi_end : pair.phi_begin, query.column);
      next_x = std::min(end, run.crossing(h.plane, query.column));
      return pair.hidden;
    }
    // The run may pass behind this face in the pair, where it gets beyond the plane by the
    // tolerance: a point within the tolerance, not behind yet, may have passed the plane.
    const FrameAffine behind_by_tolerance{h.plane.a,
                                          h.plane.b + h.light_side * query.depth_tolerance};
    next_x = std::min(next_x, run.crossing(behind_by_tolerance, query.column));
    return std::nullopt;
  };
  // Shadow is a logical OR: the first pair that shadows the point answers (Sec. 7).
  for (const AngularPair& pair : lists.wide(k)) {
    if (pair.phi_begin > phi || pair.phi_end < phi) {
      if (up == (pair.phi_begin > phi)) ahead(up ? pair.phi_begin : pair.phi_end);
      continue;
    }
    if (const std::optional<std::uint32_t> face = shadows(pair)) {
      return {true, next_x, 1, *face, refuted};
    }
  }
  const auto [before, narrow] = lists.narrow_from(k, phi);
  if (!up && before) ahead(before->reach);  // the narrow pairs skipped all end before phi
  for (const AngularPair& pair : narrow) {
    if (pair.phi_begin > phi) {  // sorted by phi_begin: no later pair holds the point
      if (up) ahead(pair.phi_begin);
      break;
    }
    if (pair.phi_end < phi) {
      if (!up) ahead(pair.phi_end);
      continue;
    }
    if (const std::optional<std::uint32_t> face = shadows(pair)) {
      return {true, next_x, 1, *face, refuted};
    }
  }
  if (std::isfinite(next_phi)) next_x = std::min(next_x, run.phi_crossing(next_phi, query.column));
  return {false, next_x, 1, 0, refuted};
}

}  // namespace

LookupResult lookup(const AngularTable& table, const ScanLineRun& run, const LookupQuery& query) {
  return lookup_in(table, table.entries(), query.entry, run, query);
}

std::optional<double> lit_across_block(const AngularTable& table, const ScanLineRun& run,
                                       const LookupQuery& query) {
  if (query.entry < 0) return std::nullopt;
  const LookupResult block =
      lookup_in(table, table.blocks(), query.entry / kBlockEntries, run, query);
  if (block.shadowed) return std::nullopt;
  return block.next_x;
}

std::optional<double> exact_shadow_end(const AngularTable& table, const LightFrame& frame,
                                       const ScanLineRun& run, const LookupQuery& query,
                                       std::uint32_t hidden) {
  const HiddenFace& h = table.hidden(hidden);
  if (!h.behind(query.local, query.depth_tolerance)) return std::nullopt;
  double end = run.crossing(h.plane, query.column);
  const std::span<const Vec3> corners = table.corners(hidden);
  double side = 0;  // the sign of the first side's plane at the point
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const FrameAffine sweep = frame.ray_plane(corners[i], corners[(i + 1) % corners.size()]);
    // The point's distance from the swept plane, with the sign of its side.
    const double distance = sweep.at(query.local) / length(sweep.a);
    if (!(std::abs(distance) > query.depth_tolerance)) return std::nullopt;
    if (side == 0) side = distance;
    if ((distance > 0) != (side > 0)) return std::nullopt;
    end = std::min(end, run.crossing(sweep, query.column));
  }
  return end;
}

std::optional<std::uint32_t> blocker_on_sheet(const AngularTable& table, const LightFrame& frame,
                                              const LookupQuery& query, std::uint32_t hidden) {
  std::uint32_t f = hidden, previous = kNoFace;
  for (int step = 0; step < kSheetSteps && f != kNoFace; ++step) {
    const std::span<const Vec3> corners = table.corners(f);
    const std::size_t n = corners.size();
    Vec3 centroid{};
    for (const Vec3& c : corners) centroid = centroid + c;
    centroid = centroid * (1.0 / double(n));
    // The side whose ray plane the point lies farthest outside of, seen from the face's
    // centroid.
    double farthest = 0;
    std::size_t exit = n;
    for (std::size_t j = 0; j < n; ++j) {
      const FrameAffine sweep = frame.ray_plane(corners[j], corners[(j + 1) % n]);
      const double out = -sweep.at(query.local) * (sweep.at(centroid) > 0 ? 1 : -1);
      if (out > farthest * length(sweep.a)) {
        farthest = out / length(sweep.a);
        exit = j;
      }
    }
    if (exit == n) {
      if (table.blocks(f, query.local, frame.point_light(), query.depth_tolerance)) return f;
      return std::nullopt;
    }
    const std::uint32_t next = table.across(f)[exit];
    if (next == previous) return std::nullopt;
    previous = f;
    f = next;
  }
  return std::nullopt;
}

bool grazed(const LookupQuery& query, bool point_light, double sine_below) {
  const FrameAffine& plane = query.face_plane;
  // Point light: the distance from the light (the origin) to the plane over the distance to
  // the point; directional: the light's direction is the frame's Z axis.
  const double sine = point_light ? std::abs(plane.b) / length(query.local) : std::abs(plane.a.z);
  return sine < sine_below * length(plane.a);
}

LookupResult lookup_on_sheets(const AngularTable& table, const LightFrame& frame,
                              const ScanLineRun& run, const LookupQuery& query, int k,
                              bool on_grazed_face) {
  // The point lies in face i's exact shadow, and so does the run until it leaves it: on a
  // grazed face a pair's end, cut at its entry's centre, may lie pixels away from the edge.
  const auto exact = [&](std::uint32_t i, int lookups) -> LookupResult {
    return {true, exact_end(table, frame, run, query, i), lookups, i};
  };
  const LookupResult own = lookup_in(table, table.entries(), query.entry, run, query, &frame);
  if (own.shadowed) return on_grazed_face ? exact(own.hidden, 1) : own;
  if (!on_grazed_face && !own.refuted) return own;
  // The face that shadows the point, if one does, may cross the slice on the other side of
  // its theta instead.
  const ThetaQuantization& q = table.theta();
  LookupQuery across = query;
  across.entry = q.entry(entry_beside(q, frame, query, k));
  const LookupResult beside = lookup_in(table, table.entries(), across.entry, run, across, &frame);
  if (beside.shadowed) return exact(beside.hidden, 2);
  if (on_grazed_face) {
    if (const auto i = neighbour_blocking(table, frame.point_light(), query)) return exact(*i, 2);
  }
  if (own.refuted || beside.refuted) return {false, query.column + 1, 2};
  // Both lit: that holds while both answers do and the point stays on this side of the
  // entry's centre.
  return {false,
          std::min({own.next_x, beside.next_x,
                    run.crossing(frame.theta_plane(q.centre(k)), query.column)}),
          2};
}

}  // namespace shadowkit::angular
