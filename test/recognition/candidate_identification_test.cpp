#include "view_direction_classification/recognition/candidate_identification.h"

#include <gtest/gtest.h>

#include <memory>
#include <numeric>
#include <random>

#include "support/mug_scene.h"
#include "support/quick_mug_model.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/recognition/shape_alternative.h"

namespace vdc {
namespace {

double sum(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0);
}

TEST(IdentityProbabilities, TheBestVerifiedModelWinsAndTheyAddUpToOne) {
  const IdentificationParameters parameters;
  const auto p = identityProbabilities({0.95, 0.85, std::nullopt}, parameters);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_NEAR(sum(p), 1.0, 1e-12);
  EXPECT_GT(p[0], 0.8);
  EXPECT_GT(p[1], p[3]);  // 0.85 beats unknown's 0.8
  EXPECT_EQ(p[2], 0.0);   // no verified pose: not this model
}

TEST(IdentityProbabilities, ScoresBelowUnknownsLeaveTheObjectUnknown) {
  const IdentificationParameters parameters;
  const auto p = identityProbabilities({0.6, 0.7}, parameters);
  EXPECT_GT(p.back(), 0.8);
  const auto none = identityProbabilities({std::nullopt, std::nullopt}, parameters);
  EXPECT_EQ(none.back(), 1.0);
}

TEST(IdentityProbabilities, TwoModelsThatExplainItEquallyShareTheProbability) {
  const auto p = identityProbabilities({0.97, 0.97}, IdentificationParameters{});
  EXPECT_NEAR(p[0], p[1], 1e-12);
  EXPECT_LT(p[0], 0.5);  // neither reaches min_probability: the candidate stays unknown
}

// An identification of model 0 made with both models' scores lowered by a shape penalty.
Identification identifiedWithPenalties(const std::vector<std::optional<double>>& raw_scores,
                                       const std::vector<double>& penalties) {
  Identification identification;
  for (std::size_t m = 0; m < raw_scores.size(); ++m) {
    identification.scores.push_back(raw_scores[m]);
    if (raw_scores[m]) *identification.scores.back() -= penalties[m];
  }
  identification.probabilities =
      identityProbabilities(identification.scores, IdentificationParameters{});
  identification.model = 0;
  identification.probability = identification.probabilities[0];
  return identification;
}

TEST(LowerPenalties, TheScoresRegainWhatThePenaltiesLostAndTheProbabilitiesFollow) {
  // A flange alone that a can's top explains (penalty 0.17): model 0 barely beats unknown.
  Identification identification = identifiedWithPenalties({1.0, std::nullopt}, {0.17, 0.17});
  ASSERT_LT(identification.probability, 0.8);
  // With the core its pose explains, no simple shape does (penalty 0).
  ASSERT_TRUE(lowerPenalties({0.17, 0.17}, {0.0, 0.0}, {}, &identification));
  EXPECT_NEAR(*identification.scores[0], 1.0, 1e-12);
  EXPECT_FALSE(identification.scores[1].has_value());  // still no verified pose
  EXPECT_EQ(identification.probabilities, identityProbabilities({1.0, std::nullopt}, {}));
  EXPECT_GT(identification.probability, 0.95);
}

TEST(LowerPenalties, AHigherPenaltyNeverReplacesTheOneUsed) {
  Identification identification = identifiedWithPenalties({1.0, 0.9}, {0.1, 0.1});
  const Identification before = identifiedWithPenalties({1.0, 0.9}, {0.1, 0.1});
  ASSERT_TRUE(lowerPenalties({0.1, 0.1}, {0.2, 0.2}, {}, &identification));
  EXPECT_EQ(identification.scores, before.scores);
  EXPECT_EQ(identification.probability, before.probability);
}

TEST(LowerPenalties, LeavesTheIdentificationAloneWhenAnotherModelWouldWin) {
  // Model 1 verifies better but carried a penalty that model 0 (a simple shape itself) did not:
  // lowered, model 1 would be the most probable, and the identification holds model 0's
  // estimator.
  Identification identification = identifiedWithPenalties({0.95, 0.99}, {0.0, 0.1});
  ASSERT_EQ(identification.model, 0);
  ASSERT_GT(identification.probabilities[0], identification.probabilities[1]);
  const Identification before = identifiedWithPenalties({0.95, 0.99}, {0.0, 0.1});
  EXPECT_FALSE(lowerPenalties({0.0, 0.1}, {0.0, 0.0}, {}, &identification));
  EXPECT_EQ(identification.scores, before.scores);
  EXPECT_EQ(identification.probabilities, before.probabilities);
  EXPECT_THROW(lowerPenalties({0.0}, {0.0, 0.0}, {}, &identification), Error);
}

TEST(IdentificationParameters, AreCheckedNamingTheBadOne) {
  IdentificationParameters bad;
  bad.temperature = 0.0;
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
  bad = {};
  bad.min_probability = 1.5;
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
  bad = {};
  bad.unknown_score = 2.0;
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
  bad = {};
  bad.threads = 0;
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
}

}  // namespace
}  // namespace vdc

namespace vdc {
namespace {

TEST(IdentityEvidence, AViewThatVerifiesWellSupportsTheModelAndOneThatDoesNotOpposesIt) {
  const IdentificationParameters parameters;
  EXPECT_GT(identityEvidence(0.9, parameters), 0.0);
  EXPECT_LT(identityEvidence(0.7, parameters), 0.0);
  EXPECT_LT(identityEvidence(std::nullopt, parameters), 0.0);  // nothing verified
  // Capped: one view never decides alone.
  EXPECT_EQ(identityEvidence(1.0, parameters), parameters.max_view_evidence);
  EXPECT_EQ(identityEvidence(-1.0, parameters), -parameters.max_view_evidence);
}

// The quick mug's classifier with its surface turned upside down: a model of the mug's size whose
// belief, on a view of the upright mug, is of poses its surface does not fit, so that only a
// search beyond the belief could make it explain the mug.
std::shared_ptr<const ModelBundle> upsideDownMug() {
  ModelBundle copy = *test::quickMugModel();
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (Eigen::Vector3f& p : copy.surface_points) p = turn.cast<float>() * p;
  for (Eigen::Vector3f& n : copy.surface_normals) n = turn.cast<float>() * n;
  Eigen::AlignedBox3d bounds;
  for (const Eigen::Vector3f& p : copy.surface_points) bounds.extend(p.cast<double>());
  copy.bounds = bounds;
  return std::make_shared<const ModelBundle>(std::move(copy));
}

// One object alone, seen from the side and above at 0.7 m (camera frame), with the camera pose.
std::pair<pcl::PointCloud<pcl::PointXYZ>, Eigen::Isometry3d> viewOf(const TriangleMesh& mesh) {
  Scene scene;
  scene.object = {mesh, test::worldFromMug()};
  const Eigen::Isometry3d camera_from_world =
      test::cameraFromWorld(Eigen::Vector3d(1.0, 0.3, 0.8).normalized(), 0.7);
  std::mt19937 rng(3);
  return {DepthRenderer(sceneMesh(scene)).render(camera_from_world, DepthNoiseModel{true}, &rng),
          camera_from_world.inverse()};
}

ModelLibrary mugAndFlipped() {
  return ModelLibrary({{"mug", test::quickMugModel()}, {"flipped", upsideDownMug()}});
}

EstimatorParameters instanceParameters() {
  EstimatorParameters instance;
  instance.segmentation.mode = SegmentationMode::kNone;
  return instance;
}

Identification identifyAlone(const TriangleMesh& mesh, int threads = 2,
                             const std::vector<double>& penalties = {}) {
  const auto [points, world_from_camera] = viewOf(mesh);
  IdentificationParameters parameters;
  parameters.threads = threads;
  return identifyCandidate(mugAndFlipped(), instanceParameters(), points,
                           Eigen::Vector3d(0.11, 0.09, 0.08), {}, world_from_camera, 0.0,
                           parameters, penalties);
}

TEST(IdentifyCandidate, AModelThatExplainsTheCandidateAtOnceSparesTheOthersTheirSearch) {
  const Identification mug = identifyAlone(makeMug());
  ASSERT_EQ(mug.model, 0) << mug.reason;
  ASSERT_EQ(mug.searched.size(), 2u);
  EXPECT_FALSE(mug.searched[0]) << "the mug's own belief explains it";
  EXPECT_FALSE(mug.searched[1]) << "the flipped model searched though the mug explained it";
  EXPECT_FALSE(mug.update.search_pending);
}

TEST(IdentifyCandidate, ACandidateIsDescribedOnceForTheModelsThatShareFeatureSettings) {
  // The mug and the flipped mug share the quick model's feature settings.
  EXPECT_EQ(identifyAlone(makeMug()).feature_passes, 1);
  // A model with a wider FPFH support needs its own pass.
  ModelBundle wider = *test::quickMugModel();
  wider.parameters.fpfh_radius *= 1.5;
  const ModelLibrary library({{"mug", test::quickMugModel()},
                              {"flipped", upsideDownMug()},
                              {"wider", std::make_shared<const ModelBundle>(std::move(wider))}});
  EstimatorParameters instance;
  instance.segmentation.mode = SegmentationMode::kNone;
  const auto [points, world_from_camera] = viewOf(makeMug());
  const Identification mug =
      identifyCandidate(library, instance, points, Eigen::Vector3d(0.11, 0.09, 0.08), {},
                        world_from_camera, 0.0, IdentificationParameters());
  EXPECT_EQ(mug.feature_passes, 2);
  // The wider-support model, the same mug otherwise, explains it too.
  EXPECT_TRUE(mug.scores[0] && mug.scores[2]);
}

TEST(IdentifyCandidate, WhenNoModelExplainsTheCandidateAtOnceEveryModelSearches) {
  // A box of the mug's size: neither model's belief explains it.
  const Identification box = identifyAlone(makeBoxMesh(Eigen::Vector3d(0.09, 0.08, 0.10)));
  EXPECT_EQ(box.model, -1);
  ASSERT_EQ(box.searched.size(), 2u);
  EXPECT_TRUE(box.searched[0]);
  EXPECT_TRUE(box.searched[1]);
}

// The same box with the shape alternative's penalties: a box explains the rendered box at the
// search's threshold (unknown_score + penalty >= search_below_score), so it is a box as surely as
// a model's own pose must explain a candidate to spare the searches, and no model searches. Just
// below the threshold every model does, as without penalties.
TEST(IdentifyCandidate, ACandidateABoxExplainsAtTheSearchsThresholdIsNotSearched) {
  const TriangleMesh box = makeBoxMesh(Eigen::Vector3d(0.09, 0.08, 0.10));
  const auto [points, world_from_camera] = viewOf(box);
  const IdentificationParameters parameters;
  const ShapeAlternative shapes(mugAndFlipped(),
                                instanceParameters().refinement_parameters.verification,
                                parameters.unknown_score);
  const Eigen::Vector3f up =
      (world_from_camera.rotation().transpose() * Eigen::Vector3d::UnitZ()).cast<float>();
  const std::vector<double> penalties = shapes.penalties(points, up);
  ASSERT_EQ(penalties.size(), 2u);
  const double search_below = instanceParameters().belief_check.search_below_score;
  ASSERT_GE(parameters.unknown_score + penalties[0], search_below);
  const Identification explained = identifyAlone(box, 2, penalties);
  EXPECT_EQ(explained.model, -1);
  ASSERT_EQ(explained.searched.size(), 2u);
  EXPECT_FALSE(explained.searched[0]);
  EXPECT_FALSE(explained.searched[1]);
  const double just_below = search_below - parameters.unknown_score - 0.01;
  const Identification unsure = identifyAlone(box, 2, {just_below, just_below});
  EXPECT_TRUE(unsure.searched[0]);
  EXPECT_TRUE(unsure.searched[1]);
}

// The models run side by side, each with its own estimator: the same scores, to the last bit, as
// one after the other, for a candidate one model explains at once and for one every model
// searches.
TEST(IdentifyCandidate, ModelsTriedSideBySideScoreExactlyAsOneAfterTheOther) {
  for (const TriangleMesh& mesh : {makeMug(), makeBoxMesh(Eigen::Vector3d(0.09, 0.08, 0.10))}) {
    const Identification alone = identifyAlone(mesh, 1);
    const Identification side_by_side = identifyAlone(mesh, 2);
    EXPECT_EQ(side_by_side.model, alone.model);
    EXPECT_EQ(side_by_side.scores, alone.scores);
    EXPECT_EQ(side_by_side.probabilities, alone.probabilities);
    EXPECT_EQ(side_by_side.searched, alone.searched);
  }
}

}  // namespace
}  // namespace vdc
