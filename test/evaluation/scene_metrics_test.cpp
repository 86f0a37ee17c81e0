#include "view_direction_classification/evaluation/scene_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/primitive_meshes.h"

namespace vdc {
namespace {

constexpr double kDegree = M_PI / 180.0;

Eigen::Isometry3d at(const Eigen::Vector3d& position, double yaw = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = position;
  return pose;
}

// A mug, a block and a can, all well visible, and a box distractor.
ViewTruth threeObjects() {
  ViewTruth truth;
  truth.known = {{"mug", at(Eigen::Vector3d(0.0, 0.0, 0.0475), 0.3), 0.8},
                 {"block", at(Eigen::Vector3d(0.2, 0.0, 0.0), 1.0), 0.9},
                 {"can", at(Eigen::Vector3d(-0.2, 0.1, 0.0), -0.5), 0.6}};
  truth.distractors = {{at(Eigen::Vector3d(0.0, 0.3, 0.0)),
                        makeBoxMesh(Eigen::Vector3d(0.2, 0.1, 0.1)).bounds().cast<double>()}};
  return truth;
}

std::vector<InstanceEstimate> perfectEstimates(const ViewTruth& truth) {
  std::vector<InstanceEstimate> estimates;
  for (const KnownObjectTruth& object : truth.known) {
    estimates.push_back({object.model, object.world_from_object, 10.0, 0.9});
  }
  return estimates;
}

TEST(SceneMetrics, PerfectEstimatesIdentifyEveryVisibleObjectWithoutError) {
  const ViewTruth truth = threeObjects();
  const SceneViewMetrics metrics = sceneViewMetrics(truth, perfectEstimates(truth));
  EXPECT_EQ(metrics.visible_known, 3);
  ASSERT_EQ(metrics.identified.size(), 3u);
  EXPECT_TRUE(metrics.false_identifications.empty());
  for (const IdentifiedInstance& instance : metrics.identified) {
    EXPECT_EQ(instance.truth, instance.estimate);
    EXPECT_NEAR(instance.rotation_error_deg, 0.0, 1e-3);
    EXPECT_NEAR(instance.position_error, 0.0, 1e-12);
    EXPECT_TRUE(instance.inside_cone90);
  }
}

TEST(SceneMetrics, AnEstimateOfTheWrongModelIsAFalseIdentification) {
  const ViewTruth truth = threeObjects();
  std::vector<InstanceEstimate> estimates = perfectEstimates(truth);
  estimates[1].model = "mug";  // on the block
  const SceneViewMetrics metrics = sceneViewMetrics(truth, estimates);
  EXPECT_EQ(metrics.identified.size(), 2u);
  ASSERT_EQ(metrics.false_identifications.size(), 1u);
  EXPECT_EQ(metrics.false_identifications[0].estimate, 1);
  EXPECT_FALSE(metrics.false_identifications[0].on_distractor);
}

TEST(SceneMetrics, AnEstimateThreeCentimetresOffIsAFalseIdentification) {
  const ViewTruth truth = threeObjects();
  std::vector<InstanceEstimate> estimates = perfectEstimates(truth);
  estimates[2].world_from_object.translation() += Eigen::Vector3d(0.0, 0.03, 0.0);
  const SceneViewMetrics metrics = sceneViewMetrics(truth, estimates);
  EXPECT_EQ(metrics.identified.size(), 2u);
  ASSERT_EQ(metrics.false_identifications.size(), 1u);
  EXPECT_EQ(metrics.false_identifications[0].estimate, 2);
}

TEST(SceneMetrics, ADuplicateEstimateIsOneIdentificationAndOneFalse) {
  const ViewTruth truth = threeObjects();
  std::vector<InstanceEstimate> estimates = perfectEstimates(truth);
  InstanceEstimate near_duplicate = estimates[0];
  near_duplicate.world_from_object.translation() += Eigen::Vector3d(0.005, 0.0, 0.0);
  estimates.insert(estimates.begin(), near_duplicate);  // listed first, but farther
  const SceneViewMetrics metrics = sceneViewMetrics(truth, estimates);
  ASSERT_EQ(metrics.identified.size(), 3u);
  ASSERT_EQ(metrics.false_identifications.size(), 1u);
  EXPECT_EQ(metrics.false_identifications[0].estimate, 0);  // the nearer one is matched
}

TEST(SceneMetrics, AnObjectBelowTheVisibleFractionIsNotCountedAsVisible) {
  ViewTruth truth = threeObjects();
  truth.known[0].visible_fraction = 0.1;
  const SceneViewMetrics metrics = sceneViewMetrics(truth, perfectEstimates(truth));
  EXPECT_EQ(metrics.visible_known, 2);
  EXPECT_EQ(metrics.identified.size(), 2u);
  for (const IdentifiedInstance& instance : metrics.identified) EXPECT_NE(instance.truth, 0);
  // Its right estimate is neither an identification nor a false one.
  EXPECT_EQ(metrics.matched_hidden, 1);
  EXPECT_TRUE(metrics.false_identifications.empty());
}

TEST(SceneMetrics, AFalseIdentificationOnADistractorIsMarked) {
  const ViewTruth truth = threeObjects();
  std::vector<InstanceEstimate> estimates = perfectEstimates(truth);
  estimates.push_back({"can", at(Eigen::Vector3d(0.08, 0.3, 0.05)), 10.0, 0.5});
  const SceneViewMetrics metrics = sceneViewMetrics(truth, estimates);
  ASSERT_EQ(metrics.false_identifications.size(), 1u);
  EXPECT_TRUE(metrics.false_identifications[0].on_distractor);
}

TEST(SceneMetrics, RotationAndPositionErrorsAndTheConeComeFromTheMatchedEstimate) {
  const ViewTruth truth = threeObjects();
  std::vector<InstanceEstimate> estimates = perfectEstimates(truth);
  estimates[0].world_from_object =
      truth.known[0].world_from_object * at(Eigen::Vector3d(0.01, 0.0, 0.0), 20.0 * kDegree);
  estimates[0].cone90_deg = 15.0;
  estimates[1].world_from_object =
      truth.known[1].world_from_object * at(Eigen::Vector3d::Zero(), 20.0 * kDegree);
  estimates[1].cone90_deg = 30.0;
  const SceneViewMetrics metrics = sceneViewMetrics(truth, estimates);
  ASSERT_EQ(metrics.identified.size(), 3u);
  for (const IdentifiedInstance& instance : metrics.identified) {
    if (instance.truth == 0) {
      EXPECT_NEAR(instance.rotation_error_deg, 20.0, 1e-6);
      EXPECT_NEAR(instance.position_error, 0.01, 1e-9);
      EXPECT_FALSE(instance.inside_cone90);
    } else if (instance.truth == 1) {
      EXPECT_NEAR(instance.rotation_error_deg, 20.0, 1e-6);
      EXPECT_TRUE(instance.inside_cone90);
    }
  }
}

TEST(SceneMetrics, RejectsANegativeMatchDistance) {
  SceneMetricSettings settings;
  settings.match_distance = -0.01;
  EXPECT_THROW(sceneViewMetrics(threeObjects(), {}, settings), Error);
}

TEST(SceneMetrics, PerfectEstimatesOfAGeneratedSceneIdentifyExactlyItsVisibleObjects) {
  const std::vector<KnownModel> models = {{"mug", makeMug()},
                                          {"can", makeCylinderMesh(0.033, 0.12)}};
  const std::vector<TriangleMesh> distractors = {makeBoxMesh(Eigen::Vector3d(0.1, 0.08, 0.16))};
  const TableScene scene = generateTableScene(models, distractors, {}, 11);
  const SceneView view =
      TableSceneRenderer(scene).render(scene.world_from_camera[0], DepthNoiseModel{false});
  const ViewTruth truth = viewTruth(scene, view);
  const SceneViewMetrics metrics = sceneViewMetrics(truth, perfectEstimates(truth));
  EXPECT_EQ(static_cast<int>(metrics.identified.size()), metrics.visible_known);
  EXPECT_EQ(metrics.visible_known + metrics.matched_hidden, static_cast<int>(scene.known.size()));
  EXPECT_TRUE(metrics.false_identifications.empty());
}

}  // namespace
}  // namespace vdc
