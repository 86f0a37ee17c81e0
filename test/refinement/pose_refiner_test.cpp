#include "view_direction_classification/refinement/pose_refiner.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/estimation/view_measurement.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/geometry/scene.h"
#include "view_direction_classification/geometry/surface_sampling.h"

namespace vdc {
namespace {

constexpr double kDistance = 0.6;

BinghamDistribution concentratedAt(const Eigen::Vector4d& q, double concentration = 200.0) {
  return BinghamDistribution::fromExponentMatrix(concentration * q * q.transpose());
}

Eigen::Vector4d orientationOf(const Eigen::Isometry3d& pose) {
  return quaternionFromRotationMatrix(pose.linear());
}

// Every hypothesis' start and end: printed when an expectation fails.
std::string describe(const RefinementResult& result, const Eigen::Vector4d& truth) {
  std::ostringstream out;
  for (const RefinedPose& pose : result.tried) {
    out << "start " << rotationErrorDeg(pose.start_orientation, truth) << " deg (score "
        << pose.start_score.score() << "), refined " << rotationErrorDeg(pose.orientation, truth)
        << " deg (inliers " << pose.score.inlier_fraction << ", violations "
        << pose.score.violation_fraction << "): " << (pose.accepted ? "accepted" : pose.rejection)
        << "\n";
  }
  return out.str();
}

// The hypotheses that came from the belief (not restarts turned from a converged pose).
std::vector<RefinedPose> beliefStarts(const RefinementResult& result) {
  std::vector<RefinedPose> starts;
  for (const RefinedPose& pose : result.tried) {
    if (pose.restarted_from < 0) starts.push_back(pose);
  }
  return starts;
}

// The built-in mug standing somewhere in the fixed frame, seen by a camera from a given
// object-frame direction and roll; its rendered, noisy view.
class PoseRefinerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mesh_ = new TriangleMesh(makeMug());
    const SurfaceSamples samples = sampleSurface(*mesh_, 0.002, 1);
    const Eigen::AlignedBox3f box = mesh_->bounds();
    surface_ = new std::shared_ptr<const ModelSurface>(std::make_shared<const ModelSurface>(
        samples.points, samples.normals,
        Eigen::AlignedBox3d(box.min().cast<double>(), box.max().cast<double>()), 0.002, 0.004));
  }
  static void TearDownTestSuite() {
    delete surface_;
    delete mesh_;
  }

  // Sets the truth and renders the view: the object at world_from_object_, the camera where it
  // sees it from `direction` (object frame) with `roll`.
  RefinementView view(const Eigen::Vector3d& direction, double roll, std::uint32_t seed = 3) {
    world_from_object_ = Eigen::Isometry3d::Identity();
    world_from_object_.linear() =
        quaternionToRotationMatrix(quaternionFromAxisAngle(Eigen::Vector3d(0.2, -0.4, 1.0), 0.9));
    world_from_object_.translation() = Eigen::Vector3d(0.5, -0.2, 0.75);
    const Eigen::Isometry3d camera_from_object =
        cameraFromObject(direction.normalized(), kDistance, roll);
    RefinementView result;
    result.world_from_camera = world_from_object_ * camera_from_object.inverse();
    std::mt19937 rng(seed);
    result.points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(
        DepthRenderer(*mesh_).render(camera_from_object, DepthNoiseModel{true}, &rng));
    return result;
  }
  // A broad belief (the truth stays in its support) centred on the mug turned 120 degrees about
  // its own axis; call after view(), which places the mug.
  BinghamMixture wrongTurnBelief() const {
    const Eigen::Vector3d axis = world_from_object_.linear().col(2);
    const Eigen::Vector4d wrong =
        quaternionMultiply(quaternionFromAxisAngle(axis, 2.0 * M_PI / 3.0), truth());
    return BinghamMixture({1.0}, {concentratedAt(wrong, 5.0)});
  }

  // The mug side-on, refined from one start turned 0.3 rad about the line of sight (several ICP
  // steps from the truth), without restarts: the screenings' subject.
  RefinementResult refineFromATurnedStart(RefinementParameters parameters);

  // The view from `direction` with a 3 cm bar standing 18 cm in front of the mug across its
  // middle, upright in the image: `scene` is every point the camera saw, `points` the mug's own
  // (the pixels where the scene's depth is the mug's).
  RefinementView behindABar(const Eigen::Vector3d& direction, double roll) {
    RefinementView v = view(direction, roll);
    const Eigen::Vector3d centre = world_from_object_ * mesh_->bounds().center().cast<double>();
    const Eigen::Vector3d camera = v.world_from_camera.translation();
    const Eigen::Matrix3d camera_axes = v.world_from_camera.linear();
    // The bar's length (its z) along the image's y axis, its foot 20 cm below the centre.
    ScenePart bar{distractorMesh("box 0.03 0.03 0.4"), Eigen::Isometry3d::Identity()};
    bar.world_from_part.linear() << camera_axes.col(2), camera_axes.col(0), camera_axes.col(1);
    bar.world_from_part.translation() =
        centre + 0.18 * (camera - centre).normalized() - 0.2 * camera_axes.col(1);
    Scene scene;
    scene.object = {*mesh_, world_from_object_};
    scene.distractors.push_back(bar);
    const Eigen::Isometry3d camera_from_world = v.world_from_camera.inverse();
    std::mt19937 rng(5);
    auto seen = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(
        DepthRenderer(sceneMesh(scene)).render(camera_from_world, DepthNoiseModel{true}, &rng));
    const std::vector<float> mug_depth =
        DepthRenderer(*mesh_).renderDepth(camera_from_world * world_from_object_);
    auto object = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    for (std::size_t i = 0; i < seen->size(); ++i) {
      const float z = (*seen)[i].z;
      if (mug_depth[i] > 0.0f && std::abs(z - mug_depth[i]) < 0.01f) object->push_back((*seen)[i]);
    }
    v.points = object;
    v.scene.occluders = seen;
    return v;
  }
  // The view `mug` with `mesh` rendered instead of the mug, at mug_from_mesh in the mug's frame.
  RefinementView inPlaceOfTheMug(const RefinementView& mug, const TriangleMesh& mesh,
                                 const Eigen::Isometry3d& mug_from_mesh) const {
    const Eigen::Isometry3d camera_from_mesh =
        mug.world_from_camera.inverse() * world_from_object_ * mug_from_mesh;
    RefinementView result = mug;
    std::mt19937 rng(5);
    result.points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(
        DepthRenderer(mesh).render(camera_from_mesh, DepthNoiseModel{true}, &rng));
    return result;
  }
  // The view's points within 5 cm of the handle's tip, as if the rest of the mug were hidden or
  // cut off.
  pcl::PointCloud<pcl::PointXYZ>::Ptr aroundTheHandle(const RefinementView& v) const {
    Eigen::Vector3f tip(-1e9f, 0.0f, 0.0f);
    for (const Eigen::Vector3f& vertex : mesh_->vertices) {
      if (vertex.x() > tip.x()) tip = vertex;
    }
    const Eigen::Isometry3f object_from_camera =
        (world_from_object_.inverse() * v.world_from_camera).cast<float>();
    auto patch = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    for (const auto& p : v.points->points) {
      if ((object_from_camera * p.getVector3fMap() - tip).norm() < 0.05f) patch->push_back(p);
    }
    return patch;
  }
  Eigen::Vector4d truth() const { return orientationOf(world_from_object_); }

  Eigen::Vector3d position() const { return world_from_object_.translation(); }
  // The view's girdle (roll free) in the fixed frame.
  BinghamMixture girdleBelief(const Eigen::Vector3d& direction, const RefinementView& v) const {
    const BinghamMixture camera_frame({1.0}, {viewGirdle(direction.normalized(), 18.0)});
    return cameraToFixedFrame(camera_frame, orientationOf(v.world_from_camera));
  }
  // The truth turned by `angle` about the camera's line of sight through the object.
  Eigen::Vector4d turnedAboutSight(const RefinementView& v, double angle) const {
    const Eigen::Vector3d sight = (position() - v.world_from_camera.translation()).normalized();
    return quaternionMultiply(quaternionFromAxisAngle(sight, angle), truth());
  }

  static TriangleMesh* mesh_;
  static std::shared_ptr<const ModelSurface>* surface_;
  Eigen::Isometry3d world_from_object_ = Eigen::Isometry3d::Identity();
};
TriangleMesh* PoseRefinerTest::mesh_ = nullptr;
std::shared_ptr<const ModelSurface>* PoseRefinerTest::surface_ = nullptr;

// Handle seen from the side and above: roll is plain geometry.
const Eigen::Vector3d kHandleSideOn(0.3, 1.0, 0.4);

// The turned start was abandoned at a screening after `iterations`, naming its threshold.
void expectAbandoned(const RefinementResult& result, int iterations, const std::string& threshold) {
  ASSERT_EQ(beliefStarts(result).size(), 1u);
  EXPECT_FALSE(result.tried[0].accepted);
  EXPECT_EQ(result.tried[0].icp_iterations, iterations);
  EXPECT_EQ(
      result.tried[0].rejection.rfind(
          "abandoned: after " + std::to_string(iterations) + " ICP iterations it verifies", 0),
      0u)
      << result.tried[0].rejection;
  EXPECT_NE(result.tried[0].rejection.find("below " + threshold + " "), std::string::npos)
      << result.tried[0].rejection;
  EXPECT_TRUE(result.kept.empty());
}

RefinementResult PoseRefinerTest::refineFromATurnedStart(RefinementParameters parameters) {
  const RefinementView v = view(kHandleSideOn, 1.0);
  const BinghamMixture belief({1.0}, {concentratedAt(turnedAboutSight(v, 0.3), 20.0)});
  parameters.restart_seeds = 0;
  return PoseRefiner(*surface_, parameters).refine(belief, position(), {v});
}

TEST_F(PoseRefinerTest, RecoversTheRollAlongAGirdle) {
  // The belief knows the viewing direction and nothing about the roll (a view's girdle); the
  // cloud fixes it.
  const RefinementView v = view(kHandleSideOn, 2.1);
  const PoseRefiner refiner(*surface_);
  const RefinementResult result = refiner.refine(girdleBelief(kHandleSideOn, v), position(), {v});
  ASSERT_FALSE(result.skipped()) << result.skip_reason;
  EXPECT_EQ(beliefStarts(result).size(), 24u);
  // Only the best-screened starts were aligned; the rest say why not.
  int aligned = 0;
  for (const RefinedPose& pose : beliefStarts(result)) {
    aligned += pose.screened_in ? 1 : 0;
    if (!pose.screened_in) {
      EXPECT_NE(pose.rejection.find("screened out"), std::string::npos);
    }
  }
  EXPECT_EQ(aligned, RefinementParameters{}.max_refined);
  ASSERT_FALSE(result.kept.empty()) << describe(result, truth());
  const RefinedPose& best = result.kept.front();
  EXPECT_LT(rotationErrorDeg(best.orientation, truth()), 2.0) << describe(result, truth());
  EXPECT_LT((best.world_from_object.translation() - position()).norm(), 0.002);
  EXPECT_GT(best.score.score(), 0.8);
  // Nothing else explains the view as well: one pose kept.
  EXPECT_EQ(result.kept.size(), 1u) << describe(result, truth());
}

TEST_F(PoseRefinerTest, ScreeningRanksTheStartNearestTheTrueRollFirst) {
  // 36 starts 10 degrees apart along the girdle; only the best-screened one is aligned, and it
  // must be the one next to the truth for the roll to come out right.
  const RefinementView v = view(kHandleSideOn, 2.1);
  RefinementParameters parameters;
  parameters.hypotheses.girdle_step_deg = 10.0;
  parameters.max_refined = 1;
  const RefinementResult result =
      PoseRefiner(*surface_, parameters).refine(girdleBelief(kHandleSideOn, v), position(), {v});
  const std::vector<RefinedPose> starts = beliefStarts(result);
  ASSERT_EQ(starts.size(), 36u);
  const auto best = std::min_element(starts.begin(), starts.end(),
                                     [](const RefinedPose& a, const RefinedPose& b) {
                                       return a.screening_distance < b.screening_distance;
                                     });
  EXPECT_TRUE(best->screened_in);
  EXPECT_LT(rotationErrorDeg(best->start_orientation, truth()), 10.0) << describe(result, truth());
  ASSERT_EQ(result.kept.size(), 1u) << describe(result, truth());
  EXPECT_LT(rotationErrorDeg(result.kept[0].orientation, truth()), 2.0);
}

TEST_F(PoseRefinerTest, ScreeningOverAllComponentsAlignsOnlyTheBestOfThemAll) {
  // Two equally weighted girdles, the right one and one of a direction 90 degrees away: per
  // component each aligns its 2 best starts; over all components only the 2 best-screened of the
  // 24 are aligned.
  const RefinementView v = view(kHandleSideOn, 2.1);
  const Eigen::Vector3d wrong = kHandleSideOn.cross(Eigen::Vector3d::UnitZ()).normalized();
  const BinghamMixture camera_frame(
      {0.5, 0.5}, {viewGirdle(kHandleSideOn.normalized(), 18.0), viewGirdle(wrong, 18.0)});
  const BinghamMixture belief =
      cameraToFixedFrame(camera_frame, orientationOf(v.world_from_camera));
  RefinementParameters parameters;
  parameters.hypotheses.girdle_step_deg = 30.0;
  parameters.max_refined = 2;
  parameters.screen_per_component = true;
  const RefinementResult per_component =
      PoseRefiner(*surface_, parameters).refine(belief, position(), {v});
  std::vector<int> aligned(2, 0);
  for (const RefinedPose& pose : beliefStarts(per_component)) {
    if (pose.screened_in) ++aligned[static_cast<std::size_t>(pose.component)];
  }
  EXPECT_EQ(aligned, (std::vector<int>{2, 2}));

  parameters.screen_per_component = false;
  const RefinementResult overall =
      PoseRefiner(*surface_, parameters).refine(belief, position(), {v});
  std::vector<RefinedPose> starts = beliefStarts(overall);
  ASSERT_EQ(starts.size(), 24u);
  std::sort(starts.begin(), starts.end(), [](const RefinedPose& a, const RefinedPose& b) {
    return a.screening_distance < b.screening_distance;
  });
  for (std::size_t i = 0; i < starts.size(); ++i) {
    EXPECT_EQ(starts[i].screened_in, i < 2) << i << "-th best-screened start";
    if (!starts[i].screened_in) {
      EXPECT_NE(starts[i].rejection.find("worse than the 2 best"), std::string::npos);
    }
  }
  ASSERT_FALSE(overall.kept.empty()) << describe(overall, truth());
  EXPECT_LT(rotationErrorDeg(overall.kept.front().orientation, truth()), 2.0)
      << describe(overall, truth());
}

TEST_F(PoseRefinerTest, ARefinerSharingAnothersSurfacesNeedsItsSpacings) {
  const PoseRefiner original(*surface_);
  RefinementParameters other;
  other.max_refined = 6;
  const PoseRefiner sharing(original, other);
  EXPECT_EQ(sharing.sharedSurface(), original.sharedSurface());
  EXPECT_EQ(sharing.parameters().max_refined, 6);
  other.model_spacing = 0.006;
  EXPECT_THROW(PoseRefiner(original, other), Error);
}

TEST_F(PoseRefinerTest, AKeptPoseCarriesItsFitsPositionCovariance) {
  const RefinementView v = view(kHandleSideOn, 2.1);
  const RefinementResult result =
      PoseRefiner(*surface_).refine(girdleBelief(kHandleSideOn, v), position(), {v});
  ASSERT_FALSE(result.kept.empty()) << describe(result, truth());
  const Eigen::Matrix3d& covariance = result.kept[0].position_covariance;
  EXPECT_TRUE(covariance.isApprox(covariance.transpose(), 1e-12));
  const Eigen::Vector3d variances =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvalues();
  const RefinementParameters defaults;
  EXPECT_GE(variances.minCoeff(), 0.999 * std::pow(defaults.min_position_sigma, 2));
  EXPECT_LE(variances.maxCoeff(), 1.001 * std::pow(defaults.max_position_sigma, 2));
  // The true position lies within the covariance's 3-sigma ellipsoid.
  const Eigen::Vector3d error = result.kept[0].world_from_object.translation() - position();
  EXPECT_LT(error.dot(covariance.inverse() * error), 9.0)
      << "error " << 1000 * error.transpose() << " mm, sigmas "
      << 1000 * variances.cwiseSqrt().transpose() << " mm";
}

TEST_F(PoseRefinerTest, AKeptPoseCarriesItsFitsRotationCovarianceFlooredByItsSpread) {
  const RefinementView v = view(kHandleSideOn, 2.1);
  const RefinementResult result =
      PoseRefiner(*surface_).refine(girdleBelief(kHandleSideOn, v), position(), {v});
  ASSERT_FALSE(result.kept.empty()) << describe(result, truth());
  const RefinedPose& pose = result.kept[0];
  const Eigen::Matrix3d& covariance = pose.rotation_covariance;
  EXPECT_TRUE(covariance.isApprox(covariance.transpose(), 1e-12));
  const Eigen::Vector3d sigmas_deg =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvalues().cwiseSqrt() * 180.0 /
      M_PI;
  const RefinementParameters defaults;
  // A whole view of the mug spreads its matches over a few centimetres: the 1 mm floor turns it
  // by 1-2 degrees, above the 1-degree floor and below the 4.05-degree ceiling.
  EXPECT_GT(sigmas_deg.minCoeff(), 1.2) << sigmas_deg.transpose();
  EXPECT_LT(sigmas_deg.minCoeff(), 2.5) << sigmas_deg.transpose();
  EXPECT_LE(sigmas_deg.maxCoeff(), 1.001 * defaults.max_rotation_sigma_deg);
  // The true orientation lies within the covariance's 3-sigma ellipsoid (a turn in the object
  // frame: truth = pose exp(t)).
  const Eigen::Vector4d relative =
      quaternionMultiply(quaternionConjugate(pose.orientation), truth());
  const Eigen::Vector3d turn = 2.0 * relative.tail<3>() * (relative(0) < 0 ? -1.0 : 1.0);
  EXPECT_LT(turn.dot(covariance.inverse() * turn), 9.0) << turn.transpose() * 180 / M_PI;
  // Polishing on every point never makes a kept pose verify more than polish_score_tolerance
  // worse than the starts' ICP left it, nor moves it off that pose.
  RefinementParameters unpolished;
  unpolished.polish_iterations = 0;
  const RefinementResult rough =
      PoseRefiner(*surface_, unpolished).refine(girdleBelief(kHandleSideOn, v), position(), {v});
  ASSERT_FALSE(rough.kept.empty());
  EXPECT_GE(pose.score.score(), rough.kept[0].score.score() - defaults.polish_score_tolerance);
  EXPECT_LT(rotationErrorDeg(pose.orientation, rough.kept[0].orientation),
            defaults.duplicate_angle_deg);
}

TEST_F(PoseRefinerTest, PolishMatchesOnlyTheSamplesFacingTheCamera) {
  // Seen from above, points on the mug's rim and walls lie within the polish's 5 mm of the
  // other side of the wall, whose samples face away; matched to every sample the polished pose
  // was 0.19-0.32 mm and 0.18-0.21 degrees off in these three views, matched only to the
  // samples facing the camera 0.02-0.07 mm and 0.09-0.13 degrees.
  const Eigen::Vector3d from_above(0.3, 0.5, 1.0);
  for (const std::uint32_t seed : {3u, 4u, 5u}) {
    const RefinementView v = view(from_above, 0.7, seed);
    const RefinementResult result =
        PoseRefiner(*surface_).refine(girdleBelief(from_above, v), position(), {v});
    ASSERT_FALSE(result.kept.empty()) << describe(result, truth());
    const RefinedPose& pose = result.kept.front();
    const double position_error_mm =
        1000.0 * (pose.world_from_object.translation() - world_from_object_.translation()).norm();
    EXPECT_LT(position_error_mm, 0.12) << "seed " << seed;
    EXPECT_LT(rotationErrorDeg(pose.orientation, truth()), 0.3) << "seed " << seed;
  }
}

TEST_F(PoseRefinerTest, VerificationRejectsTheMirroredHandle) {
  // Turned 180 degrees about the line of sight the body fits again but the handle is on the wrong
  // side: its points are unexplained and the model's handle stands in free space.
  const RefinementView v = view(kHandleSideOn, 0.4);
  const Eigen::Vector4d wrong = turnedAboutSight(v, M_PI);
  const PoseRefiner refiner(*surface_);
  const RefinementResult alone =
      refiner.refine(BinghamMixture({1.0}, {concentratedAt(wrong)}), position(), {v});
  ASSERT_EQ(beliefStarts(alone).size(), 1u);
  EXPECT_FALSE(alone.tried[0].accepted) << alone.tried[0].score.score();
  EXPECT_TRUE(alone.kept.empty()) << describe(alone, truth());
  // Beside the truth (lighter in the belief) it loses too.
  const RefinementResult both =
      refiner.refine(BinghamMixture({0.8, 0.2}, {concentratedAt(wrong), concentratedAt(truth())}),
                     position(), {v});
  ASSERT_EQ(both.kept.size(), 1u) << describe(both, truth());
  EXPECT_LT(rotationErrorDeg(both.kept[0].orientation, truth()), 2.0) << describe(both, truth());
}

TEST_F(PoseRefinerTest, TheInsideOfAThinWallExplainsANarrowerCanButItsIdentityScoreDoesNot) {
  // A closed can exactly as wide as the mug's inside, standing where the mug would, seen level:
  // its front lies on the mug's inner wall, 4 mm behind the outer one, well within the free-space
  // tolerance. Matched to any side of the surface, the mug explains the can; only its outer wall
  // faces the camera there, and that is 4 mm off.
  const RefinementView mug = view(Eigen::Vector3d(-1.0, 0.0, 0.0), 0.0);
  const MugShape shape;
  const double inner_radius = shape.outer_radius - shape.wall;
  const TriangleMesh can = makeCylinderMesh(inner_radius, shape.height - shape.bottom, 96);
  // The can's origin is its base centre, the mug's its body's centre.
  Eigen::Isometry3d mug_from_can = Eigen::Isometry3d::Identity();
  mug_from_can.translation().z() = -0.5 * shape.height + shape.bottom;
  const RefinementView can_view = inPlaceOfTheMug(mug, can, mug_from_can);
  ASSERT_GT(can_view.points->size(), 500u);

  const VerificationScore on_can = PoseVerifier(*surface_, {can_view}).score(world_from_object_);
  EXPECT_GT(on_can.score(), 0.8) << "inliers " << on_can.inlier_fraction;
  EXPECT_LT(on_can.identityScore(), 0.5) << "facing inliers " << on_can.facing_inlier_fraction;
  // The mug itself: every inlier is on a side its camera sees, and most lie within half the
  // tolerance, which is at least two noise sigmas.
  const VerificationScore on_mug = PoseVerifier(*surface_, {mug}).score(world_from_object_);
  EXPECT_NEAR(on_mug.facing_inlier_fraction, on_mug.inlier_fraction, 0.01);
  EXPECT_GT(on_mug.facing_close_fraction, 0.85);
  EXPECT_GT(on_mug.identityScore(), 0.9);
}

TEST_F(PoseRefinerTest, AModelAFewMillimetresOffTheShapeExplainsFewPointsClosely) {
  // A can 3 mm narrower than the mug, its front where the mug's is: within the inlier tolerance
  // nearly everywhere, but not within half of it; its identity score falls below the mug's own.
  const RefinementView mug = view(Eigen::Vector3d(-1.0, 0.0, 0.0), 0.0);
  const MugShape shape;
  const TriangleMesh can = makeCylinderMesh(shape.outer_radius - 0.003, shape.height, 96);
  Eigen::Isometry3d mug_from_can = Eigen::Isometry3d::Identity();
  mug_from_can.translation() = Eigen::Vector3d(-0.003, 0.0, -0.5 * shape.height);
  const RefinementView can_view = inPlaceOfTheMug(mug, can, mug_from_can);
  ASSERT_GT(can_view.points->size(), 500u);
  const VerificationScore on_can = PoseVerifier(*surface_, {can_view}).score(world_from_object_);
  const VerificationScore on_mug = PoseVerifier(*surface_, {mug}).score(world_from_object_);
  EXPECT_GT(on_can.facing_inlier_fraction, 0.8);
  EXPECT_LT(on_can.facing_close_fraction, on_can.facing_inlier_fraction - 0.2);
  EXPECT_LT(on_can.identityScore(), on_mug.identityScore() - 0.05);
}

TEST_F(PoseRefinerTest, KeepsBothModesOfAMirrorAmbiguousView) {
  // Seen level from the side opposite the handle, the mug is a cylinder whose half turn about the
  // line of sight looks the same: both poses stay.
  const Eigen::Vector3d behind(-1.0, 0.0, 0.0);
  const RefinementView v = view(behind, 0.0);
  const Eigen::Vector4d flipped = turnedAboutSight(v, M_PI);
  const PoseRefiner refiner(*surface_);
  const RefinementResult result =
      refiner.refine(BinghamMixture({0.5, 0.5}, {concentratedAt(truth()), concentratedAt(flipped)}),
                     position(), {v});
  ASSERT_EQ(result.kept.size(), 2u) << describe(result, truth());
  const double to_truth = std::min(rotationErrorDeg(result.kept[0].orientation, truth()),
                                   rotationErrorDeg(result.kept[1].orientation, truth()));
  const double to_flipped = std::min(rotationErrorDeg(result.kept[0].orientation, flipped),
                                     rotationErrorDeg(result.kept[1].orientation, flipped));
  EXPECT_LT(to_truth, 5.0);
  EXPECT_LT(to_flipped, 5.0);
}

TEST_F(PoseRefinerTest, LeavesTheRollFreeWhereTheHandleIsHidden) {
  // From behind the handle, level, the mug's turns about its axis look alike until the handle
  // comes out beside the body: each kept pose carries that sector, so that its measurement does
  // not claim a roll no point fixed.
  const Eigen::Vector3d behind(-1.0, 0.0, 0.0);
  const RefinementView v = view(behind, 0.0);
  const Eigen::Vector4d flipped = turnedAboutSight(v, M_PI);
  const BinghamMixture belief({0.5, 0.5}, {concentratedAt(truth()), concentratedAt(flipped)});
  const RefinementResult result = PoseRefiner(*surface_).refine(belief, position(), {v});
  ASSERT_FALSE(result.kept.empty()) << describe(result, truth());
  for (const RefinedPose& pose : result.kept) {
    EXPECT_GE(pose.roll_sector_deg, 30.0);
    EXPECT_LT(pose.roll_sector_deg, 180.0);
    EXPECT_GT(std::abs(pose.sector_axis.z()), 0.999) << pose.sector_axis.transpose();
  }
  RefinementParameters sharp;
  sharp.roll_sectors = false;
  const RefinementResult without = PoseRefiner(*surface_, sharp).refine(belief, position(), {v});
  ASSERT_FALSE(without.kept.empty());
  for (const RefinedPose& pose : without.kept) EXPECT_EQ(pose.roll_sector_deg, 0.0);
}

TEST_F(PoseRefinerTest, AnEarlierViewOfTheHandlePinsTheRollTheViewFromBehindLeavesFree) {
  // Refined alone, the view from behind the handle leaves the roll free over a sector; aligned
  // and verified together with an earlier view of the handle (same object pose, another camera),
  // every turn contradicts that view and the roll is fixed.
  const RefinementView handle = view(kHandleSideOn, 0.4);
  const RefinementView behind = view(Eigen::Vector3d(-1.0, 0.0, 0.0), 0.0);
  const BinghamMixture belief({1.0}, {concentratedAt(truth())});
  const PoseRefiner refiner(*surface_);
  const RefinementResult alone = refiner.refine(belief, position(), {behind});
  ASSERT_FALSE(alone.kept.empty()) << describe(alone, truth());
  EXPECT_GE(alone.kept.front().roll_sector_deg, 30.0);
  const RefinementResult together = refiner.refine(belief, position(), {behind, handle});
  ASSERT_FALSE(together.kept.empty()) << describe(together, truth());
  EXPECT_EQ(together.kept.front().roll_sector_deg, 0.0);
  EXPECT_LT(rotationErrorDeg(together.kept.front().orientation, truth()), 2.0);
}

TEST_F(PoseRefinerTest, KeepsTheRollSharpWhereTheHandleIsSeen) {
  const RefinementView v = view(kHandleSideOn, 0.4);
  const RefinementResult result = PoseRefiner(*surface_).refine(
      BinghamMixture({1.0}, {concentratedAt(truth())}), position(), {v});
  ASSERT_FALSE(result.kept.empty()) << describe(result, truth());
  EXPECT_EQ(result.kept.front().roll_sector_deg, 0.0);
  EXPECT_LT(rotationErrorDeg(result.kept.front().orientation, truth()), 2.0);
}

TEST_F(PoseRefinerTest, AligningOnSeveralThreadsGivesTheSameResultAsOne) {
  // A girdle's starts and the restarts are aligned in parallel; each is independent, so the
  // result must be the serial one to the bit.
  const RefinementView v = view(kHandleSideOn, 1.3);
  RefinementParameters serial, parallel;
  serial.threads = 1;
  parallel.threads = 3;
  serial.max_refined = parallel.max_refined = 0;  // every start aligned
  const BinghamMixture belief = girdleBelief(kHandleSideOn, v);
  const RefinementResult one = PoseRefiner(*surface_, serial).refine(belief, position(), {v});
  const RefinementResult three = PoseRefiner(*surface_, parallel).refine(belief, position(), {v});
  ASSERT_EQ(one.tried.size(), three.tried.size());
  ASSERT_GT(one.tried.size(), 10u);
  for (std::size_t i = 0; i < one.tried.size(); ++i) {
    EXPECT_TRUE(one.tried[i].world_from_object.isApprox(three.tried[i].world_from_object, 0.0))
        << i;
    EXPECT_EQ(one.tried[i].score.score(), three.tried[i].score.score()) << i;
    EXPECT_EQ(one.tried[i].rejection, three.tried[i].rejection) << i;
  }
  ASSERT_EQ(one.kept.size(), three.kept.size());
  ASSERT_FALSE(one.kept.empty());
  EXPECT_LT(rotationErrorDeg(one.kept.front().orientation, truth()), 2.0);
}

TEST_F(PoseRefinerTest, AViewCroppedToThePatchAroundTheHandleStillVerifiesTheTruePose) {
  // Only the points within 5 cm of the handle's tip are left, as if the rest of the mug were
  // hidden behind something the segmentation removed. The rest of the true pose's predicted
  // surface lies outside the view's footprint, where nothing observed is no contradiction.
  RefinementView v = view(kHandleSideOn, 0.7);
  const pcl::PointCloud<pcl::PointXYZ>::Ptr patch = aroundTheHandle(v);
  ASSERT_GT(patch->size(), 200u);
  ASSERT_LT(patch->size(), v.points->size() / 2);
  v.points = patch;
  const PoseVerifier within(*surface_, {v});
  const VerificationScore truth_within = within.score(world_from_object_);
  EXPECT_GT(truth_within.score(), 0.8)
      << truth_within.inlier_fraction << " " << truth_within.violation_fraction;
  // The mirrored handle (a half turn about the line of sight) still contradicts the patch.
  Eigen::Isometry3d mirrored = world_from_object_;
  mirrored.linear() = quaternionToRotationMatrix(turnedAboutSight(v, M_PI));
  EXPECT_LT(within.score(mirrored).score(), truth_within.score() - 0.3);
  // Judged everywhere, the true pose's hidden body counts against it: below acceptance.
  VerificationParameters everywhere;
  everywhere.judge_only_within_footprint = false;
  const PoseVerifier everywhere_verifier(*surface_, {v}, everywhere);
  EXPECT_LT(everywhere_verifier.score(world_from_object_).score(), 0.5);
}

// A piece's centroid is not the centroid of what the camera sees of the whole object: placed by
// that, the start lies several centimetres off, beyond ICP's reach. Placed also on patches of
// the visible part, the piece is found.
TEST_F(PoseRefinerTest, APieceAroundTheHandleIsFoundFromPlacementsOnPatchesOfTheVisiblePart) {
  RefinementView v = view(kHandleSideOn, 0.7);
  const pcl::PointCloud<pcl::PointXYZ>::Ptr piece = aroundTheHandle(v);
  ASSERT_LT(piece->size(), v.points->size() / 2);
  v.points = piece;
  const BinghamMixture belief({1.0}, {concentratedAt(truth())});
  const auto error_mm = [&](const RefinedPose& pose) {
    return 1000.0 * (pose.world_from_object.translation() - position()).norm();
  };

  RefinementParameters centroid_only;
  centroid_only.piece_placements = 0;
  const RefinementResult at_centroid =
      PoseRefiner(*surface_, centroid_only).refine(belief, position(), {v});
  ASSERT_FALSE(at_centroid.skipped()) << at_centroid.skip_reason;
  for (const RefinedPose& pose : at_centroid.kept) {
    EXPECT_GT(error_mm(pose), 10.0) << describe(at_centroid, truth());
  }

  const RefinementResult on_patches = PoseRefiner(*surface_).refine(belief, position(), {v});
  ASSERT_FALSE(on_patches.kept.empty()) << describe(on_patches, truth());
  EXPECT_GT(on_patches.tried.size(), at_centroid.tried.size());
  const RefinedPose& best = on_patches.kept.front();
  EXPECT_LT(rotationErrorDeg(best.orientation, truth()), 3.0) << describe(on_patches, truth());
  EXPECT_LT(error_mm(best), 3.0) << describe(on_patches, truth());
}

TEST_F(PoseRefinerTest, AnObjectHiddenBehindABarKeepsItsTruePoseAgainstTheWholeScene) {
  const RefinementView unoccluded = view(kHandleSideOn, 0.7);
  const auto visible = std::count_if(unoccluded.points->begin(), unoccluded.points->end(),
                                     [](const pcl::PointXYZ& p) { return std::isfinite(p.z); });
  const RefinementView v = behindABar(kHandleSideOn, 0.7);
  // The bar hides a band across the mug's middle, inside the footprint of what is left.
  ASSERT_LT(v.points->size(), visible * 85 / 100);
  ASSERT_GT(v.points->size(), visible * 40 / 100);

  RefinementView object_only = v;
  object_only.scene = {};
  const VerificationScore alone = PoseVerifier(*surface_, {object_only}).score(world_from_object_);
  const PoseVerifier whole_scene(*surface_, {v});
  const VerificationScore with_scene = whole_scene.score(world_from_object_);
  // Against the mug's points alone, the hidden band is a surface that is not there: the true pose
  // falls below refinement's acceptance (0.8). The scene's bar explains it.
  RecordProperty("true_pose_score_object_only", std::to_string(alone.score()));
  RecordProperty("true_pose_score_whole_scene", std::to_string(with_scene.score()));
  EXPECT_LT(alone.score(), 0.8) << alone.inlier_fraction << " " << alone.violation_fraction;
  EXPECT_GT(with_scene.score(), 0.9)
      << with_scene.inlier_fraction << " " << with_scene.violation_fraction;
  // The scene does not excuse a wrong pose: the mirrored handle still contradicts it.
  Eigen::Isometry3d mirrored = world_from_object_;
  mirrored.linear() = quaternionToRotationMatrix(turnedAboutSight(v, M_PI));
  RecordProperty("mirrored_score_whole_scene", std::to_string(whole_scene.score(mirrored).score()));
  EXPECT_LT(whole_scene.score(mirrored).score(), with_scene.score() - 0.3);
  // Nor a pose moved 2 cm towards the camera, into the space in front of the mug it saw through.
  Eigen::Isometry3d nearer = world_from_object_;
  nearer.translation() +=
      0.02 * (v.world_from_camera.translation() - nearer.translation()).normalized();
  EXPECT_LT(whole_scene.score(nearer).score(), with_scene.score() - 0.3);
}

TEST_F(PoseRefinerTest, APoseSunkIntoTheSupportIsContradictedWhereOneBehindAnOccluderIsNot) {
  // A flat board square to the line of sight, 7 cm behind the mug's centre: given as the scene's
  // support (a table) or as an occluder, the same points.
  RefinementView v = view(kHandleSideOn, 0.7);
  const Eigen::Vector3d centre = world_from_object_ * mesh_->bounds().center().cast<double>();
  const Eigen::Vector3d forward = v.world_from_camera.linear().col(2);
  Scene scene;
  scene.object = {*mesh_, world_from_object_};
  ScenePart board{makeBoxMesh(Eigen::Vector3d(0.5, 0.5, 0.01)), Eigen::Isometry3d::Identity()};
  board.world_from_part.linear() = v.world_from_camera.linear();
  board.world_from_part.translation() = centre + 0.075 * forward;
  scene.distractors.push_back(board);
  const Eigen::Isometry3d camera_from_world = v.world_from_camera.inverse();
  std::mt19937 rng(5);
  const pcl::PointCloud<pcl::PointXYZ> seen =
      DepthRenderer(sceneMesh(scene)).render(camera_from_world, DepthNoiseModel{true}, &rng);
  auto board_points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : seen.points) {
    if (std::isfinite(p.z) && p.z > (camera_from_world * centre).z() + 0.06) {
      board_points->push_back(p);
    }
  }
  ASSERT_GT(board_points->size(), 10000u);
  RefinementView as_support = v, as_occluder = v;
  as_support.scene.supports = board_points;
  as_occluder.scene.occluders = board_points;
  // Pushed 20 cm along the line of sight and 12 cm aside, the mug lies behind the board where the
  // camera saw the board, not the mug.
  Eigen::Isometry3d sunk = world_from_object_;
  sunk.translation() += 0.2 * forward + 0.12 * v.world_from_camera.linear().col(0);
  const VerificationScore behind_support = PoseVerifier(*surface_, {as_support}).score(sunk);
  const VerificationScore behind_occluder = PoseVerifier(*surface_, {as_occluder}).score(sunk);
  EXPECT_GT(behind_support.violation_fraction, 0.8);
  EXPECT_LT(behind_occluder.violation_fraction, 0.2);
  // The true pose: the board contradicts nothing of it.
  const VerificationScore truth = PoseVerifier(*surface_, {as_support}).score(world_from_object_);
  EXPECT_LT(truth.violation_fraction, 0.05);
}

TEST_F(PoseRefinerTest, APoseSunkIntoTheTableIsContradictedByItsPlaneWhereNoRayShowsIt) {
  // The mug's own points as the only scene points (as if another object hid the table around
  // it): pushed 4 cm down into its table, the mug's parts under the table meet no ray that shows
  // the table. The table's plane does: no part of an object lies under the surface it stands on,
  // and the identity score says so.
  RefinementView rays_only = view(kHandleSideOn, 0.7);
  rays_only.scene.occluders = rays_only.points;
  const Eigen::Isometry3d camera_from_object =
      rays_only.world_from_camera.inverse() * world_from_object_;
  const Eigen::Vector3d up = camera_from_object.linear().col(2);
  const Eigen::Vector3d foot =
      camera_from_object * Eigen::Vector3d(0.0, 0.0, mesh_->bounds().min().z());
  ASSERT_GT(up.dot(-foot), 0.0);  // the plane's normal points towards the camera
  RefinementView on_table = rays_only;
  on_table.scene.support_plane = Eigen::Vector4d(up.x(), up.y(), up.z(), -up.dot(foot));
  Eigen::Isometry3d sunk = world_from_object_;
  sunk.translation() -= 0.04 * world_from_object_.linear().col(2);

  const VerificationScore without_plane = PoseVerifier(*surface_, {rays_only}).score(sunk);
  const VerificationScore with_plane = PoseVerifier(*surface_, {on_table}).score(sunk);
  EXPECT_EQ(without_plane.sunk_fraction, 0.0);
  EXPECT_GT(with_plane.sunk_fraction, 0.2);
  EXPECT_LT(with_plane.identityScore(), without_plane.identityScore() - 0.2);
  // Refinement's acceptance leaves it to identification (VerificationScore::score).
  EXPECT_DOUBLE_EQ(with_plane.score(), without_plane.score());
  // Standing on the table, nothing of it is sunk.
  EXPECT_EQ(PoseVerifier(*surface_, {on_table}).score(world_from_object_).sunk_fraction, 0.0);
}

TEST_F(PoseRefinerTest, ASceneIndexedOnceScoresAsTheSceneIndexedPerVerifier) {
  // indexRays indexes the whole scene once for every verifier of a frame instead of each
  // verifier indexing the points around its object: the same scores, the true pose's and a
  // wrong one's.
  RefinementView v = behindABar(kHandleSideOn, 0.7);
  RefinementView indexed = v;
  indexed.scene = indexRays(v.scene);
  ASSERT_TRUE(indexed.scene.occluder_rays);
  EXPECT_FALSE(indexed.scene.support_rays);
  Eigen::Isometry3d mirrored = world_from_object_;
  mirrored.linear() = quaternionToRotationMatrix(turnedAboutSight(v, M_PI));
  for (const Eigen::Isometry3d& pose : {world_from_object_, mirrored}) {
    const VerificationScore per_verifier = PoseVerifier(*surface_, {v}).score(pose);
    const VerificationScore once = PoseVerifier(*surface_, {indexed}).score(pose);
    EXPECT_EQ(once.observed, per_verifier.observed);
    EXPECT_EQ(once.predicted, per_verifier.predicted);
    EXPECT_DOUBLE_EQ(once.violation_fraction, per_verifier.violation_fraction);
    EXPECT_DOUBLE_EQ(once.identityScore(), per_verifier.identityScore());
  }
}

TEST_F(PoseRefinerTest, RefusesIcpThatDivergesOrDoesNotConverge) {
  const RefinementView v = view(kHandleSideOn, 1.0);
  const BinghamMixture belief({1.0}, {concentratedAt(turnedAboutSight(v, 0.3), 20.0)});
  // It would move the pose by millimetres: with a 1 mm leash that is divergence.
  RefinementParameters leash;
  leash.max_translation_step = 0.001;
  const RefinementResult diverged = PoseRefiner(*surface_, leash).refine(belief, position(), {v});
  ASSERT_EQ(beliefStarts(diverged).size(), 1u);
  EXPECT_FALSE(diverged.tried[0].accepted);
  EXPECT_NE(diverged.tried[0].rejection.find("diverged"), std::string::npos)
      << diverged.tried[0].rejection;
  RefinementParameters hurried;
  hurried.max_iterations = 1;
  const RefinementResult stopped = PoseRefiner(*surface_, hurried).refine(belief, position(), {v});
  ASSERT_EQ(beliefStarts(stopped).size(), 1u);
  EXPECT_EQ(stopped.tried[0].rejection, "ICP did not converge");
  EXPECT_TRUE(stopped.kept.empty());
  // With the defaults the same start is refined and accepted.
  const RefinementResult refined = PoseRefiner(*surface_).refine(belief, position(), {v});
  ASSERT_EQ(refined.kept.size(), 1u) << describe(refined, truth());
  EXPECT_LT(rotationErrorDeg(refined.kept[0].orientation, truth()), 2.0)
      << describe(refined, truth());
}

TEST_F(PoseRefinerTest, RefusesIcpThatFindsTooFewPairsInsteadOfWaitingForIt) {
  // Within 10 micrometres no noisy point has a sample: PCL stops before its first step. Aligning
  // on from where it stopped used to ask PCL again for ever (the evaluation hung on a view).
  const RefinementView v = view(kHandleSideOn, 1.0);
  const BinghamMixture belief({1.0}, {concentratedAt(truth(), 20.0)});
  RefinementParameters blind;
  blind.max_correspondence_distance = 1e-5;
  const RefinementResult result = PoseRefiner(*surface_, blind).refine(belief, position(), {v});
  int aligned = 0;
  for (const RefinedPose& pose : result.tried) {
    if (!pose.screened_in) continue;
    ++aligned;
    EXPECT_FALSE(pose.accepted);
    EXPECT_EQ(pose.rejection, "ICP found too few point pairs within max_correspondence_distance");
  }
  EXPECT_GT(aligned, 0);
  EXPECT_TRUE(result.kept.empty());
}

TEST_F(PoseRefinerTest, AbandonsAStartStillFittingBadlyAfterTheScreeningIterations) {
  // A start turned 0.3 rad from the truth needs several ICP steps. After one it still fits
  // worse than a perfect score, so with continue_min_score 1 it is abandoned there, with why;
  // with the default its ICP goes on and is accepted.
  RefinementParameters impatient;
  impatient.restart_screening_iterations = 1;
  impatient.continue_min_score = 1.0;
  expectAbandoned(refineFromATurnedStart(impatient), 1, "continue_min_score");
  impatient.continue_min_score = RefinementParameters().continue_min_score;
  const RefinementResult continued = refineFromATurnedStart(impatient);
  ASSERT_EQ(continued.kept.size(), 1u) << describe(continued, truth());
  EXPECT_GT(continued.tried[0].icp_iterations, 1);
  EXPECT_LT(rotationErrorDeg(continued.kept[0].orientation, truth()), 2.0)
      << describe(continued, truth());
}

TEST_F(PoseRefinerTest, AbandonsAStartStillFittingBadlyAtTheLateScreening) {
  // The same start passes the first screening (continue_min_score -1) and is screened again after
  // late_screening_iterations: still moving and short of a perfect score there, it is abandoned
  // with why; with the late screening no later than the first it goes on and is accepted.
  RefinementParameters impatient;
  impatient.restart_screening_iterations = 1;
  impatient.continue_min_score = -1.0;
  impatient.late_screening_iterations = 2;
  impatient.late_continue_min_score = 1.0;
  expectAbandoned(refineFromATurnedStart(impatient), 2, "late_continue_min_score");
  impatient.late_screening_iterations = 1;
  const RefinementResult continued = refineFromATurnedStart(impatient);
  ASSERT_EQ(continued.kept.size(), 1u) << describe(continued, truth());
  EXPECT_GT(continued.tried[0].icp_iterations, 2);
  EXPECT_LT(rotationErrorDeg(continued.kept[0].orientation, truth()), 2.0)
      << describe(continued, truth());
  RefinementParameters invalid;
  invalid.late_continue_min_score = -1.5;
  EXPECT_THROW(PoseRefiner(*surface_, invalid), Error);
}

TEST_F(PoseRefinerTest, RestartsTurnTheHandleFromAWrongTurnAboutTheMugsAxis) {
  // The belief (broad, so the truth stays in its support) believes the mug turned 120 degrees
  // about its own axis: ICP from there fits the body with the handle on the wrong side and
  // stays. Turning that converged pose about the model's axis of near symmetry reaches the truth.
  const RefinementView v = view(kHandleSideOn, 2.1);
  const BinghamMixture belief = wrongTurnBelief();
  const RefinementResult restarted = PoseRefiner(*surface_).refine(belief, position(), {v});
  ASSERT_FALSE(restarted.kept.empty()) << describe(restarted, truth());
  // (3.4 degrees measured: the turned start's body sits a few millimetres off, ICP trades that
  // for a little roll; the first pass's 2-degree bound is for starts placed on the view.)
  EXPECT_LT(rotationErrorDeg(restarted.kept.front().orientation, truth()), 5.0)
      << describe(restarted, truth());
  EXPECT_GE(restarted.kept.front().restarted_from, 0);
  RefinementParameters no_restarts;
  no_restarts.restart_seeds = 0;
  const RefinementResult alone =
      PoseRefiner(*surface_, no_restarts).refine(belief, position(), {v});
  ASSERT_EQ(alone.tried.size(), 1u);
  EXPECT_GT(rotationErrorDeg(alone.tried[0].orientation, truth()), 30.0)
      << describe(alone, truth());
}

TEST_F(PoseRefinerTest, RestartsOnlyFromASeedVerifyingAtLeastRestartMinScore) {
  // The wrong turn of RestartsTurnTheHandle... converges and seeds the restarts only while it
  // verifies at least restart_min_score (below it a pose is taken for another model's misfit).
  const RefinementView v = view(kHandleSideOn, 2.1);
  const BinghamMixture belief = wrongTurnBelief();
  RefinementParameters no_restarts;
  no_restarts.restart_seeds = 0;
  const RefinementResult alone =
      PoseRefiner(*surface_, no_restarts).refine(belief, position(), {v});
  ASSERT_EQ(alone.tried.size(), 1u);
  ASSERT_TRUE(alone.tried[0].converged) << describe(alone, truth());
  const double seed_score = alone.tried[0].score.score();
  ASSERT_LT(seed_score, 0.99);
  const auto restarts = [&](double restart_min_score) {
    RefinementParameters parameters;
    parameters.restart_min_score = restart_min_score;
    const RefinementResult result =
        PoseRefiner(*surface_, parameters).refine(belief, position(), {v});
    return std::count_if(result.tried.begin(), result.tried.end(),
                         [](const RefinedPose& pose) { return pose.restarted_from >= 0; });
  };
  EXPECT_GT(restarts(seed_score - 0.01), 0);
  EXPECT_EQ(restarts(seed_score + 0.01), 0);
  RefinementParameters invalid;
  invalid.restart_min_score = 1.5;
  EXPECT_THROW(PoseRefiner(*surface_, invalid), Error);
}

TEST_F(PoseRefinerTest, RestartsOnlyTheTurnsTheBeliefAllows) {
  // Once verified views have made the belief sharp, a turn of the seed 30 degrees or more away
  // could only be accepted back on the seed: none is tried. A broad belief allows all 13 turns,
  // and a second sharp mode the one turn that lands on it.
  const RefinementView v = view(kHandleSideOn, 1.0);
  const auto restarts = [](const RefinementResult& result) {
    return std::count_if(result.tried.begin(), result.tried.end(),
                         [](const RefinedPose& pose) { return pose.restarted_from >= 0; });
  };
  const PoseRefiner refiner(*surface_);
  const RefinementResult sharp =
      refiner.refine(BinghamMixture({1.0}, {concentratedAt(truth(), 4000.0)}), position(), {v});
  EXPECT_EQ(restarts(sharp), 0) << describe(sharp, truth());
  ASSERT_FALSE(sharp.kept.empty()) << describe(sharp, truth());
  EXPECT_LT(rotationErrorDeg(sharp.kept.front().orientation, truth()), 2.0);

  const RefinementResult broad =
      refiner.refine(BinghamMixture({1.0}, {concentratedAt(truth(), 20.0)}), position(), {v});
  EXPECT_EQ(restarts(broad), 13) << describe(broad, truth());

  const Eigen::Vector3d axis = world_from_object_.linear().col(2);
  const Eigen::Vector4d turned =
      quaternionMultiply(quaternionFromAxisAngle(axis, 2.0 * M_PI / 3.0), truth());
  const RefinementResult two_modes = refiner.refine(
      BinghamMixture({0.5, 0.5}, {concentratedAt(truth(), 4000.0), concentratedAt(turned, 4000.0)}),
      position(), {v});
  EXPECT_EQ(restarts(two_modes), 1) << describe(two_modes, truth());
}

TEST_F(PoseRefinerTest, APoseTheBeliefRefusesStillTellsHowWellTheModelFitsTheView) {
  // A sharp belief 15 degrees off the truth about the line of sight: ICP carries its start onto
  // the truth, which verifies well but lies outside the belief, so nothing is kept. That the
  // model fits the view is still known: the belief is wrong, not the object.
  const RefinementView v = view(kHandleSideOn, 1.0);
  const PoseRefiner refiner(*surface_);
  const RefinementResult result = refiner.refine(
      BinghamMixture({1.0}, {concentratedAt(turnedAboutSight(v, 15.0 * M_PI / 180.0), 4000.0)}),
      position(), {v});
  ASSERT_TRUE(result.kept.empty()) << describe(result, truth());
  const std::optional<double> fitted = bestFittedIdentityScore(result);
  ASSERT_TRUE(fitted.has_value()) << describe(result, truth());
  EXPECT_GT(*fitted, 0.9) << describe(result, truth());

  RefinementResult nothing_aligned = result;
  for (RefinedPose& pose : nothing_aligned.tried) pose.converged = false;
  EXPECT_FALSE(bestFittedIdentityScore(nothing_aligned).has_value());
}

TEST_F(PoseRefinerTest, SymmetryAxisOfTheMugIsItsBodysAxis) {
  // The built-in mug's body is a surface of revolution about z; its handle must not tilt the axis
  // refinement turns about (the samples' principal axes are tilted 10 degrees by it).
  const Eigen::Vector3d direction = (*surface_)->symmetryAxes().front().direction();
  EXPECT_GT(std::abs(direction.z()), std::cos(1.0 * M_PI / 180.0)) << direction.transpose();
}

TEST_F(PoseRefinerTest, TheMugsFirstHalfTurnAxisRunsThroughItsHandleAndTheBodysMiddle) {
  // A half turn about the line from the body's middle through the handle leaves the handle where
  // it was and the body upside down: the one turn a view of the handle alone cannot tell. The
  // eigenvectors the axis of revolution comes from put the next axis 9 degrees off that line.
  const auto& axes = (*surface_)->symmetryAxes();
  ASSERT_EQ(axes.size(), 3u);
  EXPECT_GT(std::abs(axes[1].direction().x()), std::cos(1.0 * M_PI / 180.0))
      << axes[1].direction().transpose();
  const double middle = mesh_->bounds().center().z();
  EXPECT_NEAR(axes[1].origin().z(), middle, 0.002);
  EXPECT_NEAR(axes[1].origin().y(), 0.0, 0.002);
  EXPECT_NEAR(axes[2].direction().dot(axes[1].direction()), 0.0, 1e-9);
  EXPECT_NEAR(axes[2].direction().dot(axes[0].direction()), 0.0, 1e-9);
}

TEST_F(PoseRefinerTest, RestartsFindTheUpsideDownTwinOfAViewOfTheHandleAlone) {
  // Only the points around the handle are left, and the belief (broad, as after a first view)
  // holds the mug upside down about the line through its handle, which explains them as well as
  // the truth: the restarts' half turn must reach the truth, so that both poses are kept and
  // the measurement is no surer of one than the view is.
  RefinementView v = view(kHandleSideOn, 0.7);
  v.points = aroundTheHandle(v);
  const Eigen::Vector4d twin =
      quaternionMultiply(truth(), quaternionFromAxisAngle(Eigen::Vector3d::UnitX(), M_PI));
  const RefinementResult result = PoseRefiner(*surface_).refine(
      BinghamMixture({1.0}, {concentratedAt(twin, 5.0)}), position(), {v});
  const auto nearest = [&](const Eigen::Vector4d& q) {
    double best = 180.0;
    for (const RefinedPose& pose : result.kept) {
      best = std::min(best, rotationErrorDeg(pose.orientation, q));
    }
    return best;
  };
  EXPECT_LT(nearest(truth()), 5.0) << describe(result, truth());
  EXPECT_LT(nearest(twin), 5.0) << describe(result, truth());
}

TEST_F(PoseRefinerTest, ASecondRoundOfRestartsTurnsTheTwinARestartFoundBackOntoTheTruth) {
  // Around the handle alone, from a belief 12 degrees off the truth: the start converges a few
  // degrees off, its half turn lands on the twin exactly and beats it. One round keeps the twin
  // alone, which a belief fuses as sure of the wrong side; the twin's own half turn lands on the
  // truth, and both are kept.
  RefinementView v = view(Eigen::Vector3d(1.0, 0.2, 0.6), 1.9);
  v.points = aroundTheHandle(v);
  const Eigen::Vector4d twin =
      quaternionMultiply(truth(), quaternionFromAxisAngle(Eigen::Vector3d::UnitX(), M_PI));
  const Eigen::Vector4d off = quaternionMultiply(
      quaternionFromAxisAngle(Eigen::Vector3d(1.0, 1.0, 0.0).normalized(), 12.0 * M_PI / 180.0),
      truth());
  const BinghamMixture belief({1.0}, {concentratedAt(off, 5.0)});
  const auto nearest = [](const RefinementResult& result, const Eigen::Vector4d& q) {
    double best = 180.0;
    for (const RefinedPose& pose : result.kept) {
      best = std::min(best, rotationErrorDeg(pose.orientation, q));
    }
    return best;
  };
  const RefinementResult two_rounds = PoseRefiner(*surface_).refine(belief, position(), {v});
  EXPECT_LT(nearest(two_rounds, truth()), 5.0) << describe(two_rounds, truth());
  EXPECT_LT(nearest(two_rounds, twin), 5.0) << describe(two_rounds, truth());
  RefinementParameters one_round;
  one_round.restart_rounds = 1;
  const RefinementResult one = PoseRefiner(*surface_, one_round).refine(belief, position(), {v});
  EXPECT_GT(nearest(one, truth()), 90.0) << describe(one, truth());
}

TEST_F(PoseRefinerTest, SkipsBadInputWithAReason) {
  const RefinementView v = view(kHandleSideOn, 1.0);
  const BinghamMixture belief({1.0}, {concentratedAt(truth())});
  const PoseRefiner refiner(*surface_);
  const auto skipped = [&](const RefinementView& input, const Eigen::Vector3d& p) {
    const RefinementResult result = refiner.refine(belief, p, {input});
    EXPECT_TRUE(result.tried.empty());
    return result.skip_reason;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();

  RefinementView few = v;
  auto few_points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int i = 0; i < 20; ++i) few_points->push_back(pcl::PointXYZ(0.001f * i, 0.0f, 0.6f));
  few.points = few_points;
  EXPECT_NE(skipped(few, position()).find("only 20 finite object points"), std::string::npos);

  RefinementView all_nan = v;
  all_nan.points =
      pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(100, 1, pcl::PointXYZ(nan, nan, nan));
  EXPECT_NE(skipped(all_nan, position()).find("only 0 finite"), std::string::npos);

  // The mug with a wall behind it: a cloud 1 m across is not the object.
  RefinementView too_big = v;
  auto big = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(*v.points);
  for (int i = 0; i < 100; ++i) big->push_back(pcl::PointXYZ(-0.5f + 0.01f * i, 0.3f, 1.2f));
  too_big.points = big;
  EXPECT_NE(skipped(too_big, position()).find("span"), std::string::npos);

  EXPECT_EQ(skipped(v, Eigen::Vector3d(nan, 0, 0)), "the position estimate is not finite");
  RefinementView bad_pose = v;
  bad_pose.world_from_camera.translation().x() = nan;
  EXPECT_EQ(skipped(bad_pose, position()), "a camera pose is not finite");
}

TEST_F(PoseRefinerTest, VerificationIgnoresPointsNoCameraCouldHaveSeen) {
  // A point at (almost) no depth, or far off the optical axis, has no ray in the image: its x / z
  // is infinite or near a float's maximum, where a k-d tree over the rays would split badly.
  RefinementView v = view(kHandleSideOn, 1.0);
  auto finite = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : v.points->points) {
    if (std::isfinite(p.z)) finite->push_back(p);
  }
  v.points = finite;
  RefinementView with_bad_points = v;
  auto points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(*finite);
  points->push_back(pcl::PointXYZ(0.1f, 0.0f, 1e-39f));
  points->push_back(pcl::PointXYZ(1000.0f, -1000.0f, 1e-4f));
  points->push_back(pcl::PointXYZ(0.1f, 0.1f, 0.0f));
  with_bad_points.points = points;
  const VerificationScore clean = PoseVerifier(*surface_, {v}).score(world_from_object_);
  ASSERT_GT(clean.score(), 0.9);
  const VerificationScore scored =
      PoseVerifier(*surface_, {with_bad_points}).score(world_from_object_);
  EXPECT_EQ(scored.observed, clean.observed);
  EXPECT_EQ(scored.predicted, clean.predicted);
  EXPECT_DOUBLE_EQ(scored.score(), clean.score());
}

TEST_F(PoseRefinerTest, RefusesInvalidParameters) {
  RefinementParameters parameters;
  parameters.min_points = 2;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.max_correspondence_distance = 0.0;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.hypotheses.girdle_step_deg = -1.0;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.screening_points = 0;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.min_position_sigma = 0.1;  // above max_position_sigma
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.restart_step_deg = 0.0;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.restart_screening_iterations = 0;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.restart_rounds = 3;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.restart_max_log_density_drop = 0.0;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.verification.depth_noise_at_1m = -0.001;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.threads = 0;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.min_rotation_sigma_deg = 5.0;  // above max_rotation_sigma_deg
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.polish_iterations = -1;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.polish_scene_voxel = 0.0;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.polish_score_tolerance = -0.01;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.continue_min_score = 1.5;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.measurement_score_margin = -0.1;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters.measurement_score_margin = std::nan("");
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
  parameters = {};
  parameters.max_alternatives = -1;
  EXPECT_THROW(PoseRefiner(*surface_, parameters), Error);
}

}  // namespace
}  // namespace vdc
