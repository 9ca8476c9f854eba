#pragma once
// The lookup table of angular spans (discretized-shadow-volume paper, Secs. 3-5, 7 and 10).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "angular_pair.h"
#include "light_frame.h"
#include "phi_begin_sort.h"
#include "ridge_edges.h"
#include "shadowkit/core/context.h"

namespace shadowkit::angular {

/// \brief An occluding face in light-frame coordinates: the depth of its pairs (Sec. 5).
struct HiddenFace {
  FrameAffine plane;
  double light_side = 0;   ///< sign of the plane at the light: +1 or -1
  std::uint32_t face = 0;  ///< global face id

  /// \p p lies beyond the plane, seen from the light, by more than \p tolerance.
  bool behind(Vec3 p, double tolerance) const { return plane.at(p) * light_side < -tolerance; }
};

/// \brief theta quantized to R integer entries (Sec. 3): entry k holds theta in
/// [lower(k), lower(k + 1)) and is sampled at its centre. By default entries of equal width
/// step from theta_min. With hemispheres (Sec. 11.2), R / 2 entries lie on each side of the
/// light's XY plane (theta = +-pi/2), uniform in tan(kappa theta') of each hemisphere's
/// theta' (eq. 2, in (-pi/2, pi/2)): finer towards theta' = +-pi/2, where eq. 4 asks for
/// more, up to 1 + kHemisphereTan^2 times.
struct ThetaQuantization {
  double theta_min = 0, step = 1;
  int resolution = 1;
  bool full_turn = false;    ///< point light whose spans go all around it (light in the scene)
  bool hemispheres = false;  ///< with full_turn: Sec. 11.2's two variable-resolution halves

  /// The fractional entry position of \p theta (unwrapped: theta + 2 pi is R further).
  double position(double theta) const {
    return hemispheres ? hemisphere_position(theta) : (theta - theta_min) / step;
  }
  /// The theta at fractional entry position \p p; position's inverse.
  double theta_at(double p) const {
    return hemispheres ? hemisphere_theta(p) : theta_min + p * step;
  }
  /// The unwrapped entry number of \p theta: -1 below the table, R above it.
  int index(double theta) const {
    return int(std::clamp(std::floor(position(theta)), -1.0, double(resolution)));
  }
  /// The table entry of unwrapped index \p k; -1 when outside the table.
  int entry(int k) const {
    if (full_turn) return ((k % resolution) + resolution) % resolution;
    return k >= 0 && k < resolution ? k : -1;
  }
  double lower(int k) const { return theta_at(k); }
  double centre(int k) const { return theta_at(k + 0.5); }
  /// The theta span of the widest entry (with hemispheres: the ones at theta' = 0).
  double widest() const;

 private:
  double hemisphere_position(double theta) const;
  double hemisphere_theta(double p) const;
};

/// Sec. 11.2's variable resolution: tan(kappa pi / 2), the largest warped tan. Entries at
/// theta' = +-pi/2 are 1 + 7 = 8 times finer than at theta' = 0: the same ratio as the
/// cap of 8 entries per scan line of eq4_resolution.
inline const double kHemisphereTan = std::sqrt(7.0);

struct DepthForm;  // an occluding face's depth along a slice's rays, while the table is built
class Saturation;  // Sec. 10's test within one entry, while the table is built
class EntryRays;   // the entries' centre and bound directions, while the table is built

/// \brief What the table is built from and how.
struct AngularTableOptions {
  int resolution = 0;     ///< R; 0: automatic (automatic_resolution, or eq4_resolution)
  bool saturated = true;  ///< Sec. 10: drop pairs another pair of the entry already covers
  bool eq4 = false;       ///< automatic R by eq. 4 as written, not from the view's scan lines
  /// Sec. 11.2: a light inside the scene gets two hemisphere halves of variable resolution
  /// (ThetaQuantization::hemispheres), not one uniform table over the turn.
  bool hemispheres = false;
  /// RE-loops paper, Secs. 3.2-3.3 as written: branch pairs from local peaks, not the walk of
  /// the far sheets (which still pairs the objects the paper's scheme does not cover).
  bool paper_pairing = false;
  /// With paper_pairing: a pair the rules leave without a partner, or whose hidden edges do
  /// not lead to it, is walked instead. Off, the rules' pairs stand (insert_hidden_edges).
  bool walk_fallback = true;
};

/// \brief How the pairs of a table were made, with paper pairing.
struct PairingCounts {
  double paper_objects = 0;   ///< objects paired by the paper's scheme
  double walked_objects = 0;  ///< objects it does not cover (open, thin, around the light)
  double re_pairs = 0;        ///< begin-end pairs of ridge edges it made
  double fallbacks = 0;       ///< of those, the begins walked instead (kept, without the walk)
  double vrepips = 0;         ///< VREPIPs the loops were split at (RE-loops paper, Sec. 2.2)
};

/// \brief A pair and the entry it belongs to, while the table is built (24 bytes: no reach).
struct EntryPair {
  std::uint32_t entry = 0, hidden = 0;
  double phi_begin = 0, phi_end = 0;
};

/// \brief Storage one build leaves for the next (a method object builds once per light and
/// frame): kept, its capacity spares the next build the page faults of fresh allocations.
struct AngularTableBuffers {
  std::vector<std::vector<EntryPair>> lists;  ///< per chunk of RE loops, its pairs
  std::vector<AngularPair> unsorted;          ///< every pair before saturation and compaction
  std::vector<AngularPair> kept;  ///< the previous table's pairs (AngularTable::recycle)

  std::size_t memory_bytes() const {
    std::size_t bytes = (unsorted.capacity() + kept.capacity()) * sizeof(AngularPair);
    for (const auto& list : lists) bytes += list.capacity() * sizeof(EntryPair);
    return bytes;
  }
};

/// \brief Lists of pairs (a table's entries, or its blocks), each with its narrow pairs first,
/// sorted by phi_begin, and its wide ones last.
struct PairLists {
  std::vector<std::uint32_t> start;       ///< one offset per list into pairs, and the end
  std::vector<std::uint32_t> wide_count;  ///< per list: its last wide_count[k] pairs are wide
  std::vector<AngularPair> pairs;

  std::span<const AngularPair> list(int k) const {
    if (k < 0) return {};
    return {pairs.data() + start[k], pairs.data() + start[k + 1]};
  }
  /// The wide pairs of list \p k (none for k = -1, outside the table), longer than a
  /// sixteenth of the list's extent (such as a ground plane's): scanned whole by every query.
  std::span<const AngularPair> wide(int k) const {
    return k < 0 ? std::span<const AngularPair>{} : list(k).last(wide_count[k]);
  }
  /// The other pairs of list \p k, sorted by phi_begin.
  std::span<const AngularPair> narrow(int k) const {
    return k < 0 ? std::span<const AngularPair>{} : list(k).first(list(k).size() - wide_count[k]);
  }
  /// The narrow pairs of list \p k, sorted by phi_begin, from the first whose reach gets to
  /// \p phi: the ones before it all end before phi (a binary search instead of the paper's
  /// scan from the start of the entry); and the pair just before those, whose reach is the
  /// largest end before phi (nullptr if none).
  std::pair<const AngularPair*, std::span<const AngularPair>> narrow_from(int k, double phi) const;
  std::size_t memory_bytes() const {
    return pairs.capacity() * sizeof(AngularPair) +
           (start.capacity() + wide_count.capacity()) * sizeof(std::uint32_t);
  }
};

/// No occluding face (AngularTable::across).
inline constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();

/// Entries per block of AngularTable::blocks().
inline constexpr int kBlockEntries = 16;

/// \brief The lookup table: per theta entry, pairs sorted by phi_begin (Sec. 7, step 1.7).
class AngularTable {
 public:
  /// Sec. 7, step 1: every object's RE loops sliced at each entry's theta (\p sheets: per
  /// object, as occluding_sheets gives them). \p buffers, if given, lends its storage to the
  /// build and gets it back.
  static AngularTable build(const Scene& scene, const LightFrame& frame,
                            const std::vector<FarSheets>& sheets,
                            const AngularTableOptions& options,
                            AngularTableBuffers* buffers = nullptr);

  /// Empties the table; its pairs' storage goes to \p buffers for the next build (whose
  /// kept pairs, of about the same number, then need neither a fresh allocation nor its
  /// zero fill).
  void recycle(AngularTableBuffers& buffers) {
    buffers.kept = std::move(entries_.pairs);
    *this = AngularTable();
  }

  const ThetaQuantization& theta() const { return theta_; }
  /// The entries, each sorted by phi (Sec. 7, step 1.7).
  const PairLists& entries() const { return entries_; }
  /// Runs of kBlockEntries entries (the last run shorter), each with one pair per hidden
  /// face of its entries' pairs spanning them all: a point that no such pair shadows is lit in
  /// every entry of its block, so one lookup may answer across all of them (scan-line
  /// coherence across entries, where the paper's maximum run length, eq. 7, stops at one).
  /// Only where RE loops go all around the light (a light inside the scene): otherwise none.
  const PairLists& blocks() const { return blocks_; }
  std::span<const AngularPair> entry(int k) const { return entries_.list(k); }
  std::span<const AngularPair> wide(int k) const { return entries_.wide(k); }
  std::span<const AngularPair> narrow(int k) const { return entries_.narrow(k); }
  const HiddenFace& hidden(std::uint32_t i) const { return hidden_[i]; }
  std::size_t hidden_count() const { return hidden_.size(); }
  /// The occluding face of global face \p face, or kNoFace.
  std::uint32_t hidden_of(std::uint32_t face) const { return hidden_of_face_[face]; }
  /// Occluding face \p i has a corner strictly on the light's side of \p receiver (a
  /// receiving face's plane, \p light_side its sign at the light), by more than
  /// \p tolerance. The segment from a point on a face's lit side to the light lies on that
  /// side of the face's plane, so a face without such a corner cannot shadow it: among
  /// others every neighbour across a convex edge, where a pair's half-entry reach past its
  /// face (it is cut at the entry's centre theta) would otherwise fall.
  bool reaches_front_of(std::uint32_t i, const FrameAffine& receiver, double light_side,
                        double tolerance) const {
    for (std::uint32_t c = corner_start_[i]; c < corner_start_[i + 1]; ++c) {
      if (receiver.at(corners_[c]) * light_side > tolerance) return true;
    }
    return false;
  }
  /// Occluding face \p i's corners in the light frame, in the face's order.
  std::span<const Vec3> corners(std::uint32_t i) const {
    return {corners_.data() + corner_start_[i], corners_.data() + corner_start_[i + 1]};
  }
  /// Per corner of occluding face \p i, the occluding face across the manifold edge from that
  /// corner to the next: across a hidden edge the one whose far sheet continues i's, across a
  /// fold the other sheet's; kNoFace where the edge bounds the mesh or no such face occludes.
  std::span<const std::uint32_t> across(std::uint32_t i) const {
    return {across_.data() + corner_start_[i], across_.data() + corner_start_[i + 1]};
  }
  /// The ray from the light to \p p (towards the light from \p p, for a directional light)
  /// passes through occluding face \p i before \p p, by more than \p tolerance.
  bool blocks(std::uint32_t i, Vec3 p, bool point_light, double tolerance) const;
  std::size_t pair_count() const { return entries_.pairs.size(); }
  /// The ridge edges and RE loops the table was built from.
  const RidgeEdgeStats& loop_stats() const { return loop_stats_; }
  /// With paper pairing: what it paired and where it fell back to the walk.
  const PairingCounts& pairing() const { return pairing_; }
  /// Pairs dropped by saturation (Sec. 10).
  std::size_t saturated_count() const { return saturated_; }
  std::size_t memory_bytes() const {
    return entries_.memory_bytes() + blocks_.memory_bytes() +
           hidden_.capacity() * sizeof(HiddenFace) +
           (hidden_of_face_.capacity() + corner_start_.capacity() + across_.capacity()) *
               sizeof(std::uint32_t) +
           corners_.capacity() * sizeof(Vec3);
  }

 private:
  void fill_entries(std::span<const std::vector<EntryPair>> lists);
  struct SortScratch {
    PhiBeginSort sort;
    std::vector<AngularPair> pairs;  // the entry's kept wide pairs in order
  };
  // Sorts entry k and, given its saturation test, saturates it; returns the pairs kept at
  // its front.
  std::uint32_t sort_entry(int k, Saturation* saturation, SortScratch& scratch);
  // Keeps the first kept[k] pairs of every entry k, in \p storage; returns the storage they
  // were in.
  std::vector<AngularPair> compact(const std::vector<std::uint32_t>& kept,
                                   std::vector<AngularPair> storage);
  // The blocks from the kept pairs of the entries.
  void fill_blocks();

  ThetaQuantization theta_;
  PairLists entries_;
  PairLists blocks_;
  std::vector<HiddenFace> hidden_;
  std::vector<std::uint32_t> hidden_of_face_;  ///< per global face, its hidden id or kNoFace
  std::vector<std::uint32_t> corner_start_;    ///< per hidden face, into corners_
  std::vector<Vec3> corners_;                  ///< hidden faces' corners, light frame
  std::vector<std::uint32_t> across_;          ///< per corner, the sheet's face across its edge
  std::size_t saturated_ = 0;
  RidgeEdgeStats loop_stats_;
  PairingCounts pairing_;
};

}  // namespace shadowkit::angular
