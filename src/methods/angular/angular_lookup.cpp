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

// Sec. 7's lookup in list \p k of \p lists (an entry of the table, or a block of entries).
LookupResult lookup_in(const AngularTable& table, const PairLists& lists, int k,
                       const ScanLineRun& run, const LookupQuery& query) {
  const double phi = query.phi;
  const bool up = query.phi_increasing;
  double next_x = std::numeric_limits<double>::infinity();
  // The nearest pair boundary ahead along the run.
  double next_phi = up ? next_x : -next_x;
  const auto ahead = [&](double boundary) {
    next_phi = up ? std::min(next_phi, boundary) : std::max(next_phi, boundary);
  };
  // One pair holding phi: true when it shadows the point, with next_x where that may end.
  const auto shadows = [&](const AngularPair& pair) {
    // Sec. 5: the pair is one hidden face's cut, so its depth is the face's plane.
    const HiddenFace& h = table.hidden(pair.hidden);
    if (h.face == query.face) return false;  // a planar face never shadows itself
    if (h.behind(query.local, query.depth_tolerance) &&
        (!query.cull_faces_behind ||
         table.reaches_front_of(pair.hidden, query.face_plane, query.face_light_side,
                                query.depth_tolerance)) &&
        !within_off_face_rounding(h, query)) {
      const double end = run.phi_crossing(up ? pair.phi_end : pair.phi_begin, query.column);
      next_x = std::min(end, run.crossing(h.plane, query.column));
      return true;
    }
    // The run may pass behind this face in the pair, where it gets beyond the plane by the
    // tolerance: a point within the tolerance, not behind yet, may have passed the plane.
    const FrameAffine behind_by_tolerance{h.plane.a,
                                          h.plane.b + h.light_side * query.depth_tolerance};
    next_x = std::min(next_x, run.crossing(behind_by_tolerance, query.column));
    return false;
  };
  // Shadow is a logical OR: the first pair that shadows the point answers (Sec. 7).
  for (const AngularPair& pair : lists.wide(k)) {
    if (pair.phi_begin > phi || pair.phi_end < phi) {
      if (up == (pair.phi_begin > phi)) ahead(up ? pair.phi_begin : pair.phi_end);
      continue;
    }
    if (shadows(pair)) return {true, next_x, 1, pair.hidden};
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
    if (shadows(pair)) return {true, next_x, 1, pair.hidden};
  }
  if (std::isfinite(next_phi)) next_x = std::min(next_x, run.phi_crossing(next_phi, query.column));
  return {false, next_x};
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

bool grazed(const LookupQuery& query, bool point_light) {
  const FrameAffine& plane = query.face_plane;
  // Point light: the distance from the light (the origin) to the plane over the distance to
  // the point; directional: the light's direction is the frame's Z axis.
  const double sine = point_light ? std::abs(plane.b) / length(query.local) : std::abs(plane.a.z);
  return sine < kGrazingSine * length(plane.a);
}

LookupResult lookup_grazing(const AngularTable& table, const LightFrame& frame,
                            const ScanLineRun& run, const LookupQuery& query, int k) {
  const LookupResult own = lookup(table, run, query);
  const bool point_light = frame.point_light();
  // The point lies in face i's exact shadow, and so does the run until it leaves it: on a
  // grazed face a pair's end, cut at its entry's centre, may lie pixels away from the edge.
  const auto exact = [&](std::uint32_t i, int lookups) -> LookupResult {
    const std::optional<double> end = exact_shadow_end(table, frame, run, query, i);
    return {true, end ? *end : query.column + 1, lookups, i};
  };
  if (own.shadowed && table.blocks(own.hidden, query.local, point_light, query.depth_tolerance)) {
    return exact(own.hidden, 1);
  }
  const ThetaQuantization& q = table.theta();
  const double centre = q.centre(k);
  double past_centre = frame.angular_local(query.local).theta - centre;
  if (point_light) past_centre = std::remainder(past_centre, 2 * std::numbers::pi);
  const int other = past_centre < 0 ? k - 1 : k + 1;
  LookupQuery across = query;
  across.entry = q.entry(other);
  const LookupResult beside = lookup(table, run, across);
  if (beside.shadowed &&
      table.blocks(beside.hidden, query.local, point_light, query.depth_tolerance)) {
    return exact(beside.hidden, 2);
  }
  if (!own.shadowed && !beside.shadowed) {
    // Both lit: that holds while both answers do and the point stays on this side of the
    // entry's centre.
    return {false,
            std::min(
                {own.next_x, beside.next_x, run.crossing(frame.theta_plane(centre), query.column)}),
            2};
  }
  const auto blocks = [&](std::uint32_t i) {
    return table.hidden(i).face != query.face &&
           table.blocks(i, query.local, point_light, query.depth_tolerance) &&
           table.reaches_front_of(i, query.face_plane, query.face_light_side,
                                  query.depth_tolerance);
  };
  for (const int near : {q.entry(k), q.entry(other)}) {
    for (const AngularPair& pair : table.entry(near)) {
      if (blocks(pair.hidden)) return exact(pair.hidden, 2);
    }
    for (const std::uint32_t i : table.covered(near)) {
      if (blocks(i)) return exact(i, 2);
    }
  }
  // A face thinner than the gap between the two slices crosses neither.
  for (const std::uint32_t i : table.between(std::min(k, other))) {
    if (blocks(i)) return exact(i, 2);
  }
  return {false, query.column + 1, 2};
}

}  // namespace shadowkit::angular
