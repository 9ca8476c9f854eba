#pragma once
/// \brief Imports kept between runs. assimp parses some formats slowly (its IFC reader takes a
/// quarter of a second on a small house), and users run many commands on one model: the
/// converted polygons are stored once per version of the file and read back in a few
/// milliseconds.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace shadowkit::mesh_io {

class ImportCache {
 public:
  /// The directory $SHADOWKIT_CACHE_DIR, else $XDG_CACHE_HOME/shadowkit, else
  /// $HOME/.cache/shadowkit. SHADOWKIT_CACHE_DIR set but empty turns the cache off.
  static ImportCache from_environment();
  explicit ImportCache(std::filesystem::path dir) : dir_(std::move(dir)) {}

  /// What store() kept for \p file as it is now (same path, size and modification time, same
  /// importer), if anything.
  std::optional<std::string> find(const std::filesystem::path& file) const;
  /// Keeps \p bytes for \p file, dropping the oldest entries past kCapacity. Failing to
  /// write (a read-only home, a full disk) only means the next run imports again.
  void store(const std::filesystem::path& file, const std::string& bytes) const;

  /// Bytes the cache may hold.
  static constexpr std::uintmax_t kCapacity = std::uintmax_t{1} << 30;

 private:
  void trim() const;
  std::optional<std::string> key_of(const std::filesystem::path& file) const;
  std::filesystem::path entry_of(const std::string& key) const;
  std::filesystem::path dir_;  // empty: off
};

}  // namespace shadowkit::mesh_io
