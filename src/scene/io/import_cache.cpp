#include "import_cache.h"

#include <assimp/version.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <vector>

namespace shadowkit::mesh_io {
namespace fs = std::filesystem;

ImportCache ImportCache::from_environment() {
  if (const char* dir = std::getenv("SHADOWKIT_CACHE_DIR")) return ImportCache(dir);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return ImportCache(fs::path(xdg) / "shadowkit");
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return ImportCache(fs::path(home) / ".cache" / "shadowkit");
  }
  return ImportCache(fs::path());
}

// The file's identity: what it is and which version of it, and which importer converted it.
std::optional<std::string> ImportCache::key_of(const fs::path& file) const {
  if (dir_.empty()) return std::nullopt;
  std::error_code error;
  const fs::path path = fs::canonical(file, error);
  const auto size = fs::file_size(path, error);
  const auto time = fs::last_write_time(path, error);
  if (error) return std::nullopt;
  return "shadowkit-import 1, assimp " + std::to_string(aiGetVersionMajor()) + "." +
         std::to_string(aiGetVersionMinor()) + "." + std::to_string(aiGetVersionRevision()) + ", " +
         std::to_string(size) + " bytes, modified " +
         std::to_string(time.time_since_epoch().count()) + ", " + path.string();
}

fs::path ImportCache::entry_of(const std::string& key) const {
  char name[32];
  std::snprintf(name, sizeof name, "%016zx.import", std::hash<std::string>{}(key));
  return dir_ / name;
}

std::optional<std::string> ImportCache::find(const fs::path& file) const {
  const std::optional<std::string> key = key_of(file);
  if (!key) return std::nullopt;
  std::ifstream in(entry_of(*key), std::ios::binary);
  std::string stored_key;
  // The key is kept in the entry: two files whose keys hash alike are told apart.
  if (!in || !std::getline(in, stored_key) || stored_key != *key) return std::nullopt;
  std::string bytes;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    bytes.append(buffer, std::size_t(in.gcount()));
  if (in.bad()) return std::nullopt;
  return bytes;
}

void ImportCache::store(const fs::path& file, const std::string& bytes) const {
  const std::optional<std::string> key = key_of(file);
  if (!key) return;
  std::error_code error;
  fs::create_directories(dir_, error);
  // Written aside and renamed into place: a reader never sees half an entry.
  const fs::path entry = entry_of(*key);
  fs::path partial = entry;
  partial += "." + std::to_string(getpid()) + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    out << *key << '\n';
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      fs::remove(partial, error);
      return;
    }
  }
  fs::rename(partial, entry, error);
  if (error) fs::remove(partial, error);
  trim();
}

// Oldest entries go first once the cache holds more than kCapacity bytes.
void ImportCache::trim() const {
  struct Entry {
    fs::file_time_type time;
    std::uintmax_t size;
    fs::path path;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code error;
  for (const auto& item : fs::directory_iterator(dir_, error)) {
    if (item.path().extension() != ".import") continue;
    entries.push_back({item.last_write_time(error), item.file_size(error), item.path()});
    total += entries.back().size;
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.time < b.time; });
  for (const Entry& e : entries) {
    if (total <= kCapacity) break;
    fs::remove(e.path, error);
    total -= e.size;
  }
}

}  // namespace shadowkit::mesh_io
