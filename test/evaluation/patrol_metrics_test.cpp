#include "view_direction_classification/evaluation/patrol_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

constexpr double kDegree = M_PI / 180.0;

Eigen::Isometry3d at(double x, double y, double yaw = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x, y, 0.05);
  return pose;
}

InstanceEstimate estimateAt(const std::string& model, const Eigen::Isometry3d& pose) {
  InstanceEstimate estimate;
  estimate.model = model;
  estimate.world_from_object = pose;
  return estimate;
}

// A mug (id 0) and a block (id 1) on the table; a second mug (id 2) was taken away from (0.3, 0).
PatrolTruth mugAndBlockAfterARemoval() {
  PatrolTruth truth;
  truth.present = {{"mug", at(0.0, 0.0, 0.5), 0.9}, {"block", at(-0.2, 0.1, 1.0), 0.8}};
  truth.ids = {0, 1};
  truth.vacated = {{2, "mug", at(0.3, 0.0), 0.7}};
  return truth;
}

std::vector<InstanceEstimate> rightEstimates(const PatrolTruth& truth) {
  std::vector<InstanceEstimate> estimates;
  for (const KnownObjectTruth& object : truth.present) {
    estimates.push_back(estimateAt(object.model, object.world_from_object));
  }
  return estimates;
}

ChangeNotice removalOf(int object) {
  ChangeNotice notice;
  notice.kind = PatrolChangeKind::kRemoved;
  notice.object = object;
  notice.model = "mug";
  return notice;
}

TEST(PatrolMetrics, ARightMemoryHasEveryObjectRightAndNothingStale) {
  const PatrolTruth truth = mugAndBlockAfterARemoval();
  const PatrolMemoryMetrics metrics = patrolMemoryMetrics(truth, rightEstimates(truth));
  EXPECT_EQ(metrics.present, 2);
  EXPECT_EQ(metrics.confirmed, 2);
  EXPECT_EQ(metrics.right, 2);
  EXPECT_EQ(metrics.duplicates, 0);
  EXPECT_EQ(metrics.stale, 0);
  EXPECT_TRUE(changeReflected(removalOf(2), truth, metrics));
}

TEST(PatrolMetrics, AnInstanceLeftAtARemovedObjectsPlaceIsStale) {
  const PatrolTruth truth = mugAndBlockAfterARemoval();
  std::vector<InstanceEstimate> estimates = rightEstimates(truth);
  estimates.push_back(estimateAt("mug", at(0.31, 0.01)));
  const PatrolMemoryMetrics metrics = patrolMemoryMetrics(truth, estimates);
  EXPECT_EQ(metrics.stale, 1);
  EXPECT_EQ(metrics.right, 2);
  ASSERT_EQ(metrics.place_stale.size(), 1u);
  EXPECT_TRUE(metrics.place_stale[0]);
  EXPECT_FALSE(changeReflected(removalOf(2), truth, metrics));
  // An instance of another model there is not the removed mug's: a false one, not stale.
  estimates.back().model = "block";
  EXPECT_EQ(patrolMemoryMetrics(truth, estimates).stale, 0);
}

TEST(PatrolMetrics, TwoInstancesOnOneObjectAreADuplicate) {
  const PatrolTruth truth = mugAndBlockAfterARemoval();
  std::vector<InstanceEstimate> estimates = rightEstimates(truth);
  estimates.push_back(estimateAt("mug", at(0.03, 0.0, 0.5)));  // 3 cm off the mug
  const PatrolMemoryMetrics metrics = patrolMemoryMetrics(truth, estimates);
  EXPECT_EQ(metrics.duplicates, 1);
  EXPECT_EQ(metrics.right, 2);
  EXPECT_EQ(metrics.stale, 0);  // on a present object of its model
}

TEST(PatrolMetrics, RightNeedsTheModelTwoCentimetresAndFiveDegrees) {
  const PatrolTruth truth = mugAndBlockAfterARemoval();
  std::vector<InstanceEstimate> estimates = rightEstimates(truth);
  estimates[0].world_from_object = at(0.0, 0.0, 0.5 + 6.0 * kDegree);
  estimates[1].world_from_object = at(-0.2, 0.125, 1.0);
  PatrolMemoryMetrics metrics = patrolMemoryMetrics(truth, estimates);
  EXPECT_EQ(metrics.right, 0);
  EXPECT_EQ(metrics.object_right, (std::vector<bool>{false, false}));
  estimates[0].world_from_object = at(0.015, 0.0, 0.5 + 4.0 * kDegree);
  estimates[1] = estimateAt("mug", truth.present[1].world_from_object);
  metrics = patrolMemoryMetrics(truth, estimates);
  EXPECT_EQ(metrics.object_right, (std::vector<bool>{true, false}));
}

TEST(PatrolMetrics, ARemovalIsNoticedOnTheFirstViewWithoutTheStaleInstance) {
  const PatrolTruth truth = mugAndBlockAfterARemoval();
  std::vector<InstanceEstimate> stale_memory = rightEstimates(truth);
  stale_memory.push_back(estimateAt("mug", at(0.3, 0.0)));
  const PatrolMemoryMetrics before = patrolMemoryMetrics(truth, stale_memory);
  const PatrolMemoryMetrics after = patrolMemoryMetrics(truth, rightEstimates(truth));
  ChangeNotice notice = removalOf(2);
  PatrolTruth hidden = truth;
  hidden.vacated[0].visible_fraction = 0.1;
  // Its place hidden on the first view, seen free on the next two; noticed on the third.
  const std::vector<std::pair<const PatrolTruth*, const PatrolMemoryMetrics*>> views = {
      {&hidden, &before}, {&truth, &before}, {&truth, &after}, {&truth, &before}};
  for (const auto& [view_truth, metrics] : views) {
    advanceNotice(changeReflected(notice, *view_truth, *metrics),
                  changePlaceSeen(notice, *view_truth, PatrolMetricSettings{}), &notice);
  }
  EXPECT_TRUE(notice.noticed);
  EXPECT_EQ(notice.views, 3);  // the view after its notice does not count
  EXPECT_EQ(notice.place_views, 2);
}

TEST(PatrolMetrics, AMoveIsReflectedWhenTheObjectIsRightAtItsNewPlaceAndTheOldIsFree) {
  PatrolTruth truth = mugAndBlockAfterARemoval();
  truth.vacated.push_back({0, "mug", at(-0.1, -0.15), 0.9});  // the mug moved from there
  ChangeNotice move;
  move.kind = PatrolChangeKind::kMoved;
  move.object = 0;
  move.model = "mug";
  std::vector<InstanceEstimate> estimates = rightEstimates(truth);
  EXPECT_TRUE(changeReflected(move, truth, patrolMemoryMetrics(truth, estimates)));
  estimates.push_back(estimateAt("mug", at(-0.1, -0.15)));  // still at the old place too
  EXPECT_FALSE(changeReflected(move, truth, patrolMemoryMetrics(truth, estimates)));
  estimates.pop_back();
  estimates[0].world_from_object = at(-0.1, -0.15);  // only at the old place
  EXPECT_FALSE(changeReflected(move, truth, patrolMemoryMetrics(truth, estimates)));
  EXPECT_TRUE(changePlaceSeen(move, truth, PatrolMetricSettings{}));
}

TEST(PatrolMetrics, BadSettingsOrTruthAreRefused) {
  PatrolTruth truth = mugAndBlockAfterARemoval();
  PatrolMetricSettings settings;
  settings.near = -0.01;
  EXPECT_THROW(patrolMemoryMetrics(truth, {}, settings), Error);
  truth.ids.pop_back();
  EXPECT_THROW(patrolMemoryMetrics(truth, {}), Error);
}

}  // namespace
}  // namespace vdc
