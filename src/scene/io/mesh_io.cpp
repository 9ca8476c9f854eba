#include "shadowkit/scene/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "readers.h"
#include "shadowkit/core/error.h"

namespace shadowkit {

std::string mesh_io::why_not_a_file(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (std::filesystem::is_directory(status)) return "it is a directory";
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    return "it is not a regular file";
  }
  return "";
}

namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File open_file(const std::filesystem::path& path, const std::string& where) {
  if (const std::string why = mesh_io::why_not_a_file(path); !why.empty()) {
    throw InputError(where, "cannot read the file: " + why);
  }
  // stdio rather than iostreams: errno then says why opening failed.
  File file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw InputError(where, std::string("cannot open the file: ") + std::strerror(errno));
  return file;
}

std::string read_whole_file(const std::filesystem::path& path, const std::string& where) {
  const File file = open_file(path, where);
  std::error_code error;
  // One read into a buffer of the file's size; the loop catches a file that grew meanwhile.
  const auto size = std::filesystem::file_size(path, error);
  std::string data(error ? 0 : size, '\0');
  data.resize(std::fread(data.data(), 1, data.size(), file.get()));
  char buffer[1 << 16];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0;) {
    data.append(buffer, n);
  }
  if (std::ferror(file.get())) {
    throw InputError(where, std::string("cannot read the file: ") + std::strerror(errno));
  }
  return data;
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

using Reader = MeshFile (*)(std::string_view, const std::string&, const Context&);

// shadowkit's own readers, for their exact error positions, and tinygltf for glTF 2.0.
struct OwnReader {
  std::string_view extension;
  Reader read;
};
constexpr OwnReader kOwnReaders[] = {
    {".obj", &mesh_io::read_obj}, {".ply", &mesh_io::read_ply},   {".off", &mesh_io::read_off},
    {".stl", &mesh_io::read_stl}, {".gltf", &mesh_io::read_gltf}, {".glb", &mesh_io::read_gltf},
};

Reader own_reader(const std::string& extension) {
  for (const OwnReader& r : kOwnReaders) {
    if (r.extension == extension) return r.read;
  }
  return nullptr;
}

MeshFile read_any(const std::filesystem::path& path, const Context& ctx) {
  const std::string where = path.string();
  const Reader reader = own_reader(lower_extension(path));
  // Any other format, and a file without an extension, is assimp's to recognise.
  if (reader == nullptr) {
    open_file(path, where);  // a missing file is said in shadowkit's words, not assimp's
    return mesh_io::read_with_assimp(where, ctx);
  }
  const std::string data = read_whole_file(path, where);
  if (data.empty()) throw InputError(where, "holds no faces (the file is empty)");
  return reader(data, where, ctx);
}

}  // namespace

MeshFile read_mesh_file(const std::filesystem::path& path, const Context& ctx) {
  MeshFile file = read_any(path, ctx);
  if (file.soup.face_count() == 0) {
    throw InputError(path.string(), file.skipped_primitives > 0
                                        ? "holds no faces, only " +
                                              std::to_string(file.skipped_primitives) +
                                              " points and lines, which cast no shadow"
                                        : std::string("holds no faces"));
  }
  return file;
}

std::vector<std::string> mesh_file_extensions() {
  std::vector<std::string> extensions;
  for (const OwnReader& r : kOwnReaders) extensions.emplace_back(r.extension);
  for (const std::string& e : mesh_io::assimp_extensions()) {
    if (std::find(extensions.begin(), extensions.end(), e) == extensions.end()) {
      extensions.push_back(e);
    }
  }
  return extensions;
}

bool is_mesh_file_name(const std::filesystem::path& path) {
  const std::vector<std::string> known = mesh_file_extensions();
  return std::find(known.begin(), known.end(), lower_extension(path)) != known.end();
}

}  // namespace shadowkit
