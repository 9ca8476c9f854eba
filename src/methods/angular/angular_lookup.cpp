#include "angular_lookup.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowkit {
namespace {

// The first column after c0 where the run crosses the triangle's plane or the light rays
// through its edges: where it may leave or enter the triangle's shadow.
double triangle_change(const ScanLineRun& run, const HiddenTriangle& h, double c0) {
  double x = run.crossing(h.plane, c0);
  for (const FrameAffine& s : h.side) x = std::min(x, run.crossing(s, c0));
  return x;
}

}  // namespace

LookupResult lookup(const AngularTable& table, const ScanLineRun& run, const LookupQuery& query) {
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
    if (pair.face == query.face) return false;  // a planar face never shadows itself
    // Sec. 5: depth from the hidden face's plane; the pair's phi range holds the triangle's
    // cuts within the entry, and the triangle's own edges decide exactly.
    const HiddenTriangle& h = table.hidden(pair.hidden);
    const double change = triangle_change(run, h, query.column);
    if (h.behind(query.local, query.depth_tolerance) && h.covers(query.local)) {
      const double end = run.phi_crossing(up ? pair.phi_end : pair.phi_begin, query.column);
      next_x = std::min(end, change);
      return true;
    }
    next_x = std::min(next_x, change);  // the run may pass behind this triangle in the pair
    return false;
  };
  // Shadow is a logical OR: the first pair that shadows the point answers (Sec. 7).
  for (const AngularPair& pair : table.wide(query.entry)) {
    if (pair.phi_begin > phi || pair.phi_end < phi) {
      if (up == (pair.phi_begin > phi)) ahead(up ? pair.phi_begin : pair.phi_end);
      continue;
    }
    if (shadows(pair)) return {true, next_x};
  }
  const AngularPair* before = table.narrow_before(query.entry, phi);
  if (!up && before) ahead(before->reach);  // the narrow pairs skipped all end before phi
  for (const AngularPair& pair : table.narrow_from(query.entry, phi)) {
    if (pair.phi_begin > phi) {  // sorted by phi_begin: no later pair holds the point
      if (up) ahead(pair.phi_begin);
      break;
    }
    if (pair.phi_end < phi) {
      if (!up) ahead(pair.phi_end);
      continue;
    }
    if (shadows(pair)) return {true, next_x};
  }
  if (std::isfinite(next_phi)) next_x = std::min(next_x, run.phi_crossing(next_phi, query.column));
  return {false, next_x};
}

}  // namespace shadowkit
