#pragma once
// The reports' tests' study: a small scene on disk and a study folder written by hand, with
// fractions each test chooses, so that every value of a report is known exactly.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shadowkit/scene/scene.h"
#include "study_polygons.h"
#include "study_reports.h"

namespace shadowkit::sun_study {

/// \brief Four objects and their 8 polygons (rows of polygons.csv):
/// - object 0 "Roof": row 0 (area 1), row 1 (area 3);
/// - object 1 "wall,east": row 2 (area 2), row 3 (degenerate, area 0);
/// - object 2 "roof", object 1's mesh moved 5 along z: row 4 (area 2), row 5 (area 0);
/// - object 3 "  ", object 0's mesh moved 5 along x: row 6 (area 1), row 7 (area 3).
class HandStudy {
 public:
  explicit HandStudy(const std::string& name);
  ~HandStudy();
  HandStudy(const HandStudy&) = delete;
  HandStudy& operator=(const HandStudy&) = delete;

  const std::filesystem::path& dir() const { return dir_; }
  const Scene& scene() const { return scene_; }
  Polygons& polygons() { return polygons_; }

  /// Writes the contract's files and sun_study.json: step k at \p first_utc (YYYY-MM-DDTHH:MM,
  /// UTC) + k * \p step_minutes, with the 8 fractions \p fractions[k], the sun up where one
  /// of them is above 0.
  void write_study(const std::string& first_utc, int step_minutes,
                   const std::vector<std::vector<float>>& fractions, double utc_offset_hours = 0);
  /// The record of the study write_study() wrote.
  StudyRecord record() const;
  /// The lines of a file of the study's folder.
  std::vector<std::string> lines(const std::string& name) const;

 private:
  std::filesystem::path dir_;
  Scene scene_;
  Polygons polygons_;
  double step_hours_ = 0, utc_offset_hours_ = 0;
  std::int64_t steps_ = 0;
};

}  // namespace shadowkit::sun_study
