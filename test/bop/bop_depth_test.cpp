#include "view_direction_classification/bop/bop_depth.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/error_of.h"
#include "support/temporary_directory_test.h"

namespace vdc {
namespace {

namespace fs = std::filesystem;

using BopDepthTest = test::TemporaryDirectoryTest;

// An 8-bit gray PNG: what a colour or visualisation image saved as depth looks like.
void writeEightBitPng(const std::string& path, int width, int height) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_GRAY;
  std::vector<png_byte> pixels(static_cast<std::size_t>(width) * height, 7);
  ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, pixels.data(), 0, nullptr));
}

std::string errorOf(const std::string& path, int width, int height) {
  return test::errorOf([&] { readBopDepthPng(path, width, height); });
}

TEST_F(BopDepthTest, SixteenBitValuesRoundTrip) {
  const fs::path path = directory() / "000000.png";
  BopDepthImage image{5, 3, {}};
  for (int i = 0; i < 15; ++i) image.values.push_back(static_cast<std::uint16_t>(i * 4369 + 1));
  image.values[4] = 65535;
  image.values[5] = 0;
  writeBopDepthPng(image, path.string());
  const BopDepthImage read = readBopDepthPng(path.string(), 5, 3);
  EXPECT_EQ(read.values, image.values);
}

TEST_F(BopDepthTest, WrongDepthPngsAreRefusedWithTheirName) {
  const std::string eight_bit = (directory() / "000001.png").string();
  writeEightBitPng(eight_bit, 4, 4);
  const std::string message = errorOf(eight_bit, 4, 4);
  EXPECT_NE(message.find("000001.png"), std::string::npos) << message;
  EXPECT_NE(message.find("16-bit single-channel"), std::string::npos) << message;

  const std::string small = (directory() / "000002.png").string();
  writeBopDepthPng({4, 2, std::vector<std::uint16_t>(8, 1)}, small);
  const std::string size_message = errorOf(small, 640, 480);
  EXPECT_NE(size_message.find("000002.png is 4 x 2"), std::string::npos) << size_message;

  const std::string missing = errorOf((directory() / "absent.png").string(), 4, 4);
  EXPECT_NE(missing.find("absent.png"), std::string::npos) << missing;

  const std::string not_png = (directory() / "000003.png").string();
  std::ofstream(not_png) << "depth";
  EXPECT_NE(errorOf(not_png, 4, 4).find("000003.png"), std::string::npos);
}

TEST(BopDepth, QuantisationRoundsToTheScaleAndDropsWhatDoesNotFit) {
  const BopDepthImage image = quantiseDepth({0.0f, 0.50004f, 0.50006f, 7.0f}, 2, 2, 0.1);
  EXPECT_EQ(image.values, (std::vector<std::uint16_t>{0, 5000, 5001, 0}));
}

TEST(BopDepth, CloudCastsEachPixelAlongItsRay) {
  BopCamera camera;
  camera.intrinsics = {3, 2, 100, 200, 1, 0.5};
  camera.depth_scale = 0.5;  // a value of 2000 is 1000 mm
  BopDepthImage image{3, 2, {0, 2000, 2000, 2000, 2000, 4000}};
  const auto cloud = bopDepthCloud(image, camera);
  ASSERT_EQ(cloud.width, 3u);
  ASSERT_EQ(cloud.height, 2u);
  EXPECT_TRUE(std::isnan(cloud.at(0, 0).z));
  EXPECT_FLOAT_EQ(cloud.at(1, 0).z, 1.0f);
  EXPECT_FLOAT_EQ(cloud.at(1, 0).x, 0.0f);
  EXPECT_FLOAT_EQ(cloud.at(1, 0).y, -0.5f / 200.0f);
  EXPECT_FLOAT_EQ(cloud.at(2, 1).z, 2.0f);
  EXPECT_FLOAT_EQ(cloud.at(2, 1).x, 2.0f / 100.0f);
  EXPECT_FLOAT_EQ(cloud.at(2, 1).y, 0.5f * 2.0f / 200.0f);
}

}  // namespace
}  // namespace vdc
