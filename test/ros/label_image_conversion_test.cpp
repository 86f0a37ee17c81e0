// sensor_msgs/Image -> LabelImage (toLabelImage): the encodings a detector's instance label image
// comes in, either byte order, and every inconsistency refused with a vdc::Error before a byte is
// read past the buffer.
#include "view_direction_classification/ros/label_image_conversion.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

sensor_msgs::Image image(std::uint32_t width, std::uint32_t height, const std::string& encoding,
                         std::uint32_t bytes_per_pixel) {
  sensor_msgs::Image msg;
  msg.width = width;
  msg.height = height;
  msg.encoding = encoding;
  msg.step = width * bytes_per_pixel;
  msg.data.assign(std::size_t(msg.step) * height, 0);
  return msg;
}

std::string errorOf(const sensor_msgs::Image& msg) {
  try {
    toLabelImage(msg);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(LabelImageConversion, Mono8AndItsAliasAreReadPixelByPixel) {
  for (const std::string encoding : {"mono8", "8UC1"}) {
    sensor_msgs::Image msg = image(3, 2, encoding, 1);
    msg.step = 4;  // a padded row
    msg.data = {0, 1, 2, 99, 3, 4, 255, 99};
    const LabelImage labels = toLabelImage(msg);
    EXPECT_EQ(labels.width, 3);
    EXPECT_EQ(labels.height, 2);
    EXPECT_EQ(labels.labels, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 255})) << encoding;
  }
}

TEST(LabelImageConversion, SixteenBitLabelsAreReadInTheMessagesByteOrder) {
  for (const std::string encoding : {"mono16", "16UC1"}) {
    sensor_msgs::Image msg = image(2, 1, encoding, 2);
    msg.data = {0x91, 0x65, 0x01, 0x00};  // 26 001 (0x6591) and 1, little-endian
    EXPECT_EQ(toLabelImage(msg).labels, (std::vector<std::uint32_t>{26001, 1})) << encoding;
    msg.is_bigendian = 1;
    msg.data = {0x65, 0x91, 0x00, 0x01};
    EXPECT_EQ(toLabelImage(msg).labels, (std::vector<std::uint32_t>{26001, 1})) << encoding;
  }
}

TEST(LabelImageConversion, ThirtyTwoBitSignedLabelsAreReadAndNegativeOnesAreBackground) {
  sensor_msgs::Image msg = image(3, 1, "32SC1", 4);
  msg.data = {0xA0, 0x86, 0x01, 0x00,   // 100 000
              0xFF, 0xFF, 0xFF, 0xFF,   // -1: background
              0x07, 0x00, 0x00, 0x00};  // 7
  EXPECT_EQ(toLabelImage(msg).labels, (std::vector<std::uint32_t>{100000, 0, 7}));
  msg.is_bigendian = 1;
  msg.data = {0x00, 0x01, 0x86, 0xA0, 0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x07};
  EXPECT_EQ(toLabelImage(msg).labels, (std::vector<std::uint32_t>{100000, 0, 7}));
}

TEST(LabelImageConversion, AnotherEncodingIsRefusedNamingIt) {
  for (const std::string encoding : {"rgb8", "bgr8", "32FC1", "16SC1", "mono8 ", ""}) {
    const std::string error = errorOf(image(4, 4, encoding, 1));
    EXPECT_NE(error.find("'" + encoding + "'"), std::string::npos) << encoding << ": " << error;
  }
}

TEST(LabelImageConversion, AStepShorterThanARowOrTooLittleDataIsRefused) {
  sensor_msgs::Image short_step = image(4, 4, "mono16", 2);
  short_step.step = 7;  // 4 pixels of 2 bytes need 8
  EXPECT_NE(errorOf(short_step).find("inconsistent"), std::string::npos);
  sensor_msgs::Image truncated = image(4, 4, "mono16", 2);
  truncated.data.pop_back();
  EXPECT_NE(errorOf(truncated).find("inconsistent"), std::string::npos);
  // Sizes whose products wrap around 32 bits must not pass as small ones.
  sensor_msgs::Image huge = image(1, 1, "32SC1", 4);
  huge.width = 0x40000001u;
  huge.step = 4;  // 0x40000001 x 4 wraps to 4 in 32 bits
  EXPECT_NE(errorOf(huge).find("inconsistent"), std::string::npos);
  sensor_msgs::Image tall = image(1, 1, "mono8", 1);
  tall.height = 0xFFFFFFFFu;
  EXPECT_NE(errorOf(tall).find("inconsistent"), std::string::npos);
}

TEST(LabelImageConversion, AnEmptyImageIsEmpty) {
  const LabelImage labels = toLabelImage(image(0, 0, "mono8", 1));
  EXPECT_EQ(labels.width, 0);
  EXPECT_TRUE(labels.labels.empty());
}

}  // namespace
}  // namespace vdc
