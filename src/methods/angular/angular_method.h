#pragma once
// angular: Thakur, Cheng & Miura, RE loops in an angular lookup table.
#include <optional>

#include "angular_lookup.h"
#include "angular_table.h"
#include "light_frame.h"
#include "ridge_edges.h"
#include "scan_line_run.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/sub_objects.h"

namespace shadowkit::angular {

/// \brief Per light: the RE loops sliced into a table indexed by the scan-line angle theta
/// (option `resolution` = R, 0 or absent: automatic, eq4: eq. 4 as written; `saturated` = 0
/// keeps covered pairs, Sec. 10; `exact` = 0 drops the exact assists); per scan line: one
/// lookup per run of pixels, the answer held until nextX or the maximum run length of eq. 7.
class AngularMethod final : public ShadowMethod {
 public:
  explicit AngularMethod(const MethodOptions& options);
  std::string_view name() const override { return "angular"; }
  void prepare(const Scene& scene, const Context& ctx) override;
  void build(const Scene& scene, std::size_t light, const Context& ctx) override;
  void shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
             const Context& ctx) override;
  /// The table and the build's buffers, kept for the next build.
  std::size_t memory_bytes() const override {
    return table_.memory_bytes() + table_buffers_.memory_bytes() + parts_.memory_bytes();
  }
  MethodCounters counters() const override;

 private:
  // From the first pixel of a run (\p query, in unwrapped entry \p k) within a stretch of one
  // face that ends at \p face_end: the column after the run lit across the entry's block
  // (lit_across_block), where the light grazes neither end of it; nullopt otherwise.
  std::optional<int> lit_block_run(const ScanLineRun& run, const LookupQuery& query, int k,
                                   int face_end) const;
  // Whether a scan line tries blocks: on the current stretch of one face, until a block fails
  // to answer on it; on the whole line, while the pixels blocks saved, less two runs of the
  // fine lookup per try (a block holds more and longer pairs: a lookup in it costs about
  // two), stay above -kBlockEntries: they do not pay where shadows or pairs crowd.
  struct BlockTries {
    bool stretch = true;
    int credit = 0;
    bool tried = false;  ///< the last run tried one
  };
  // The column after the run from \p query's point (in unwrapped entry \p k) answered by
  // \p result, which holds up to \p stop within the entry (\p left_entry: the run leaves the
  // entry there, not its pairs), extended across entries: in shadow while the shadowing face
  // shadows it exactly, lit across the entry's block (lit_block_run).
  int extend_run(const ScanLineRun& run, const LookupQuery& query, int k,
                 const LookupResult& result, bool left_entry, int stop, int face_end,
                 BlockTries& tries) const;
  // Shades one scan line; returns its lookup calls.
  std::size_t shade_row(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
                        int row) const;

  AngularTableOptions table_options_;
  SubObjects parts_;
  Light light_;
  std::optional<LightFrame> frame_;
  AngularTable table_;
  AngularTableBuffers table_buffers_;
  ThetaBoundaries boundaries_;
  double depth_tolerance_ = 0;
  /// The exact assists the papers do not have: faces wholly behind a receiver culled,
  /// grazed faces re-checked, shadowed runs extended by their face's exact shadow.
  bool exact_ = true;
  bool block_runs_ = false;  ///< runs may be answered across a block of entries
  double lookup_calls_ = 0;
  double shadowed_sub_objects_ = 0;
};

}  // namespace shadowkit::angular
