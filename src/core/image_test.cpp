#include "shadowkit/core/image.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

TEST(Image, GrayPngRoundTripKeepsEveryValue) {
  Image<std::uint8_t> image(7, 3);
  for (std::size_t i = 0; i < image.size(); ++i) image.pixels[i] = std::uint8_t(i * 37);
  const auto path = std::filesystem::temp_directory_path() / "shadowkit_image_test.png";
  write_png(path, image);
  const Image<std::uint8_t> back = read_png_gray(path);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, image.pixels);
  std::filesystem::remove(path);
}

TEST(Image, EncodedRgbPngReadsBackEveryPixel) {
  Image<Rgb8> image(5, 4);
  for (std::size_t i = 0; i < image.size(); ++i) {
    image.pixels[i] = {std::uint8_t(i * 11), std::uint8_t(255 - i), std::uint8_t(i * i)};
  }
  const auto path = std::filesystem::temp_directory_path() / "shadowkit_image_test_rgb.png";
  std::ofstream(path, std::ios::binary) << encode_png(image);
  const Image<Rgb8> back = read_png_rgb(path);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 4);
  EXPECT_EQ(back.pixels, image.pixels);
  std::filesystem::remove(path);
}

TEST(Image, MissingParentDirectoriesAreCreated) {
  const auto dir = std::filesystem::temp_directory_path() / "shadowkit_image_test_dir";
  std::filesystem::remove_all(dir);
  write_png(dir / "a" / "b.png", Image<std::uint8_t>(2, 2));
  EXPECT_TRUE(std::filesystem::exists(dir / "a" / "b.png"));
  std::filesystem::remove_all(dir);
}

TEST(Image, AnUnwritablePathIsNamedInTheError) {
  Image<std::uint8_t> image(2, 2);
  EXPECT_THAT([&] { write_png("/proc/shadowkit/x.png", image); },
              testing::ThrowsMessage<InputError>(testing::HasSubstr("/proc/shadowkit/x.png")));
}

}  // namespace
}  // namespace shadowkit
