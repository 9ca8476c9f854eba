#pragma once
// The shadow query of the discretized-shadow-volume paper, Sec. 7, step 2.
#include <cstdint>
#include <optional>

#include "angular_table.h"
#include "own_face.h"
#include "scan_line_run.h"

namespace shadowkit::angular {

/// \brief The answer of one lookup and the column where it may stop holding (nextX).
struct LookupResult {
  bool shadowed = false;
  double next_x = 0;
  int lookups = 1;           ///< entries scanned for it
  std::uint32_t hidden = 0;  ///< when shadowed: the occluding face that shadows it
  bool refuted = false;      ///< a pair's shadow did not hold on its sheet (lookup_on_sheets)
};

/// \brief What a lookup needs to know about the queried visible point.
struct LookupQuery {
  int entry = -1;              ///< table entry of its theta
  double phi = 0;              ///< eq. 3, as AngularPoint keeps it
  Vec3 local;                  ///< light-frame coordinates
  std::uint32_t face = 0;      ///< its face: a planar face never shadows itself
  FrameAffine face_plane;      ///< its face's plane, light frame
  double face_light_side = 1;  ///< sign of face_plane at the light
  double column = 0;           ///< its pixel column on the scan line
  bool phi_increasing = true;  ///< phi grows with the column along this run
  double depth_tolerance = 0;  ///< distance from a hidden face's plane still counted on it
  /// Skip faces wholly behind the point's face (AngularTable::reaches_front_of), an exact
  /// assist the papers do not have (angular.exact).
  bool cull_faces_behind = true;
  /// Its face as the scan converter chose it: a pair's face that passes nearer the point
  /// than the point lies outside its own face shadows it only by the scan converter's
  /// rounding, and does not (angular.exact; none: every pair counts).
  const OwnFace* own_face = nullptr;
};

/// Sec. 7: scans entry theta's pairs holding phi, stops at the first pair that shadows the
/// point (shadow is a logical OR) and returns the column where the answer may change (nextX):
/// the pair's end, the start of the next pair, or where the run crosses the plane of the
/// hidden face of a pair holding phi.
LookupResult lookup(const AngularTable& table, const ScanLineRun& run, const LookupQuery& query);

/// The lookup in the block of the queried entry (AngularTable::blocks): where none of its
/// pairs shadows the point, the point is lit in every entry of the block, and so is the run
/// up to the returned column, as long as it stays in the block; nullopt where a pair may
/// shadow it (the blocks' pairs span a face's pairs in several entries, so only their lit
/// answers hold).
std::optional<double> lit_across_block(const AngularTable& table, const ScanLineRun& run,
                                       const LookupQuery& query);

/// Where the run from the queried point leaves the shadow that occluding face \p hidden casts
/// on it, exactly: the point lies beyond the face's plane and on the face's side of every
/// plane the light's rays sweep through its sides, so the ray from the light meets the face
/// (a non-convex face: in its kernel); the run stays in that shadow, whatever entries it
/// crosses, until it passes one of those planes. nullopt when the point is not within them
/// by more than the query's depth tolerance.
std::optional<double> exact_shadow_end(const AngularTable& table, const LightFrame& frame,
                                       const ScanLineRun& run, const LookupQuery& query,
                                       std::uint32_t hidden);

/// The occluding face that blocks the queried point exactly, found on the far sheet of face
/// \p hidden by walking from it towards the point's ray, from face to occluding face across
/// their edges (AngularTable::across: hidden edges, and folds onto the other sheet), at most
/// kSheetSteps faces: a pair cut at its entry's centre theta names a face beside the one
/// whose shadow the point lies in. nullopt where the walk leaves the occluding faces, would
/// step back, meets the ray in front of the point, or runs out of steps.
std::optional<std::uint32_t> blocker_on_sheet(const AngularTable& table, const LightFrame& frame,
                                              const LookupQuery& query, std::uint32_t hidden);
inline constexpr int kSheetSteps = 16;

/// Whether the light grazes the queried point's face: the light's rays meet its plane there
/// at a sine below \p sine. An angular error of the table (a pair cut at its entry's centre
/// theta answers for the whole entry) moves a shadow's edge on such a face by that error over
/// the sine, many pixels, and a receiver in the light's own plane maps to a sliver of the
/// table thinner than an entry, which no R resolves.
inline constexpr double kGrazingSine = 0.07;
bool grazed(const LookupQuery& query, bool point_light, double sine = kGrazingSine);
/// Where the lookup re-checks a point against the neighbouring entry (lookup_on_sheets):
/// beyond kGrazingSine, below which the automatic R leaves points to the re-check, since just
/// above it an entry's error still moves a shadow's edge past a pixel's centre where a sheet
/// nearly edge-on to the light shadows itself (two of 74,000 random lights, at sines of 0.08).
inline constexpr double kRecheckSine = 0.12;

/// lookup, with every shadow it finds checked on its far sheet (angular.exact): a pair's face
/// that does not block the point exactly shadows it only through the face of its sheet that
/// does (blocker_on_sheet), and then as long as the point stays in that face's exact shadow.
/// A pair cut at its entry's centre reaches up to half an entry past its face: on a finely
/// tessellated surface, past the terminators that run across its lit slopes.
/// Where no pair's shadow holds on its sheet, and always on a grazed face
/// (\p on_grazed_face), the entry whose centre lies on the other side of the point's theta
/// (\p k: the point's unwrapped entry) answers too, checked the same way: a sheet that shadows
/// the point is cut near it by one of the two slices unless it lies wholly between them, and
/// on a grazed face the table's error moves a shadow's edge by pixels. A shadow from either
/// holds while the point stays in the face's exact shadow; a lit answer after a shadow that
/// did not hold, for this pixel alone.
LookupResult lookup_on_sheets(const AngularTable& table, const LightFrame& frame,
                              const ScanLineRun& run, const LookupQuery& query, int k,
                              bool on_grazed_face);

}  // namespace shadowkit::angular
