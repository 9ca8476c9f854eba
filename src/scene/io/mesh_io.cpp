#include "shadowkit/scene/mesh_io.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "readers.h"
#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

std::string read_whole_file(const std::filesystem::path& path, const std::string& where) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(where, "cannot read the file: it is a directory");
  }
  // stdio rather than iostreams: errno then says why opening failed.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) throw InputError(where, std::string("cannot open the file: ") + std::strerror(errno));
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

}  // namespace

PolygonSoup read_mesh_file(const std::filesystem::path& path) {
  const std::string where = path.string();
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));

  using Reader = PolygonSoup (*)(std::string_view, const std::string&);
  Reader reader = nullptr;
  if (extension == ".obj") reader = &mesh_io::read_obj;
  if (extension == ".ply") reader = &mesh_io::read_ply;
  if (extension == ".off") reader = &mesh_io::read_off;
  if (extension == ".stl") reader = &mesh_io::read_stl;
  if (reader == nullptr) {
    throw InputError(where, (extension.empty() ? std::string("the file name has no extension")
                                               : "unknown mesh format '" + extension + "'") +
                                "; expected .obj, .ply, .off or .stl");
  }

  const std::string data = read_whole_file(path, where);
  if (data.empty()) throw InputError(where, "holds no faces (the file is empty)");
  PolygonSoup soup = reader(data, where);
  if (soup.face_count() == 0) throw InputError(where, "holds no faces");
  return soup;
}

}  // namespace shadowkit
