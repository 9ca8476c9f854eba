// Every format assimp imports (COLLADA, FBX, 3DS, IFC, X3D, Blender, ...), polygons whole:
// no post-processing step runs, so no triangulation. Node transforms place the meshes.
//
// assimp parses in a child process: its importers can crash, loop or exhaust memory on a
// damaged file, and a crash of the child is reported as bad input instead of ending
// shadowkit. The child sends the placed polygons back through a pipe.
#include <assimp/scene.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "import_cache.h"
#include "readers.h"
#include "shadowkit/scene/limits.h"
#include "skipped_items.h"
#include "text_cursor.h"

namespace shadowkit::mesh_io {
namespace {

// AddressSanitizer reserves terabytes of address space, so a cap on it only holds without.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

/// \brief An affine map in double, from assimp's row-major aiMatrix4x4.
struct Placement {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  static Placement of(const aiMatrix4x4& a) {
    Placement p;
    const ai_real* rows[3] = {&a.a1, &a.b1, &a.c1};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) p.m[r][c] = rows[r][c];
    }
    return p;
  }
  Placement operator*(const Placement& b) const {
    Placement c;
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 4; ++k) {
        c.m[r][k] = m[r][0] * b.m[0][k] + m[r][1] * b.m[1][k] + m[r][2] * b.m[2][k] +
                    (k == 3 ? m[r][3] : 0.0);
      }
    }
    return c;
  }
  Vec3 apply(const aiVector3D& v) const {
    Vec3 out;
    for (int r = 0; r < 3; ++r) out[r] = m[r][0] * v.x + m[r][1] * v.y + m[r][2] * v.z + m[r][3];
    return out;
  }
};

/// \brief What the child sends: the file's polygons or the reason it could not read them.
struct ImportResult {
  MeshFile file;
  std::vector<std::string> warnings;
  std::string error;  ///< empty on success
};

// Appends mesh \p mesh placed by \p placement.
void place_mesh(const aiMesh& mesh, const Placement& placement, ImportResult& result) {
  PolygonSoup& soup = result.file.soup;
  const auto base = static_cast<std::uint32_t>(soup.positions.size());
  std::vector<std::uint32_t> face;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& in = mesh.mFaces[f];
    if (in.mNumIndices < 3) continue;  // a point or a segment
    face.clear();
    for (unsigned k = 0; k < in.mNumIndices; ++k) {
      if (in.mIndices[k] >= mesh.mNumVertices) {
        throw std::runtime_error("mesh '" + std::string(mesh.mName.C_Str()) + "' face " +
                                 std::to_string(f) + " has vertex index " +
                                 std::to_string(in.mIndices[k]) + " out of range (" +
                                 std::to_string(mesh.mNumVertices) + " vertices)");
      }
      face.push_back(base + in.mIndices[k]);
    }
    soup.add_face(face);
  }
  if (soup.face_count() > limits::kPolygons) {
    throw std::runtime_error("the file places more than " + std::to_string(limits::kPolygons) +
                             " polygons, the most a scene may hold");
  }
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const Vec3 p = placement.apply(mesh.mVertices[v]);
    if (!is_finite(p)) {
      throw std::runtime_error("mesh '" + std::string(mesh.mName.C_Str()) + "' vertex " +
                               std::to_string(v) + " is not finite once placed");
    }
    soup.positions.push_back(p);
  }
}

// Counts every mesh's faces once, placed or not, as assimp's own tools count them.
void count_stored(const aiScene& scene, MeshFile& file) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    if (scene.mMeshes[m] == nullptr) continue;
    for (unsigned f = 0; f < scene.mMeshes[m]->mNumFaces; ++f) {
      ++(scene.mMeshes[m]->mFaces[f].mNumIndices < 3 ? file.skipped_primitives
                                                     : file.stored_polygons);
    }
  }
}

// Walks the node tree with an explicit stack (depth is the file's to choose) and places
// every node's meshes.
ImportResult collect(const aiScene& scene) {
  ImportResult result;
  std::vector<char> placed(scene.mNumMeshes, 0);
  struct Visit {
    const aiNode* node;
    Placement parent;
  };
  std::vector<Visit> stack;
  if (scene.mRootNode != nullptr) stack.push_back({scene.mRootNode, {}});
  std::size_t visits = 0;
  while (!stack.empty()) {
    const Visit visit = stack.back();
    stack.pop_back();
    if (++visits > limits::kPolygons) throw std::runtime_error("the node tree is too large");
    const Placement world = visit.parent * Placement::of(visit.node->mTransformation);
    for (unsigned k = 0; k < visit.node->mNumMeshes; ++k) {
      const unsigned m = visit.node->mMeshes[k];
      if (m >= scene.mNumMeshes || scene.mMeshes[m] == nullptr) {
        throw std::runtime_error("node '" + std::string(visit.node->mName.C_Str()) +
                                 "' names mesh " + std::to_string(m) + ", which does not exist");
      }
      place_mesh(*scene.mMeshes[m], world, result);
      placed[m] = 1;
    }
    for (unsigned c = visit.node->mNumChildren; c-- > 0;) {
      if (visit.node->mChildren[c] != nullptr) stack.push_back({visit.node->mChildren[c], world});
    }
  }
  count_stored(scene, result.file);
  const auto unplaced = static_cast<std::size_t>(std::count(placed.begin(), placed.end(), 0));
  if (unplaced > 0) {
    result.warnings.push_back("skipped " + std::to_string(unplaced) +
                              " mesh(es) that no node places");
  }
  if (result.file.skipped_primitives > 0) {
    result.warnings.push_back("skipped " + std::to_string(result.file.skipped_primitives) +
                              " point and line primitive(s) (they bound no surface)");
  }
  return result;
}

/// \brief What one import may take: limits.h's base, and more for a larger file.
struct ImportBudget {
  double seconds;
  std::size_t bytes;

  static ImportBudget for_file(const std::string& path) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    const std::uintmax_t file_bytes = error ? 0 : size;
    return {
        limits::kImportSeconds + limits::kImportSecondsPerMiB * double(file_bytes >> 20),
        limits::kImportBytes + limits::kImportBytesPerFileByte *
                                   std::min<std::uintmax_t>(file_bytes, std::uintmax_t{1} << 32)};
  }
  std::string memory_text() const {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(std::size_t{1} << 30));
    return text;
  }
};

ImportResult import(const std::string& path, const ImportBudget& budget) {
  ImportResult result;
  try {
    Assimp::Importer importer;
    // No post-processing: polygons stay whole, as the file has them.
    const aiScene* scene = importer.ReadFile(path, 0);
    if (scene == nullptr) {
      result.error = importer.GetErrorString();
      if (result.error.empty()) result.error = "assimp could not read it";
      return result;
    }
    result = collect(*scene);
  } catch (const std::bad_alloc&) {
    result.error = "reading it needs more than " + budget.memory_text() +
                   " of memory (1 GiB and 64 bytes per byte of the file)";
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  return result;
}

// ---- The pipe between child and parent: plain native-endian values, the same program on
// both ends. ----

class Writer {
 public:
  template <typename T>
  void put(const T& value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  template <typename T>
  void put_vector(const std::vector<T>& values) {
    put<std::uint64_t>(values.size());
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    bytes_.append(s);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    T value{};
    take(&value, sizeof value);
    return value;
  }
  template <typename T>
  std::vector<T> get_vector() {
    const auto n = get<std::uint64_t>();
    if (n > bytes_.size() / sizeof(T)) throw std::length_error("truncated");
    std::vector<T> values(n);
    take(values.data(), n * sizeof(T));
    return values;
  }
  std::string get_string() {
    const std::vector<char> chars = get_vector<char>();
    return {chars.begin(), chars.end()};
  }

 private:
  void take(void* out, std::size_t n) {
    if (n > bytes_.size()) throw std::length_error("truncated");
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy must not get
    std::memcpy(out, bytes_.data(), n);
    bytes_.remove_prefix(n);
  }
  std::string_view bytes_;
};

std::string encode(const ImportResult& result) {
  Writer w;
  w.put_string(result.error);
  w.put_vector(result.file.soup.positions);
  w.put_vector(result.file.soup.face_start);
  w.put_vector(result.file.soup.indices);
  w.put<std::uint64_t>(result.file.stored_polygons);
  w.put<std::uint64_t>(result.file.skipped_primitives);
  w.put<std::uint64_t>(result.warnings.size());
  for (const std::string& warning : result.warnings) w.put_string(warning);
  return w.bytes();
}

ImportResult decode(std::string_view bytes) {
  Reader r(bytes);
  ImportResult result;
  result.error = r.get_string();
  result.file.soup.positions = r.get_vector<Vec3>();
  result.file.soup.face_start = r.get_vector<std::uint32_t>();
  result.file.soup.indices = r.get_vector<std::uint32_t>();
  result.file.stored_polygons = r.get<std::uint64_t>();
  result.file.skipped_primitives = r.get<std::uint64_t>();
  const auto warnings = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; k < warnings && k < 64; ++k) result.warnings.push_back(r.get_string());
  return result;
}

// ---- The child process ----

[[noreturn]] void run_child(const std::string& path, const ImportBudget& budget, int out) {
  // A crash is the parent's to report, not the handlers the child inherited (a fuzzer's).
  for (int signal_number : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP}) {
    signal(signal_number, SIG_DFL);
  }
  if (!kAddressSanitizer) {
    const rlimit memory{budget.bytes, budget.bytes};
    setrlimit(RLIMIT_AS, &memory);
  }
  // Some importers print; shadowkit's output (info --json) and messages must stay its own.
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0) {
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
  }
  const std::string message = encode(import(path, budget));
  for (std::size_t done = 0; done < message.size();) {
    const ssize_t n = write(out, message.data() + done, message.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(3);
    done += static_cast<std::size_t>(n);
  }
  _exit(0);
}

// Reads the child's whole message; false when the deadline passes first.
bool read_until(int in, std::chrono::steady_clock::time_point deadline, std::string& message) {
  char buffer[1 << 16];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd fd{in, POLLIN, 0};
    const int ready = poll(&fd, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) return ready == 0 ? false : true;
    const ssize_t n = read(in, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    message.append(buffer, static_cast<std::size_t>(n));
  }
}

// The child's message about \p path: its polygons or the reason it could not read them.
std::string import_in_child(const std::string& path) {
  const ImportBudget budget = ImportBudget::for_file(path);
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) {
    throw InputError(path, std::string("cannot start the importer: ") + std::strerror(errno));
  }
  const pid_t child = fork();
  if (child < 0) {
    close(pipe_ends[0]);
    close(pipe_ends[1]);
    throw InputError(path, std::string("cannot start the importer: ") + std::strerror(errno));
  }
  if (child == 0) {
    close(pipe_ends[0]);
    run_child(path, budget, pipe_ends[1]);
  }
  close(pipe_ends[1]);
  std::string message;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::milliseconds(std::int64_t(budget.seconds * 1000));
  const bool finished = read_until(pipe_ends[0], deadline, message);
  close(pipe_ends[0]);
  if (!finished) kill(child, SIGKILL);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!finished) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.0f", budget.seconds);
    throw InputError(path, std::string("assimp did not finish reading it within ") + seconds +
                               " s (" + std::to_string(int(limits::kImportSeconds)) +
                               " s and 1 s per MiB of the file)");
  }
  if (WIFSIGNALED(status)) {
    throw InputError(
        path, "assimp crashed reading it (" + std::string(strsignal(WTERMSIG(status))) + ")");
  }
  return message;
}

std::optional<ImportResult> decoded(const std::string& message) {
  try {
    return decode(message);
  } catch (const std::exception&) {
    return std::nullopt;  // the child stopped midway, or a cache entry is damaged
  }
}

// The cache's copy of the import if it holds a sound one, else a fresh import, then cached.
ImportResult cached_import(const std::string& path) {
  const ImportCache cache = ImportCache::from_environment();
  if (const std::optional<std::string> kept = cache.find(path)) {
    if (std::optional<ImportResult> result = decoded(*kept)) return std::move(*result);
  }
  const std::string message = import_in_child(path);
  std::optional<ImportResult> result = decoded(message);
  if (!result) throw InputError(path, "assimp stopped before it finished reading it");
  if (result->error.empty()) cache.store(path, message);
  return std::move(*result);
}

}  // namespace

std::vector<std::string> assimp_extensions() {
  std::string list;  // "*.3d;*.3ds;..."
  Assimp::Importer().GetExtensionList(list);
  std::vector<std::string> extensions;
  for (std::size_t start = 0; start < list.size();) {
    std::size_t end = list.find(';', start);
    if (end == std::string::npos) end = list.size();
    std::string pattern = list.substr(start, end - start);
    if (pattern.starts_with("*")) pattern.erase(0, 1);
    // Two-part extensions (".mesh.xml") never match a path's last extension.
    if (pattern.starts_with(".") && pattern.find('.', 1) == std::string::npos) {
      extensions.push_back(pattern);
    }
    start = end + 1;
  }
  return extensions;
}

MeshFile read_with_assimp(const std::string& path, const Context& ctx) {
  ImportResult result = cached_import(path);
  if (!result.error.empty()) {
    throw InputError(path, "assimp cannot read it: " + first_line(result.error));
  }
  for (const std::string& warning : result.warnings) ctx.warning(path + ": " + warning);
  return std::move(result.file);
}

}  // namespace shadowkit::mesh_io
