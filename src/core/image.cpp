#include "shadowkit/core/image.h"

#include <png.h>

#include <cstdio>
#include <memory>

#include "shadowkit/core/error.h"
#include "shadowkit/core/files.h"

namespace shadowkit {
namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File open_file(const std::filesystem::path& path, const char* mode) {
  if (mode[0] == 'w') create_parent_directories(path);
  File file(std::fopen(path.c_str(), mode), &std::fclose);
  if (!file) throw InputError(path.string(), "cannot open file");
  return file;
}

// libpng reports errors by longjmp; the simplified API avoids that hazard entirely.
void write_png_rows(const std::filesystem::path& path, int width, int height, png_uint_32 format,
                    const void* data) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(width);
  image.height = png_uint_32(height);
  image.format = format;
  File file = open_file(path, "wb");
  if (!png_image_write_to_stdio(&image, file.get(), 0, data, 0, nullptr)) {
    throw InputError(path.string(), std::string("cannot write PNG: ") + image.message);
  }
}

// Reads a PNG converted to \p format, whose pixel is a T.
template <class T>
Image<T> read_png(const std::filesystem::path& path, png_uint_32 format) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    throw InputError(path.string(), std::string("cannot read PNG: ") + png.message);
  }
  png.format = format;
  Image<T> image(int(png.width), int(png.height));
  if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
    throw InputError(path.string(), std::string("cannot read PNG: ") + png.message);
  }
  return image;
}

}  // namespace

void write_png(const std::filesystem::path& path, const Image<std::uint8_t>& image) {
  write_png_rows(path, image.width, image.height, PNG_FORMAT_GRAY, image.pixels.data());
}

void write_png(const std::filesystem::path& path, const Image<Rgb8>& image) {
  write_png_rows(path, image.width, image.height, PNG_FORMAT_RGB, image.pixels.data());
}

Image<std::uint8_t> read_png_gray(const std::filesystem::path& path) {
  return read_png<std::uint8_t>(path, PNG_FORMAT_GRAY);
}

Image<Rgb8> read_png_rgb(const std::filesystem::path& path) {
  return read_png<Rgb8>(path, PNG_FORMAT_RGB);
}

std::string encode_png(const Image<Rgb8>& image, PngSpeed speed) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = PNG_FORMAT_RGB;
  if (speed == PngSpeed::fast) png.flags = PNG_IMAGE_FLAG_FAST;
  // Room for the worst case, so that one pass writes it.
  std::string bytes(PNG_IMAGE_PNG_SIZE_MAX(png), '\0');
  png_alloc_size_t size = bytes.size();
  if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, image.pixels.data(), 0, nullptr)) {
    throw InputError("PNG", std::string("cannot encode: ") + png.message);
  }
  bytes.resize(size);
  return bytes;
}

}  // namespace shadowkit
