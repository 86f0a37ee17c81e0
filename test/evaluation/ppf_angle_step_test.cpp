#include "view_direction_classification/evaluation/ppf_angle_step.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

constexpr double kDegrees = M_PI / 180.0;

// PCL's accumulator size and the bin its largest angle votes into, as ppf_registration.hpp
// computes them, written out here so the test does not share the code it checks.
double pclBins(float step) { return std::floor(2 * M_PI / step); }
double pclLargestVote(float step) { return std::floor((kLargestPpfAngle + M_PI) / step); }

TEST(PpfAngleStepTest, LargestAngleIsTheLargestFloatNotAbovePi) {
  // The float nearest pi lies above it, so PCL's wrap (alpha > pi: subtract 2 pi) sends it to
  // -pi; the float below it is the largest alpha that votes.
  EXPECT_GT(static_cast<double>(static_cast<float>(M_PI)), M_PI);
  EXPECT_EQ(kLargestPpfAngle, static_cast<double>(std::nextafter(static_cast<float>(M_PI), 0.0f)));
  EXPECT_LE(kLargestPpfAngle, M_PI);
}

TEST(PpfAngleStepTest, TwelveDegreesAsAFloatOverflowsPclsAccumulator) {
  // 12 degrees as a float is a little above 2 pi / 30: 29 bins, and the largest angle votes into
  // bin 29, one past the end (the ASan report in doc/hardening.md).
  const float raw = static_cast<float>(12.0 * kDegrees);
  EXPECT_EQ(pclBins(raw), 29.0);
  EXPECT_EQ(pclLargestVote(raw), 29.0);
  EXPECT_FALSE(isSafePpfAngleStep(raw));
}

TEST(PpfAngleStepTest, TheSafeStepNearTwelveDegreesKeepsEveryVoteInside) {
  const float step = safePpfAngleStep(12.0 * kDegrees);
  EXPECT_NEAR(step / kDegrees, 12.4138, 1e-3);  // 2 pi / 29: 30 bins has no safe float
  EXPECT_LT(pclLargestVote(step), pclBins(step));
  EXPECT_TRUE(isSafePpfAngleStep(step));
  // The smallest angle, -kLargestPpfAngle, votes into bin 0, not below it.
  EXPECT_GE(std::floor((-kLargestPpfAngle + M_PI) / step), 0.0);
}

TEST(PpfAngleStepTest, ChosenStepsAreSafeAndNearTheRequest) {
  for (const double degrees : {1.0, 3.0, 5.0, 8.0, 10.0, 20.0}) {
    const float step = safePpfAngleStep(degrees * kDegrees);
    EXPECT_LT(pclLargestVote(step), pclBins(step)) << degrees;
    // Within a few bin counts: a step of 2 pi / N for N within 7 % of the request's.
    EXPECT_NEAR(step / kDegrees, degrees, 0.07 * degrees) << degrees;
  }
  EXPECT_FLOAT_EQ(safePpfAngleStep(8.0 * kDegrees), 0.13962633907794952f);  // 2 pi / 45: exact
}

TEST(PpfAngleStepTest, BadRequestsAreRefused) {
  EXPECT_THROW(safePpfAngleStep(0.0), Error);
  EXPECT_THROW(safePpfAngleStep(-0.1), Error);
  EXPECT_THROW(safePpfAngleStep(std::numeric_limits<double>::quiet_NaN()), Error);
  EXPECT_THROW(safePpfAngleStep(M_PI), Error);
  EXPECT_FALSE(isSafePpfAngleStep(0.0f));
  EXPECT_FALSE(isSafePpfAngleStep(std::numeric_limits<float>::infinity()));
}

}  // namespace
}  // namespace vdc
