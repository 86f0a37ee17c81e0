// The scene layer on a real Kinect scene (test/support/milk_scene.h): a milk carton among other
// objects on a table, recognised with a library of a carton model, trained quickly from a
// gable-top box of the carton's measured sizes, and the built-in mug, so that identification has
// a choice. The estimator runs with its defaults: nothing here is tuned to this scene.
#include <gtest/gtest.h>
#include <pcl/common/transforms.h>
#include <pcl/io/pcd_io.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/milk_scene.h"
#include "support/quick_mug_model.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/geometry/surface_sampling.h"
#include "view_direction_classification/recognition/scene_estimator.h"
#include "view_direction_classification/recognition/shape_alternative.h"
#include "view_direction_classification/scene/scene_segmentation.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// The carton as its points in the scene show it, measured in the table's frame (the support
// plane segmentScene finds): its two visible walls meet square and are 9.7 and 10.1 cm wide (the
// Kinect's mixed pixels at the silhouette add a few mm), a half-gallon carton's 9.5 cm base
// bulged by its milk; the walls' tops are 20.0 cm above the table, the roof rises at 31 degrees
// across the wall 9.7 cm wide to a ridge 3.0 cm higher, and the sealed fin on the ridge reaches
// 24.6-25.0 cm. The fin lies in the scene but not in milk.pcd: the tutorial's cut left it out.
constexpr double kCartonSide = 0.098, kCartonHeight = 0.248, kCartonGable = 0.030;
constexpr double kCartonFin = 0.018;

TriangleMesh cartonMesh() {
  return makeCartonMesh(Eigen::Vector3d(kCartonSide, kCartonSide, kCartonHeight), kCartonGable,
                        kCartonFin);
}

// Where that mesh stands in the scene's own frame: its base's centre on the table, +z the table's
// normal, +x along the ridge. From the same measurement: each visible wall's plane is the median
// of its points, and the base's centre half the sides in from their corner. The mesh placed so
// lies within 1.6 mm of half of milk.pcd's points and 3.6 mm of 90 % (checked below).
Eigen::Isometry3d sceneFromCarton() {
  const Eigen::Vector3d up = Eigen::Vector3d(-0.00047, 0.82052, 0.57162).normalized();
  const Eigen::Vector3d along(0.77715, 0.36003, -0.51616);  // in the table's plane to 5 digits
  const Eigen::Vector3d ridge = (along - up.dot(along) * up).normalized();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear().col(0) = ridge;
  pose.linear().col(1) = up.cross(ridge);
  pose.linear().col(2) = up;
  pose.translation() = Eigen::Vector3d(-0.06100, 0.04097, -0.87639);
  return pose;
}

// A carton model trained as the tests' quick mug is (12 directions x 3 clouds, a 6 mm surface
// set): seconds, not the minutes of a default training.
std::shared_ptr<const ModelBundle> quickCartonModel(double* training_ms) {
  TrainingParameters parameters = test::quickMugTrainingParameters();
  parameters.mesh_name = "carton";
  const auto start = std::chrono::steady_clock::now();
  auto model = std::make_shared<const ModelBundle>(trainModel(cartonMesh(), parameters));
  *training_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return model;
}

// The distances [m] from each point to the nearest of `surface`'s samples, ascending.
std::vector<double> distancesTo(const SurfaceSamples& surface, const Cloud& points) {
  Cloud::Ptr samples(new Cloud);
  for (const Eigen::Vector3f& p : surface.points) samples->push_back({p.x(), p.y(), p.z()});
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(samples);
  std::vector<int> found(1);
  std::vector<float> squared(1);
  std::vector<double> distances;
  for (const pcl::PointXYZ& p : points) {
    if (tree.nearestKSearch(p, 1, found, squared) == 1) distances.push_back(std::sqrt(squared[0]));
  }
  std::sort(distances.begin(), distances.end());
  return distances;
}

double quantile(const std::vector<double>& ascending, double fraction) {
  return ascending[static_cast<std::size_t>(fraction * (ascending.size() - 1))];
}

// The carton's only rotational symmetry: the half turn about its axis.
const std::vector<Eigen::Vector4d> kCartonSymmetry{
    quaternionFromAxisAngle(Eigen::Vector3d::UnitZ(), M_PI)};

// [deg] The estimator's cone90 measures the belief's spread about its MAP as if every
// orientation were distinct: a belief that holds the carton's two symmetric poses (both true)
// spreads 180 degrees. The same 1000 fixed-seed samples' angles to the nearer of the MAP and its
// symmetric twin give the spread that is uncertainty.
double symmetricCone90(const OrientationEstimator& estimator) {
  std::mt19937_64 generator(7);
  const Eigen::Vector4d map = estimator.mapOrientation();
  std::vector<double> angles;
  for (const Eigen::Vector4d& q : estimator.belief().sample(1000, generator)) {
    angles.push_back(discreteSymmetricRotationErrorDeg(q, map, kCartonSymmetry));
  }
  std::sort(angles.begin(), angles.end());
  return quantile(angles, 0.9);
}

std::string describe(const SceneEstimator& estimator, const SceneUpdate& update) {
  std::ostringstream text;
  text << update.candidates.size() << " candidates on " << update.planes << " plane(s) in "
       << update.total_ms << " ms";
  if (!update.segmentation_note.empty()) text << " (" << update.segmentation_note << ")";
  for (const CandidateOutcome& c : update.candidates) {
    text << "\n  " << c.points << " points at (" << c.centroid_world.transpose() << "), sides ("
         << c.sides.transpose() << "): instance " << c.instance << " p " << c.probability << " "
         << c.note;
  }
  for (const ObjectInstance& instance : estimator.instances()) {
    const auto position = instance.estimator->positionEstimate();
    text << "\n  " << instance.name << " p " << instance.identity_probability << " at ("
         << (position ? *position : Eigen::Vector3d::Constant(NAN)).transpose() << "), identity";
    for (const double p : instance.identity) text << " " << p;
  }
  return text.str();
}

TEST(RealScene, TheMilkCartonIsRecognisedInTheWholeKinectSceneWithDefaults) {
  const std::string scene_path = test::milkScenePath(), carton_path = test::milkCartonPath();
  if (!std::filesystem::exists(scene_path) || !std::filesystem::exists(carton_path)) {
    GTEST_SKIP() << "PCL's milk scene is not at " << scene_path
                 << " (with milk.pcd): " << test::kMilkSceneMissing;
  }
  Cloud scene, carton;
  ASSERT_EQ(pcl::io::loadPCDFile(scene_path, scene), 0) << scene_path;
  ASSERT_EQ(pcl::io::loadPCDFile(carton_path, carton), 0) << carton_path;
  const Eigen::Isometry3d optical_from_scene = test::opticalFromMilkScene();
  Cloud cloud;  // organised, NaNs kept
  pcl::transformPointCloud(scene, cloud, optical_from_scene.matrix().cast<float>());
  ASSERT_EQ(cloud.width, 640u);
  ASSERT_EQ(cloud.height, 480u);

  // The optical frame: every point in front of the camera, each pixel's point on its ray.
  double worst_pixel = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const pcl::PointXYZ& p = cloud[i];
    if (!std::isfinite(p.z)) continue;
    ASSERT_GT(p.z, 0.0f) << "pixel " << i;
    const double u = 525.0 * p.x / p.z + 319.5, v = 525.0 * p.y / p.z + 239.5;
    worst_pixel = std::max({worst_pixel, std::abs(u - static_cast<double>(i % cloud.width)),
                            std::abs(v - static_cast<double>(i / cloud.width))});
  }
  EXPECT_LT(worst_pixel, 0.01);
  // Turned towards the camera, the table's normal points up in the image (-y): the camera looks
  // down on the table from above, y down.
  const SceneSegments segments = segmentScene(cloud, {});
  ASSERT_FALSE(segments.planes.empty()) << segments.note;
  Eigen::Vector4d table = segments.planes[0].coefficients;
  table /= table.head<3>().norm();
  if (table.w() < 0.0) table = -table;  // the camera's side positive
  std::cout << "table (optical frame): " << table.transpose() << "\n";
  EXPECT_LT(table.y(), -0.5);
  EXPECT_GT(table.w(), 0.3);  // the camera ~47 cm above the table

  // The truth, and that the mesh placed there is the carton the camera saw.
  const Eigen::Isometry3d camera_from_carton = optical_from_scene * sceneFromCarton();
  EXPECT_GT(camera_from_carton.linear().col(2).dot(table.head<3>()), 0.9999);
  EXPECT_NEAR(table.head<3>().dot(camera_from_carton.translation()) + table.w(), 0.0, 0.005);
  Cloud carton_points;
  pcl::transformPointCloud(test::cartonInSceneFrame(carton), carton_points,
                           sceneFromCarton().inverse().matrix().cast<float>());
  const std::vector<double> fit = distancesTo(sampleSurface(cartonMesh(), 0.002, 1), carton_points);
  std::cout << "the carton mesh at the truth: milk.pcd's points within "
            << 1000 * quantile(fit, 0.5) << " mm (median), " << 1000 * quantile(fit, 0.9)
            << " mm (90 %)\n";
  ASSERT_LT(quantile(fit, 0.5), 0.002);
  ASSERT_LT(quantile(fit, 0.9), 0.005);

  double training_ms = 0.0;
  const std::shared_ptr<const ModelBundle> carton_model = quickCartonModel(&training_ms);
  // Its roof and fin are about 14 % of its surface, off its bounding box: the model is not a
  // simple shape, so its score bears the simple-shape alternative's penalty like the mug's.
  const bool simple = isSimpleShape(carton_model->surface_points);
  RecordProperty("carton_is_simple_shape", simple ? "yes" : "no");
  SceneEstimator estimator(ModelLibrary({{"carton", carton_model}, {"mug", test::quickMugModel()}}),
                           {});
  const auto start = std::chrono::steady_clock::now();
  const SceneUpdate update = estimator.update(cloud, Eigen::Isometry3d::Identity(), 0.0);
  const double update_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const std::string report = describe(estimator, update);
  std::cout << "carton training " << training_ms << " ms (a simple shape: " << simple
            << "); scene update " << update_ms << " ms: " << report << "\n";
  RecordProperty("carton_training_ms", std::to_string(training_ms));
  RecordProperty("scene_update_ms", std::to_string(update_ms));
  ASSERT_TRUE(update.segmented) << update.skip_reason;

  const int carton_index = estimator.library().find("carton");
  std::vector<const ObjectInstance*> cartons;
  for (const ObjectInstance& instance : estimator.instances()) {
    if (instance.model == carton_index) cartons.push_back(&instance);
  }
  RecordProperty("instances", std::to_string(estimator.instances().size()));
  RecordProperty("carton_instances", std::to_string(cartons.size()));
  // No other candidate is a carton, and the carton is one.
  ASSERT_EQ(cartons.size(), 1u) << report;
  const ObjectInstance& found = *cartons.front();
  const Eigen::Vector3d position = *found.estimator->positionEstimate();
  const double position_error = (position - camera_from_carton.translation()).norm();
  const Eigen::Vector4d truth = quaternionFromRotationMatrix(camera_from_carton.linear());
  const Eigen::Vector4d estimate = found.estimator->mapOrientation();
  const double rotation_error = discreteSymmetricRotationErrorDeg(estimate, truth, kCartonSymmetry);
  const double axis_error =
      axisSymmetricRotationErrorDeg(estimate, truth, Eigen::Vector3d::UnitZ());
  const double cone90 = found.estimator->spread().cone90 * 180.0 / M_PI;
  const double symmetric_cone90 = symmetricCone90(*found.estimator);
  std::cout << "carton: position error " << 1000 * position_error << " mm, rotation error "
            << rotation_error << " deg (axis " << axis_error << " deg), identity probability "
            << found.identity_probability << ", cone90 " << cone90 << " deg (" << symmetric_cone90
            << " deg up to the half turn)\n";
  RecordProperty("position_error_mm", std::to_string(1000 * position_error));
  RecordProperty("rotation_error_deg", std::to_string(rotation_error));
  RecordProperty("axis_error_deg", std::to_string(axis_error));
  RecordProperty("identity_probability", std::to_string(found.identity_probability));
  RecordProperty("cone90_deg", std::to_string(cone90));
  RecordProperty("cone90_up_to_half_turn_deg", std::to_string(symmetric_cone90));
  // The truth is measured to a few mm (the mesh's 9.8 cm sides against the 9.7 and 10.1 cm
  // seen), not to the cm: 2 cm is a miss, not noise. Its axis and ridge are two walls' planes: 5
  // degrees off them is a wrong pose.
  EXPECT_LT(position_error, 0.02) << report;
  EXPECT_LT(rotation_error, 5.0) << report;
  EXPECT_TRUE(estimator.confirmed(found)) << report;
}

}  // namespace
}  // namespace vdc
