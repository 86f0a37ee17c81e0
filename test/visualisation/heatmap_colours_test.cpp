#include "view_direction_classification/visualisation/heatmap_colours.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vdc {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

TEST(HeatmapColours, ZeroIsWhiteAndBlackAtIsBlack) {
  EXPECT_EQ(heatmapColour(0.0, 2.0), (Rgb{255, 255, 255}));
  EXPECT_EQ(heatmapColour(2.0, 2.0), (Rgb{0, 0, 0}));
}

TEST(HeatmapColours, IsLinearBetweenAndBlackAbove) {
  EXPECT_EQ(heatmapColour(1.0, 2.0), (Rgb{128, 128, 128}));  // 127.5 rounds up
  EXPECT_EQ(heatmapColour(1.5, 2.0), (Rgb{64, 64, 64}));
  EXPECT_EQ(heatmapColour(7.0, 2.0), (Rgb{0, 0, 0}));
}

TEST(HeatmapColours, UnobservableGetsTheDistinctColour) {
  EXPECT_EQ(heatmapColour(-1.0, 2.0), kUnobservableColour);
  EXPECT_EQ(heatmapColour(std::nan(""), 2.0), kUnobservableColour);
  EXPECT_NE(kUnobservableColour[0], kUnobservableColour[2]);  // not a grey level
}

TEST(HeatmapColours, DegenerateScaleIsAStep) {
  EXPECT_EQ(heatmapColour(0.0, 0.0), (Rgb{255, 255, 255}));
  EXPECT_EQ(heatmapColour(0.1, 0.0), (Rgb{0, 0, 0}));
}

TEST(HeatmapColours, MedianAndMaximumIgnoreInvalidValues) {
  Eigen::VectorXf values(6);
  values << -1, 4, 1, -1, 3, 2;
  EXPECT_DOUBLE_EQ(medianOfValid(values), 2.5);  // of {1, 2, 3, 4}
  EXPECT_DOUBLE_EQ(maximumOfValid(values), 4.0);
  values(1) = -1;
  EXPECT_DOUBLE_EQ(medianOfValid(values), 2.0);  // of {1, 2, 3}
  EXPECT_DOUBLE_EQ(medianOfValid(Eigen::VectorXf::Constant(3, -1.0f)), 0.0);
  EXPECT_DOUBLE_EQ(maximumOfValid(Eigen::VectorXf()), 0.0);
}

}  // namespace
}  // namespace vdc
