#include "view_direction_classification/training/training_set.h"

#include <gtest/gtest.h>

#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/surface_sampling.h"

namespace vdc {
namespace {

class TrainingSetTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mesh_ = new TriangleMesh(makeMug());
    renderer_ = new DepthRenderer(*mesh_);
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete mesh_;
  }
  static TriangleMesh* mesh_;
  static DepthRenderer* renderer_;
};
TriangleMesh* TrainingSetTest::mesh_ = nullptr;
DepthRenderer* TrainingSetTest::renderer_ = nullptr;

TEST_F(TrainingSetTest, LabelsEveryFeatureWithItsCloudsView) {
  const ViewSphere sphere(12);
  const TrainingSet set = generateTrainingSet(*renderer_, sphere, 2, {}, {}, 7);
  ASSERT_EQ(set.clouds.size(), 24u);
  ASSERT_GT(set.featureCount(), 0u);
  EXPECT_EQ(set.descriptors.rows(), static_cast<Eigen::Index>(set.featureCount()));
  EXPECT_EQ(set.object_keypoints.size(), set.featureCount());
  for (Eigen::Index i = 0; i < set.labels.size(); ++i) {
    const auto& cloud = set.clouds[static_cast<std::size_t>(set.cloud_of_feature(i))];
    ASSERT_EQ(set.labels(i), cloud.view);
  }
  EXPECT_EQ(set.featuresPerView().sum(), static_cast<int>(set.featureCount()));
  EXPECT_GT(set.featuresPerView().minCoeff(), 0);
}

TEST_F(TrainingSetTest, IsReproducibleForASeedAndDiffersAcrossSeeds) {
  const ViewSphere sphere(12);
  const TrainingSet a = generateTrainingSet(*renderer_, sphere, 1, {}, {}, 3);
  const TrainingSet b = generateTrainingSet(*renderer_, sphere, 1, {}, {}, 3);
  const TrainingSet c = generateTrainingSet(*renderer_, sphere, 1, {}, {}, 4);
  EXPECT_EQ(a.descriptors, b.descriptors);
  EXPECT_EQ(a.labels, b.labels);
  EXPECT_FALSE(a.descriptors.rows() == c.descriptors.rows() && a.descriptors == c.descriptors);
}

TEST_F(TrainingSetTest, TheSimulatedSensorRendersTheTrainingClouds) {
  // Same seed, same poses (drawn before the noise): structured light loses edge pixels and
  // shadows that the default Gaussian noise keeps.
  const ViewSphere sphere(12);
  ViewSimulation structured_light;
  structured_light.sensor = DepthSensor::kStructuredLight;
  const TrainingSet gaussian = generateTrainingSet(*renderer_, sphere, 1, {}, {}, 3);
  const TrainingSet sl = generateTrainingSet(*renderer_, sphere, 1, structured_light, {}, 3);
  ASSERT_EQ(gaussian.clouds.size(), sl.clouds.size());
  for (std::size_t i = 0; i < sl.clouds.size(); ++i) {
    EXPECT_TRUE(sl.clouds[i].camera_from_object.isApprox(gaussian.clouds[i].camera_from_object));
    EXPECT_LT(sl.clouds[i].points, gaussian.clouds[i].points) << i;
  }
}

TEST_F(TrainingSetTest, CloudsAreSeenFromInsideTheirDirectionsCell) {
  const ViewSphere sphere(42);
  ViewSimulation simulation;
  std::mt19937 rng(11);
  for (int m = 0; m < sphere.size(); ++m) {
    const Eigen::Isometry3d pose = sampleTrainingPose(sphere, m, simulation, rng);
    EXPECT_EQ(sphere.nearest(viewDirectionOf(pose)), m);
    const double distance = pose.translation().norm();
    EXPECT_GE(distance, simulation.distance * (1 - simulation.distance_jitter) - 1e-9);
    EXPECT_LE(distance, simulation.distance * (1 + simulation.distance_jitter) + 1e-9);
  }
}

TEST_F(TrainingSetTest, KeypointsInTheObjectFrameLieOnTheMesh) {
  const ViewSphere sphere(12);
  ViewSimulation simulation;
  simulation.noise = false;
  const TrainingSet set = generateTrainingSet(*renderer_, sphere, 1, simulation, {}, 5);
  const SurfaceSamples surface = sampleSurface(*mesh_, 0.001, 1);
  // A keypoint is a voxel centroid of surface points: within a few mm of the surface, never
  // centimetres off (which a wrong camera-to-object transform would give).
  std::size_t far = 0;
  for (const auto& k : set.object_keypoints) {
    double best = 1e9;
    for (const auto& s : surface.points) best = std::min(best, double((s - k).norm()));
    if (best > 0.004) ++far;
  }
  EXPECT_LT(far, set.featureCount() / 100 + 1);
  // The visible centroid sits inside the mug's bounding box.
  for (const auto& cloud : set.clouds) {
    EXPECT_LT(cloud.visible_centroid.head<2>().norm(), 0.07);
    EXPECT_LT(std::abs(cloud.visible_centroid.z()), 0.05);
  }
}

}  // namespace
}  // namespace vdc
