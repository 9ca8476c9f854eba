#pragma once
/// \brief The comparison report: an HTML page with the images side by side.
#include <filesystem>
#include <optional>
#include <vector>

#include "shadowkit/app/pipeline.h"
#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief Everything compare measured, per method (runs in light order).
struct ComparedMethod {
  std::string name;
  std::vector<MethodRun> runs;
  /// Per light; nothing where this method or the reference failed on the light.
  std::vector<std::optional<MaskComparison>> against_reference;
};

/// Writes DIR/index.html with, per method, the shaded image, and per light the mask and the
/// difference image against the reference (the first method), all as PNGs in DIR. A method
/// that failed on a light shows the reason there and in the table, and no shaded image.
void write_report(const std::filesystem::path& dir, const Scene& scene, const CameraPass& pass,
                  const std::vector<ComparedMethod>& methods);

}  // namespace shadowkit
