#pragma once
/// \brief Row-major images and PNG output.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowkit {

/// \brief A width x height grid of T, row 0 at the top.
template <class T>
struct Image {
  int width = 0, height = 0;
  std::vector<T> pixels;

  Image() = default;
  Image(int w, int h, T fill = T{}) : width(w), height(h), pixels(std::size_t(w) * h, fill) {}
  T& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  const T& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
  std::size_t size() const { return pixels.size(); }
};

/// \brief An 8-bit RGB pixel.
struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(Rgb8, Rgb8) = default;
};

/// Writes an 8-bit grayscale PNG, creating missing parent directories; throws InputError
/// naming the path if it cannot.
void write_png(const std::filesystem::path& path, const Image<std::uint8_t>& image);
/// Writes an 8-bit RGB PNG; throws InputError naming the path if it cannot.
void write_png(const std::filesystem::path& path, const Image<Rgb8>& image);
/// Reads an 8-bit grayscale PNG (converting colour); throws InputError if it cannot.
Image<std::uint8_t> read_png_gray(const std::filesystem::path& path);
/// Reads an 8-bit RGB PNG (converting grey); throws InputError if it cannot.
Image<Rgb8> read_png_rgb(const std::filesystem::path& path);
/// \brief How hard PNG encoding compresses: `small` files, or `fast` for images sent as
/// they are made (the viewer's frames): on a 1280x720 shaded image about five times faster
/// and a tenth larger (build/bench/frame_bench).
enum class PngSpeed { small, fast };

/// The bytes of an 8-bit RGB PNG of \p image, for a caller that writes them whole (under a
/// temporary name, say, renamed into place when complete) or sends them.
std::string encode_png(const Image<Rgb8>& image, PngSpeed speed = PngSpeed::small);

}  // namespace shadowkit
