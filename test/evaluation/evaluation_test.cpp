#include "view_direction_classification/evaluation/evaluation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/quick_mug_model.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

// Small enough for a unit test: 2 sequences x 2 views, unoccluded and r_vis = 6 cm.
EvaluationSettings smallSettings() {
  EvaluationSettings settings;
  settings.sequences = 2;
  settings.views = 2;
  settings.candidates = 4;
  settings.visibility_radii = {kAllVisible, 0.06};
  settings.seed = 7;
  settings.threads = 2;
  return settings;
}

void expectErrorsInRange(const EvaluationResult& result, const EvaluationSettings& settings) {
  ASSERT_EQ(result.settings.size(), settings.visibility_radii.size());
  for (const auto& setting : result.settings) {
    ASSERT_EQ(setting.errors_deg.rows(), settings.sequences);
    ASSERT_EQ(setting.errors_deg.cols(), settings.views);
    EXPECT_TRUE(setting.errors_deg.allFinite());
    EXPECT_GE(setting.errors_deg.minCoeff(), 0.0);
    EXPECT_LE(setting.errors_deg.maxCoeff(), 180.0);
    const Eigen::VectorXd medians = setting.medianPerView();
    ASSERT_EQ(medians.size(), settings.views);
    EXPECT_TRUE(medians.allFinite());
    // The trust signals after each view: at most one new view each, a cone within [0, 180].
    ASSERT_EQ(setting.views_fused.rows(), settings.sequences);
    ASSERT_EQ(setting.views_fused.cols(), settings.views);
    ASSERT_EQ(setting.cone90_deg.rows(), settings.sequences);
    ASSERT_EQ(setting.cone90_deg.cols(), settings.views);
    for (int v = 0; v < settings.views; ++v) {
      EXPECT_LE(setting.views_fused.col(v).maxCoeff(), v + 1);
    }
    EXPECT_GE(setting.views_fused.col(0).minCoeff(), 0);
    EXPECT_GT(setting.cone90_deg.minCoeff(), 0.0);
    EXPECT_LE(setting.cone90_deg.maxCoeff(), 180.0);
    EXPECT_EQ(setting.insideCone90PerView().size(), settings.views);
    // Positions: NaN only before the first fused view; the object (at the origin) is seen from
    // 0.6 m, so an estimate is centimetres off at worst, never as far as the camera.
    ASSERT_EQ(setting.position_errors_mm.rows(), settings.sequences);
    ASSERT_EQ(setting.position_errors_mm.cols(), settings.views);
    for (Eigen::Index i = 0; i < setting.position_errors_mm.size(); ++i) {
      const double error = setting.position_errors_mm.data()[i];
      if (std::isnan(error)) continue;
      EXPECT_GE(error, 0.0);
      EXPECT_LT(error, 300.0);
    }
    EXPECT_FALSE(std::isnan(setting.medianPositionPerView()(settings.views - 1)));
    // The refined position comes with its covariance: a distance wherever a position does not
    // come from the centroid alone.
    ASSERT_EQ(setting.position_mahalanobis.rows(), settings.sequences);
    ASSERT_EQ(setting.position_mahalanobis.cols(), settings.views);
    EXPECT_FALSE(std::isnan(setting.positionInsideEllipsoid90PerView()(settings.views - 1)));
  }
}

TEST(EvaluationTest, TheCalibrationFigureIsTheFractionOfSequencesWithTheErrorWithinCone90) {
  SettingErrors setting;
  setting.errors_deg.resize(4, 2);
  setting.errors_deg << 10, 1, 20, 2, 30, 3, 40, 50;
  setting.cone90_deg.resize(4, 2);
  setting.cone90_deg << 15, 5, 20, 1, 25, 5, 45, 5;
  // View 1: 10 <= 15, 20 <= 20, 40 <= 45 inside; view 2: 1 <= 5 and 3 <= 5 inside.
  EXPECT_TRUE(setting.insideCone90PerView().isApprox(Eigen::Vector2d(0.75, 0.5)));
  EXPECT_EQ(SettingErrors().insideCone90PerView().size(), 0) << "no trust signals, no figure";
}

TEST(EvaluationTest, ThePositionFigureIsTheFractionWithinTheCovariances90PercentEllipsoid) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  SettingErrors setting;
  setting.position_mahalanobis.resize(4, 2);
  // chi-square(3) at 0.9 is 6.25: a distance of 2.5 (6.25) is just inside, 2.51 outside.
  setting.position_mahalanobis << 1.0, nan, 2.5, nan, 2.51, 0.5, 3.0, nan;
  const Eigen::VectorXd fractions = setting.positionInsideEllipsoid90PerView();
  ASSERT_EQ(fractions.size(), 2);
  EXPECT_DOUBLE_EQ(fractions(0), 0.5);
  EXPECT_DOUBLE_EQ(fractions(1), 1.0) << "only the sequences with a covariance count";
  setting.position_mahalanobis.setConstant(nan);
  EXPECT_TRUE(setting.positionInsideEllipsoid90PerView().array().isNaN().all());
  EXPECT_EQ(SettingErrors().positionInsideEllipsoid90PerView().size(), 0);
}

TEST(EvaluationTest, ConfidentlyWrongIsAnErrorBeyondTwiceCone90AndBeyondTheFloor) {
  SettingErrors setting;
  setting.errors_deg.resize(4, 2);
  setting.errors_deg << 174, 0.3, 100, 2.5, 31, 12, 4, 50;
  setting.cone90_deg.resize(4, 2);
  setting.cone90_deg << 67, 0.05, 60, 1, 15, 5, 1, 30;
  // View 1: 174 > 134 and 31 > 30 count; 100 < 120 does not; 4 > 2 is under the 5-degree floor.
  // View 2: 12 > 10 counts; 0.3 > 0.1 and 2.5 > 2 are under the floor; 50 < 60.
  EXPECT_TRUE(setting.confidentlyWrongPerView().isApprox(Eigen::Vector2d(0.5, 0.25)));
  EXPECT_TRUE(setting.confidentlyWrongPerView(0.0).isApprox(Eigen::Vector2d(0.75, 0.75)))
      << "without the floor the renders' tenths of a degree against hundredths count";
  EXPECT_EQ(SettingErrors().confidentlyWrongPerView().size(), 0) << "no trust signals, no figure";
}

TEST(EvaluationTest, RandomPlannerGivesFiniteErrorsBetweenZeroAnd180PerSettingSequenceAndView) {
  const EvaluationSettings settings = smallSettings();
  const EvaluationResult result = evaluateEstimator(
      test::quickMugModel(), makeMug(), mugHandleAnchors(), EvaluationPlanner::kRandom, settings);
  EXPECT_EQ(result.planner, "random");
  expectErrorsInRange(result, settings);
  EXPECT_EQ(result.settings[0].visible_fraction, 1.0);
  // The paper reports 24.6 % of the mug within 6 cm of its two handle points.
  EXPECT_GT(result.settings[1].visible_fraction, 0.1);
  EXPECT_LT(result.settings[1].visible_fraction, 0.5);
  EXPECT_GT(result.mean_update_ms, 0.0);
  EXPECT_EQ(result.mean_planning_ms, 0.0);
}

TEST(EvaluationTest, SameSeedGivesIdenticalErrorsWhateverTheThreadCount) {
  EvaluationSettings settings = smallSettings();
  settings.threads = 1;
  const EvaluationResult one = evaluateEstimator(
      test::quickMugModel(), makeMug(), mugHandleAnchors(), EvaluationPlanner::kRandom, settings);
  settings.threads = 2;
  const EvaluationResult two = evaluateEstimator(
      test::quickMugModel(), makeMug(), mugHandleAnchors(), EvaluationPlanner::kRandom, settings);
  ASSERT_EQ(one.settings.size(), two.settings.size());
  for (std::size_t k = 0; k < one.settings.size(); ++k) {
    EXPECT_EQ(one.settings[k].errors_deg, two.settings[k].errors_deg) << "setting " << k;
    EXPECT_EQ(one.settings[k].skipped_views, two.settings[k].skipped_views);
  }
}

TEST(EvaluationTest, TheSensorSettingRendersTheViews) {
  EvaluationSettings settings = smallSettings();
  settings.visibility_radii = {kAllVisible};
  const auto errors = [&settings] {
    return evaluateEstimator(test::quickMugModel(), makeMug(), mugHandleAnchors(),
                             EvaluationPlanner::kRandom, settings)
        .settings[0]
        .errors_deg;
  };
  const auto by_default = errors();
  settings.sensor = DepthSensor::kTimeOfFlight;
  EXPECT_NE(errors(), by_default);  // other views, other errors
}

TEST(EvaluationTest, UtilityPlannersRunOnTheSameSequencesWithFiniteErrors) {
  EvaluationSettings settings = smallSettings();
  settings.sequences = 1;
  settings.visibility_radii = {kAllVisible};
  for (const auto planner :
       {EvaluationPlanner::kInformativeness, EvaluationPlanner::kInformationGain}) {
    const EvaluationResult result =
        evaluateEstimator(test::quickMugModel(), makeMug(), mugHandleAnchors(), planner, settings);
    EXPECT_EQ(result.planner, evaluationPlannerName(planner));
    expectErrorsInRange(result, settings);
    EXPECT_GT(result.mean_planning_ms, 0.0);
  }
}

TEST(EvaluationTest, SequencesAreDeterministicPerSeedAndDifferBetweenSequences) {
  const EvaluationSettings settings = smallSettings();
  const EvaluationSequence a = makeEvaluationSequence(settings, 0);
  const EvaluationSequence again = makeEvaluationSequence(settings, 0);
  const EvaluationSequence b = makeEvaluationSequence(settings, 1);
  ASSERT_EQ(a.camera_from_object.size(), static_cast<std::size_t>(settings.candidates));
  EXPECT_EQ(a.world_from_object, again.world_from_object);
  EXPECT_NEAR(a.world_from_object.norm(), 1.0, 1e-12);
  EXPECT_NE(a.world_from_object, b.world_from_object);
  for (std::size_t c = 0; c < a.camera_from_object.size(); ++c) {
    EXPECT_TRUE(a.camera_from_object[c].isApprox(again.camera_from_object[c], 0.0));
    // Every candidate looks at the object origin from the settings' distance.
    EXPECT_NEAR(a.camera_from_object[c].translation().norm(), settings.distance, 1e-9);
    EXPECT_NEAR(a.camera_from_object[c].translation().normalized().z(), 1.0, 1e-9);
  }
}

TEST(EvaluationTest, SingleViewMethodWithoutEstimatesCountsEveryViewAs180DegreesAndSkipped) {
  const EvaluationSettings settings = smallSettings();
  int calls = 0;
  const SingleViewMethod nothing = [&calls](const pcl::PointCloud<pcl::PointXYZ>&) {
    ++calls;
    return std::optional<Eigen::Isometry3d>{};
  };
  const EvaluationResult result = evaluateSingleView(nothing, "none", makeMug(), CameraIntrinsics{},
                                                     mugHandleAnchors(), settings);
  EXPECT_EQ(calls, 2 * 2 * 2);
  for (const auto& setting : result.settings) {
    EXPECT_EQ(setting.skipped_views, 2 * 2);
    EXPECT_EQ(setting.errors_deg, Eigen::MatrixXd::Constant(2, 2, 180.0));
    EXPECT_TRUE(setting.position_errors_mm.array().isNaN().all());
    EXPECT_TRUE(setting.medianPositionPerView().array().isNaN().all());
  }
}

TEST(EvaluationTest, SingleViewMethodReturningTheTrueRotationScoresZero) {
  // A method that reads the object's rotation off the rendered view is not available, but one
  // that returns the pose of the view it is handed (looked up by call order) checks the
  // bookkeeping: every error must be 0.
  EvaluationSettings settings = smallSettings();
  settings.visibility_radii = {kAllVisible};
  std::vector<Eigen::Isometry3d> poses;
  for (int s = 0; s < settings.sequences; ++s) {
    const EvaluationSequence sequence = makeEvaluationSequence(settings, s);
    for (int v = 0; v < settings.views; ++v) poses.push_back(sequence.camera_from_object[v]);
  }
  std::size_t call = 0;
  const SingleViewMethod oracle = [&](const pcl::PointCloud<pcl::PointXYZ>&) {
    return std::optional<Eigen::Isometry3d>(poses[call++]);
  };
  const EvaluationResult result =
      evaluateSingleView(oracle, "oracle", makeMug(), CameraIntrinsics{}, {}, settings);
  ASSERT_EQ(result.settings.size(), 1u);
  EXPECT_LT(result.settings[0].errors_deg.maxCoeff(), 1e-4);
  EXPECT_LT(result.settings[0].position_errors_mm.maxCoeff(), 1e-9);
  EXPECT_EQ(result.settings[0].skipped_views, 0);
}

TEST(EvaluationTest, MedianIgnoringNaNSkipsMissingValues) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double values[] = {nan, 3.0, 1.0, nan};
  EXPECT_EQ(medianIgnoringNaN(values, 4), 2.0);
  EXPECT_EQ(medianIgnoringNaN(values, 3), 2.0);
  EXPECT_EQ(medianIgnoringNaN(values + 1, 1), 3.0);
  EXPECT_TRUE(std::isnan(medianIgnoringNaN(values, 1)));
  EXPECT_TRUE(std::isnan(medianIgnoringNaN(values, 0)));
}

TEST(EvaluationTest, ViewsUntilTheMedianStaysBelowAThresholdIgnoreDipsThatComeBack) {
  Eigen::VectorXd medians(6);
  medians << 90, 4, 12, 6, 4.5, 3;  // the dip at view 2 comes back up
  EXPECT_EQ(viewsUntilMedianStaysBelow(medians, 5.0), std::optional<int>(5));
  EXPECT_EQ(viewsUntilMedianStaysBelow(medians, 100.0), std::optional<int>(1));
  EXPECT_EQ(viewsUntilMedianStaysBelow(medians, 3.0), std::nullopt);  // strictly below
  EXPECT_EQ(viewsUntilMedianStaysBelow(Eigen::VectorXd(), 5.0), std::nullopt);
}

// The errors of a fresh estimator given the true camera pose of each of the random planner's
// views of `sequence`: what the evaluation did before it had camera pose errors.
Eigen::VectorXd errorsOnTheTruePoses(const EvaluationSettings& settings, int sequence) {
  const auto model = test::quickMugModel();
  const DepthRenderer renderer(makeMug(), intrinsicsOf(model->parameters));
  const EvaluationSequence views = makeEvaluationSequence(settings, sequence);
  OrientationEstimator estimator(model, settings.estimator);
  Eigen::VectorXd errors(settings.views);
  for (int v = 0; v < settings.views; ++v) {
    const Eigen::Isometry3d& camera_from_object = views.camera_from_object[v];
    const auto cloud =
        renderEvaluationView(renderer, settings, sequence, v, camera_from_object, {}, kAllVisible);
    estimator.update(cloud, views.worldFromObject() * camera_from_object.inverse());
    errors(v) = rotationErrorDeg(estimator.mapOrientation(), views.world_from_object);
  }
  return errors;
}

TEST(EvaluationTest, WithoutPoseErrorTheEstimatorGetsTheTruePosesExactlyAndWithItNot) {
  EvaluationSettings settings = smallSettings();
  settings.sequences = 1;
  settings.threads = 1;
  settings.visibility_radii = {kAllVisible};
  const Eigen::VectorXd truth = errorsOnTheTruePoses(settings, 0);
  const EvaluationResult exact = evaluateEstimator(
      test::quickMugModel(), makeMug(), mugHandleAnchors(), EvaluationPlanner::kRandom, settings);
  EXPECT_EQ(Eigen::VectorXd(exact.settings[0].errors_deg.row(0).transpose()), truth);
  // A 5-degree hand-eye bias turns every view's evidence: the errors change (measured against
  // the same truth).
  settings.camera_pose_error.bias_deg = 5.0;
  const EvaluationResult biased = evaluateEstimator(
      test::quickMugModel(), makeMug(), mugHandleAnchors(), EvaluationPlanner::kRandom, settings);
  EXPECT_NE(Eigen::VectorXd(biased.settings[0].errors_deg.row(0).transpose()), truth);
}

TEST(EvaluationTest, TheViewsAreRenderedFromThePerturbedMeshWithTheEvaluationSeed) {
  EvaluationSettings settings = smallSettings();
  const TriangleMesh mug = makeMug();
  const TriangleMesh same = renderedObjectMesh(mug, settings);
  ASSERT_EQ(same.vertices.size(), mug.vertices.size());
  for (std::size_t v = 0; v < mug.vertices.size(); ++v)
    EXPECT_EQ(same.vertices[v], mug.vertices[v]);
  settings.mesh_perturbation.scale = Eigen::Vector3d(1.0, 1.0, 1.03);
  EXPECT_NEAR(renderedObjectMesh(mug, settings).bounds().max().z(), 1.03 * mug.bounds().max().z(),
              1e-6);
  settings.mesh_perturbation.scale = Eigen::Vector3d::Ones();
  settings.mesh_perturbation.dents = 3;
  settings.mesh_perturbation.dent_depth = 0.002;
  const TriangleMesh seeded = renderedObjectMesh(mug, settings);
  settings.seed += 1;
  const TriangleMesh reseeded = renderedObjectMesh(mug, settings);
  bool differ = false;
  for (std::size_t v = 0; v < mug.vertices.size(); ++v) {
    differ = differ || seeded.vertices[v] != reseeded.vertices[v];
  }
  EXPECT_TRUE(differ);
}

TEST(EvaluationTest, BadSettingsAndMissingAnchorsAreRefused) {
  EvaluationSettings settings = smallSettings();
  settings.sequences = 0;
  EXPECT_THROW(checkEvaluationSettings(settings), Error);
  settings = smallSettings();
  settings.candidates = settings.views - 1;
  EXPECT_THROW(checkEvaluationSettings(settings), Error);
  settings = smallSettings();
  settings.visibility_radii = {-0.05};
  EXPECT_THROW(checkEvaluationSettings(settings), Error);
  settings = smallSettings();
  settings.distance = 0.0;
  EXPECT_THROW(checkEvaluationSettings(settings), Error);
  settings = smallSettings();
  settings.camera_pose_error.noise_mm = -1.0;
  EXPECT_THROW(checkEvaluationSettings(settings), Error);
  settings = smallSettings();
  settings.mesh_perturbation.scale.y() = 0.0;
  EXPECT_THROW(checkEvaluationSettings(settings), Error);
  // Occlusion settings need anchors; the unoccluded one does not.
  EXPECT_THROW(evaluateEstimator(test::quickMugModel(), makeMug(), {}, EvaluationPlanner::kRandom,
                                 smallSettings()),
               Error);
  EXPECT_THROW(evaluateEstimator(nullptr, makeMug(), mugHandleAnchors(), EvaluationPlanner::kRandom,
                                 smallSettings()),
               Error);
}

}  // namespace
}  // namespace vdc
