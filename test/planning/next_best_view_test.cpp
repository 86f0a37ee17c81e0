#include "view_direction_classification/planning/next_best_view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

// Six training directions +x, -x, +y, -y, +z, -z (indices 0..5) and four surface points:
// two on the +x face, one on the -x face, one on the +z face. Only +x and -x have valid scores
// for their own points; +z (view 4) observed nothing; view 5 (-z) has no training data.
std::shared_ptr<ModelBundle> makeAxisBundle() {
  auto bundle = std::make_shared<ModelBundle>();
  bundle->view_directions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  bundle->surface_points = {{0.05f, 0.01f, 0}, {0.05f, -0.01f, 0}, {-0.05f, 0, 0}, {0, 0, 0.05f}};
  bundle->surface_normals = {{1, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}};
  bundle->score_matrix = Eigen::MatrixXf::Constant(4, 6, -1.0f);
  bundle->score_matrix(0, 0) = 1.0f;
  bundle->score_matrix(1, 0) = 3.0f;
  bundle->score_matrix(2, 1) = 0.5f;
  bundle->view_informativeness.view_scores = Eigen::VectorXd::Constant(6, 2.0);
  bundle->view_informativeness.view_scores(4) = 1.25;
  bundle->view_informativeness.view_scores(5) = -1.0;
  bundle->view_informativeness.confusion = Eigen::MatrixXd::Identity(6, 6);
  return bundle;
}

// A concentrated Bingham distribution whose mode is q.
BinghamDistribution sharpAround(const Eigen::Vector4d& q) {
  BinghamDistribution::Axes axes;  // rows w, x, y, z: the mode (identity) is the fourth direction
  axes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  return BinghamDistribution(Eigen::Vector3d::Constant(-100), axes).rotated(q);
}

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

TEST(NextBestViewPlanner, RejectsABundleWhoseScoreMatrixDoesNotMatchItsViews) {
  auto bundle = makeAxisBundle();
  bundle->score_matrix = Eigen::MatrixXf::Zero(4, 5);
  EXPECT_THROW(NextBestViewPlanner{bundle}, Error);
  EXPECT_THROW(NextBestViewPlanner{nullptr}, Error);
}

TEST(NextBestViewPlanner, NearestViewPicksTheClosestTrainingDirection) {
  const NextBestViewPlanner planner(makeAxisBundle());
  EXPECT_EQ(planner.nearestView({0.9, 0.1, -0.2}), 0);
  EXPECT_EQ(planner.nearestView({0.1, -3, 0.2}), 3);
  EXPECT_THROW(planner.nearestView({0, 0, 0}), Error);
  EXPECT_THROW(planner.nearestView({std::nan(""), 0, 1}), Error);
}

TEST(Informativeness, IsMinusTheMeanScoreOfTheFacingObservedPoints) {
  const NextBestViewPlanner planner(makeAxisBundle());
  // From +x the two +x points (scores 1 and 3) face the camera.
  EXPECT_NEAR(planner.informativeness({0.6, 0, 0}), -2.0, 1e-9);
  // From -x only the -x point (0.5).
  EXPECT_NEAR(planner.informativeness({-0.6, 0.05, 0}), -0.5, 1e-9);
}

TEST(Informativeness, FallsBackToTheViewScoreWhenNothingVisibleWasObserved) {
  const NextBestViewPlanner planner(makeAxisBundle());
  // +z: the +z point faces the camera but was never observed (K = -1): -v(4).
  EXPECT_NEAR(planner.informativeness({0, 0, 0.6}), -1.25, 1e-12);
  // -z has no training data at all (v = -1): the worst utility.
  EXPECT_EQ(planner.informativeness({0, 0, -0.6}), NextBestViewPlanner::worstUtility());
  EXPECT_LT(NextBestViewPlanner::worstUtility(), -27.0);
}

TEST(Informativeness, IgnoresSurfacePointsHiddenByTheOccluder) {
  const NextBestViewPlanner planner(makeAxisBundle());
  // An occluder point on the line from the second +x point (score 3) to the camera hides it.
  const OccluderCloud occluder({{0.3, -0.005, 0}}, 0.005);
  EXPECT_NEAR(planner.informativeness({0.6, 0, 0}, &occluder), -1.0, 1e-9);
  // Hiding both +x points leaves nothing to see: the worst utility, not the view score.
  const OccluderCloud wall({{0.3, -0.005, 0}, {0.3, 0.005, 0}}, 0.005);
  EXPECT_EQ(planner.informativeness({0.6, 0, 0}, &wall), NextBestViewPlanner::worstUtility());
}

TEST(OccluderCloud, DoesNotHideAPointByOccluderPointsOnItOrBehindIt) {
  const std::vector<Eigen::Vector3d> surface = {{0.05, 0, 0}};
  const Eigen::Vector3d camera(0.6, 0, 0);
  EXPECT_FALSE(OccluderCloud({{0.052, 0, 0}}, 0.005).hidden(camera, surface)[0]);
  EXPECT_FALSE(OccluderCloud({{-0.2, 0, 0}}, 0.005).hidden(camera, surface)[0]);
  EXPECT_FALSE(OccluderCloud({{0.3, 0.006, 0}}, 0.005).hidden(camera, surface)[0]);
  EXPECT_TRUE(OccluderCloud({{0.3, 0.004, 0}}, 0.005).hidden(camera, surface)[0]);
}

TEST(OccluderCloud, AgreesWithTheBruteForceSegmentDistanceTest) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> box(-0.1, 0.1);
  std::vector<Eigen::Vector3d> occluder_points, surface;
  for (int i = 0; i < 120; ++i) occluder_points.emplace_back(box(rng), box(rng), box(rng) + 0.2);
  for (int i = 0; i < 600; ++i) surface.emplace_back(box(rng), box(rng), box(rng));
  const double radius = 0.006;
  const OccluderCloud occluder(occluder_points, radius);
  for (const Eigen::Vector3d& camera :
       {Eigen::Vector3d(0.05, -0.1, 0.6), Eigen::Vector3d(0.3, 0.2, 0.25)}) {
    const std::vector<bool> hidden = occluder.hidden(camera, surface);
    int hidden_count = 0;
    for (std::size_t i = 0; i < surface.size(); ++i) {
      const Eigen::Vector3d to_camera = camera - surface[i];
      const Eigen::Vector3d start = surface[i] + 2.0 * radius * to_camera.normalized();
      const Eigen::Vector3d segment = camera - start;
      bool expected = false;
      for (const auto& o : occluder_points) {
        // Points closer than 2 radii to the camera plane are left out by design.
        const Eigen::Vector3d axis = -camera.normalized();
        if ((o - camera).dot(axis) <= 2.0 * radius) continue;
        const double t = std::clamp((o - start).dot(segment) / segment.squaredNorm(), 0.0, 1.0);
        if ((start + t * segment - o).norm() <= radius) expected = true;
      }
      EXPECT_EQ(hidden[i], expected) << "surface point " << i;
      hidden_count += hidden[i] ? 1 : 0;
    }
    // The scene is built so that the test exercises both outcomes.
    EXPECT_GT(hidden_count, 10);
    EXPECT_LT(hidden_count, static_cast<int>(surface.size()) - 10);
  }
}

TEST(OccluderCloud, RejectsAnEmptyCloudANonFinitePointAndABadRadius) {
  EXPECT_THROW(OccluderCloud({}, 0.005), Error);
  EXPECT_THROW(OccluderCloud({{0, std::nan(""), 0}}, 0.005), Error);
  EXPECT_THROW(OccluderCloud({{0, 0, 0}}, 0.0), Error);
}

TEST(InformationGain, IsTheWeightEntropyWhenHypothesesSeeDistinctViews) {
  const NextBestViewPlanner planner(makeAxisBundle());
  // Identity and a half turn about z: from +x they see +x and -x (distinct confusion rows).
  const std::vector<OrientationHypothesis> hypotheses = {
      {Eigen::Vector4d(1, 0, 0, 0), 0.5},
      {quaternionFromAxisAngle(Eigen::Vector3d::UnitZ(), M_PI), 0.5}};
  const Eigen::Vector3d object(0.1, 0.2, 0.3);
  EXPECT_NEAR(planner.informationGain(object + Eigen::Vector3d(0.6, 0, 0), object, hypotheses),
              std::log(2.0), 1e-12);
  // From +z both see +z: nothing to learn.
  EXPECT_NEAR(planner.informationGain(object + Eigen::Vector3d(0, 0, 0.6), object, hypotheses), 0.0,
              1e-12);
  EXPECT_THROW(planner.informationGain(object, object, hypotheses), Error);
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

TEST(RankCandidates, OrdersByDescendingUtilityAndReportsTheViewSeen) {
  const NextBestViewPlanner planner(makeAxisBundle());
  PlanningScene scene;
  scene.object_position = Eigen::Vector3d(1, 0, 0);
  // The object is turned by a half turn about z: a camera at world -x sees its +x face.
  scene.orientation = quaternionFromAxisAngle(Eigen::Vector3d::UnitZ(), M_PI);
  const std::vector<Eigen::Vector3d> candidates = {
      {1.6, 0, 0}, {0.4, 0, 0}, {1, 0, 0.6}};  // sees -x (0.5), +x (2), +z (1.25)
  const auto ranked = rankCandidates(planner, candidates, ViewUtility::kInformativeness, scene);
  ASSERT_EQ(ranked.size(), 3u);
  EXPECT_EQ(ranked[0].index, 0);
  EXPECT_EQ(ranked[0].view, 1);
  EXPECT_NEAR(ranked[0].utility, -0.5, 1e-9);
  EXPECT_EQ(ranked[1].index, 2);
  EXPECT_EQ(ranked[2].index, 1);
  EXPECT_EQ(ranked[2].view, 0);

  // With two hypotheses (identity, half turn) only the x candidates tell them apart.
  scene.belief = BinghamMixture(
      {0.5, 0.5}, {sharpAround(Eigen::Vector4d(1, 0, 0, 0)), sharpAround(scene.orientation)});
  const auto gains = rankCandidates(planner, candidates, ViewUtility::kInformationGain, scene);
  EXPECT_NEAR(gains[0].utility, std::log(2.0), 1e-9);
  EXPECT_NEAR(gains[1].utility, std::log(2.0), 1e-9);
  EXPECT_EQ(gains[2].index, 2);
  EXPECT_NEAR(gains[2].utility, 0.0, 1e-9);

  EXPECT_THROW(rankCandidates(planner, {}, ViewUtility::kInformativeness, scene), Error);
  EXPECT_THROW(rankCandidates(planner, {{1, 0, 0}}, ViewUtility::kInformativeness, scene), Error);
}

TEST(SampleCandidatePoses, PutsCamerasAtTheDistanceLookingAtTheObject) {
  const Eigen::Vector3d object(0.5, -0.2, 0.8);
  const auto poses = sampleCandidatePoses(42, 0.7, object);
  ASSERT_EQ(poses.size(), 42u);
  for (const auto& pose : poses) {
    EXPECT_NEAR((pose.translation() - object).norm(), 0.7, 1e-9);
    const Eigen::Vector3d optical_axis = pose.linear().col(2);
    EXPECT_NEAR(optical_axis.dot((object - pose.translation()).normalized()), 1.0, 1e-9);
  }
  EXPECT_THROW(sampleCandidatePoses(1, 0.7, object), Error);
  EXPECT_THROW(sampleCandidatePoses(10, 0.0, object), Error);
}

}  // namespace
}  // namespace vdc
