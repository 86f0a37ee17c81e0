#include "view_direction_classification/planning/view_utility_scorer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "support/axis_model_bundle.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

using test::makeAxisBundle;
using test::sharpAround;

double entropyOf(const std::vector<double>& weights) {
  double h = 0.0;
  for (double w : weights) h -= w * std::log(w);
  return h;
}

TEST(MutualInformation, IsZeroWhenAllHypothesesPredictTheSameMeasurement) {
  Eigen::MatrixXd confusion(3, 3);
  confusion << 0.5, 0.3, 0.2, 0.5, 0.3, 0.2, 0.1, 0.1, 0.8;
  EXPECT_NEAR(mutualInformation(confusion, {0, 1}, {0.3, 0.7}), 0.0, 1e-12);
  EXPECT_NEAR(mutualInformation(confusion, {2, 2, 2}, {0.2, 0.3, 0.5}), 0.0, 1e-12);
}

TEST(MutualInformation, EqualsTheWeightEntropyWhenPredictionsAreDisjoint) {
  const Eigen::MatrixXd confusion = Eigen::MatrixXd::Identity(4, 4);
  const std::vector<double> weights = {0.1, 0.2, 0.3, 0.4};
  EXPECT_NEAR(mutualInformation(confusion, {0, 1, 2, 3}, weights), entropyOf(weights), 1e-12);
  // Unnormalised weights are normalised.
  EXPECT_NEAR(mutualInformation(confusion, {3, 1}, {2.0, 2.0}), std::log(2.0), 1e-12);
}

TEST(MutualInformation, MatchesAHandComputedPartialOverlap) {
  // Two equally likely hypotheses with rows (1, 0) and (0.5, 0.5): p(m) = (0.75, 0.25),
  // I = 0.5 ln(1 / 0.75) + 0.5 (0.5 ln(0.5 / 0.75) + 0.5 ln(0.5 / 0.25)).
  Eigen::MatrixXd confusion(2, 2);
  confusion << 1.0, 0.0, 0.5, 0.5;
  const double expected =
      0.5 * std::log(1.0 / 0.75) + 0.25 * std::log(0.5 / 0.75) + 0.25 * std::log(2.0);
  EXPECT_NEAR(mutualInformation(confusion, {0, 1}, {1.0, 1.0}), expected, 1e-12);
}

TEST(MutualInformation, RejectsInvalidInput) {
  const Eigen::MatrixXd confusion = Eigen::MatrixXd::Identity(3, 3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(mutualInformation(confusion, {}, {}), Error);
  EXPECT_THROW(mutualInformation(confusion, {0, 1}, {1.0}), Error);
  EXPECT_THROW(mutualInformation(confusion, {0, 3}, {1.0, 1.0}), Error);
  EXPECT_THROW(mutualInformation(confusion, {0, 1}, {nan, 1.0}), Error);
  EXPECT_THROW(mutualInformation(confusion, {0, 1}, {-1.0, 1.0}), Error);
  EXPECT_THROW(mutualInformation(confusion, {0, 1}, {0.0, 0.0}), Error);
  Eigen::MatrixXd zero_row = confusion;
  zero_row.row(1).setZero();
  EXPECT_THROW(mutualInformation(zero_row, {0, 1}, {1.0, 1.0}), Error);
}

TEST(ViewUtilityName, ParsesBothUtilitiesAndRejectsOthers) {
  EXPECT_EQ(parseViewUtility("informativeness"), ViewUtility::kInformativeness);
  EXPECT_EQ(parseViewUtility("information_gain"), ViewUtility::kInformationGain);
  EXPECT_EQ(viewUtilityName(ViewUtility::kInformationGain), "information_gain");
  EXPECT_THROW(parseViewUtility("random"), Error);
}

TEST(ViewUtilityScorer, RejectsABundleWhoseScoreMatrixDoesNotMatchItsViews) {
  auto bundle = makeAxisBundle();
  bundle->score_matrix = Eigen::MatrixXf::Zero(4, 5);
  EXPECT_THROW(ViewUtilityScorer{bundle}, Error);
  EXPECT_THROW(ViewUtilityScorer{nullptr}, Error);
}

TEST(ViewUtilityScorer, NearestViewPicksTheClosestTrainingDirection) {
  const ViewUtilityScorer scorer(makeAxisBundle());
  EXPECT_EQ(scorer.nearestView({0.9, 0.1, -0.2}), 0);
  EXPECT_EQ(scorer.nearestView({0.1, -3, 0.2}), 3);
  EXPECT_THROW(scorer.nearestView({0, 0, 0}), Error);
  EXPECT_THROW(scorer.nearestView({std::nan(""), 0, 1}), Error);
}

TEST(Informativeness, IsMinusTheMeanScoreOfTheFacingObservedPoints) {
  const ViewUtilityScorer scorer(makeAxisBundle());
  // From +x the two +x points (scores 1 and 3) face the camera.
  EXPECT_NEAR(scorer.informativeness({0.6, 0, 0}), -2.0, 1e-9);
  // From -x only the -x point (0.5).
  EXPECT_NEAR(scorer.informativeness({-0.6, 0.05, 0}), -0.5, 1e-9);
}

TEST(Informativeness, FallsBackToTheViewScoreWhenNothingVisibleWasObserved) {
  const ViewUtilityScorer scorer(makeAxisBundle());
  // +z: the +z point faces the camera but was never observed (K = -1): -v(4).
  EXPECT_NEAR(scorer.informativeness({0, 0, 0.6}), -1.25, 1e-12);
  // -z has no training data at all (v = -1): the worst utility.
  EXPECT_EQ(scorer.informativeness({0, 0, -0.6}), ViewUtilityScorer::worstUtility());
  EXPECT_LT(ViewUtilityScorer::worstUtility(), -27.0);
}

TEST(Informativeness, IgnoresSurfacePointsHiddenByTheOccluder) {
  const ViewUtilityScorer scorer(makeAxisBundle());
  // An occluder point on the line from the second +x point (score 3) to the camera hides it.
  const OccluderCloud occluder({{0.3, -0.005, 0}}, 0.005);
  EXPECT_NEAR(scorer.informativeness({0.6, 0, 0}, &occluder), -1.0, 1e-9);
  // Hiding both +x points leaves nothing to see: the worst utility, not the view score.
  const OccluderCloud wall({{0.3, -0.005, 0}, {0.3, 0.005, 0}}, 0.005);
  EXPECT_EQ(scorer.informativeness({0.6, 0, 0}, &wall), ViewUtilityScorer::worstUtility());
}

TEST(InformationGain, IsTheWeightEntropyWhenHypothesesSeeDistinctViews) {
  const ViewUtilityScorer scorer(makeAxisBundle());
  // Identity and a half turn about z: from +x they see +x and -x (distinct confusion rows).
  const std::vector<OrientationHypothesis> hypotheses = {
      {Eigen::Vector4d(1, 0, 0, 0), 0.5},
      {quaternionFromAxisAngle(Eigen::Vector3d::UnitZ(), M_PI), 0.5}};
  const Eigen::Vector3d object(0.1, 0.2, 0.3);
  EXPECT_NEAR(scorer.informationGain(object + Eigen::Vector3d(0.6, 0, 0), object, hypotheses),
              std::log(2.0), 1e-12);
  // From +z both see +z: nothing to learn.
  EXPECT_NEAR(scorer.informationGain(object + Eigen::Vector3d(0, 0, 0.6), object, hypotheses), 0.0,
              1e-12);
  EXPECT_THROW(scorer.informationGain(object, object, hypotheses), Error);
}

TEST(BeliefHypotheses, UsesEveryComponentModeAndSplitsItsWeightOverSamples) {
  const BinghamDistribution first;
  const BinghamDistribution second = first.rotated(quaternionFromAxisAngle({0, 0, 1}, 1.0));
  const BinghamMixture belief({0.25, 0.75}, {first, second});
  const auto modes = beliefHypotheses(belief);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_NEAR(modes[1].weight, 0.75, 1e-12);
  EXPECT_TRUE(modes[1].orientation.isApprox(second.mode()));
  const auto sampled = beliefHypotheses(belief, 3, 5);
  ASSERT_EQ(sampled.size(), 8u);
  double total = 0.0;
  for (const auto& h : sampled) {
    total += h.weight;
    EXPECT_NEAR(h.orientation.norm(), 1.0, 1e-9);
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_NEAR(sampled[0].weight, 0.0625, 1e-12);
  EXPECT_THROW(beliefHypotheses(belief, -1), Error);
}

}  // namespace
}  // namespace vdc
