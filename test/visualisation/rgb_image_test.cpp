#include "view_direction_classification/visualisation/rgb_image.h"

#include <gtest/gtest.h>
#include <png.h>

#include <fstream>
#include <string>

#include "support/temporary_directory_test.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

TEST(RgbImage, StartsFilledAndRefusesANonPositiveSize) {
  const RgbImage image(3, 2, {10, 20, 30});
  ASSERT_EQ(image.pixels.size(), 3u * 2u * 3u);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 3; ++x) EXPECT_EQ(image.at(x, y), (Rgb{10, 20, 30}));
  }
  EXPECT_THROW(RgbImage(0, 2, {0, 0, 0}), Error);
  EXPECT_THROW(RgbImage(3, -1, {0, 0, 0}), Error);
}

TEST(RgbImage, SetWritesOnlyItsPixelRowMajorFromTheTopLeft) {
  RgbImage image(4, 3, {0, 0, 0});
  image.set(3, 1, {1, 2, 3});
  // Row 1, column 3: bytes (1 * 4 + 3) * 3 onwards.
  EXPECT_EQ(image.pixels[21], 1);
  EXPECT_EQ(image.pixels[22], 2);
  EXPECT_EQ(image.pixels[23], 3);
  EXPECT_EQ(image.at(3, 1), (Rgb{1, 2, 3}));
  int changed = 0;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) changed += image.at(x, y) != Rgb{0, 0, 0} ? 1 : 0;
  }
  EXPECT_EQ(changed, 1);
}

TEST(RgbImage, PixelsOutsideTheImageAreRefusedNotWrapped) {
  RgbImage image(4, 3, {0, 0, 0});
  // (4, 0) would be (0, 1) in the buffer, (0, 3) past its end.
  for (const auto& [x, y] : {std::pair{4, 0}, {0, 3}, {-1, 0}, {0, -1}}) {
    EXPECT_THROW(image.set(x, y, {9, 9, 9}), Error) << x << ", " << y;
    EXPECT_THROW(image.at(x, y), Error) << x << ", " << y;
  }
  EXPECT_EQ(image.at(0, 1), (Rgb{0, 0, 0}));
  try {
    image.at(4, 0);
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()), "pixel (4, 0) is outside the 4 x 3 image");
  }
}

class PngFiles : public test::TemporaryDirectoryTest {};

TEST_F(PngFiles, WriteThenReadGivesTheSameSizeAndPixels) {
  RgbImage image(5, 3, {235, 235, 235});
  image.set(0, 0, {255, 0, 0});
  image.set(4, 0, {0, 255, 0});
  image.set(2, 2, {0, 0, 255});
  image.set(4, 2, {1, 2, 3});
  writePng(image, path("round_trip.png"));
  const RgbImage back = readPng(path("round_trip.png"));
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, image.pixels);
}

TEST_F(PngFiles, ReadDropsTheAlphaOfAnRgbaPng) {
  // Written with libpng's own simplified API, not with writePng (which writes RGB only).
  const unsigned char rgba[] = {10, 20, 30, 0, 40, 50, 60, 255};
  png_image writer{};
  writer.version = PNG_IMAGE_VERSION;
  writer.width = 2;
  writer.height = 1;
  writer.format = PNG_FORMAT_RGBA;
  ASSERT_TRUE(png_image_write_to_file(&writer, path("rgba.png").c_str(), 0, rgba, 0, nullptr));
  const RgbImage image = readPng(path("rgba.png"));
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 1);
  // libpng composes onto the buffer, which readPng fills black: alpha 0 reads black.
  EXPECT_EQ(image.at(0, 0), (Rgb{0, 0, 0}));
  EXPECT_EQ(image.at(1, 0), (Rgb{40, 50, 60}));
}

TEST_F(PngFiles, UnreadableAndUnwritableFilesAreRefusedNamingThePath) {
  std::ofstream(path("not_a.png")) << "plain text";
  for (const std::string& name : {path("missing.png"), path("not_a.png")}) {
    try {
      readPng(name);
      ADD_FAILURE() << "read " << name;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
    }
  }
  const std::string unwritable = path("no_such_directory/out.png");
  try {
    writePng(RgbImage(2, 2, {0, 0, 0}), unwritable);
    ADD_FAILURE() << "wrote " << unwritable;
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(unwritable), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace vdc
