#pragma once
// The study's steps read back from its folder in bounded blocks: each step's instant and
// whether the sun is up from times.csv, and its row of sunlit_fraction.f32, so that no
// report holds the whole T x P file.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "shadowkit/scene/sun_position.h"

namespace shadowkit::sun_study {

/// \brief The steps of a study's folder, a block at a time, in step order.
class FractionStream {
 public:
  /// InputError naming the file when times.csv or sunlit_fraction.f32 does not hold
  /// \p steps steps of \p polygons polygons.
  FractionStream(const std::filesystem::path& dir, std::int64_t steps, std::size_t polygons);

  /// Reads the next block; false when every step has been read.
  bool next();
  std::size_t size() const { return instants_.size(); }
  sun::Instant instant(std::size_t i) const { return instants_[i]; }
  /// Whether the sun's elevation is above 0 (below it, every fraction is 0).
  bool sun_up(std::size_t i) const { return sun_up_[i] != 0; }
  const float* fractions(std::size_t i) const { return values_.data() + i * polygons_; }

 private:
  std::filesystem::path times_path_, fractions_path_;
  std::ifstream times_, fractions_;
  std::int64_t steps_ = 0, next_ = 0;  ///< next_: the next block's first step
  std::size_t polygons_ = 0, block_ = 1;
  std::vector<sun::Instant> instants_;
  std::vector<char> sun_up_;
  std::vector<float> values_;
  std::vector<unsigned char> bytes_;
};

}  // namespace shadowkit::sun_study
