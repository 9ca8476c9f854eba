#include "shadowkit/core/image.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

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

TEST(Image, WritingIntoAMissingDirectoryNamesThePath) {
  Image<std::uint8_t> image(2, 2);
  EXPECT_THAT([&] { write_png("/nonexistent-dir/x.png", image); },
              testing::ThrowsMessage<InputError>(testing::HasSubstr("/nonexistent-dir/x.png")));
}

}  // namespace
}  // namespace shadowkit
