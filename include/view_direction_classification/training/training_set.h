#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

#include "view_direction_classification/common/progress.h"
#include "view_direction_classification/features/fpfh_features.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/sensor_model.h"
#include "view_direction_classification/geometry/view_sphere.h"

namespace vdc {

// How training (and evaluation) clouds are simulated (doc/method.md section 2).
struct ViewSimulation {
  double distance = 0.6;         // camera to object origin [m]
  double distance_jitter = 0.1;  // relative: distance drawn uniformly in d (1 +/- jitter)
  bool noise = true;             // Kinect axial noise
  // The depth camera imitated when noise is on (sensor_model.h).
  DepthSensor sensor = DepthSensor::kKinectGaussian;
};

// One rendered training cloud, reduced to what training and scoring need.
struct TrainingCloud {
  int view = -1;  // grid direction whose cell it was drawn in
  Eigen::Isometry3d camera_from_object = Eigen::Isometry3d::Identity();
  Eigen::MatrixXf descriptors;                    // features x kFpfhBins
  std::vector<Eigen::Vector3f> object_keypoints;  // keypoints moved into the object frame
  Eigen::Vector3d visible_centroid = Eigen::Vector3d::Zero();  // object frame, of all points
  std::size_t points = 0;                                      // valid depth points rendered
};

// All clouds of a training (or held-out) set, with the features flattened for the classifier.
struct TrainingSet {
  int num_views = 0;
  std::vector<TrainingCloud> clouds;
  Eigen::MatrixXf descriptors;                    // all features, cloud by cloud
  Eigen::VectorXi labels;                         // view of each feature
  Eigen::VectorXi cloud_of_feature;               // index into clouds of each feature
  std::vector<Eigen::Vector3f> object_keypoints;  // per feature, object frame

  std::size_t featureCount() const { return static_cast<std::size_t>(labels.size()); }
  // Number of features per view (a view with none is degenerate: reported by the caller).
  Eigen::VectorXi featuresPerView() const;
};

// Renders `clouds_per_view` clouds for every direction of `sphere`: direction drawn uniformly
// inside the direction's cell, random roll, distance jitter, optional noise; then features.
// Deterministic for a seed whatever the thread count (each cloud has its own generator, seeded
// from (seed, view, index)). Runs clouds in parallel on all cores.
TrainingSet generateTrainingSet(const DepthRenderer& renderer, const ViewSphere& sphere,
                                int clouds_per_view, const ViewSimulation& simulation,
                                const FeatureParameters& features, std::uint32_t seed,
                                const ProgressCallback& progress = {});

// The camera pose of cloud `index` of direction `view` (exposed for tests and the evaluation).
Eigen::Isometry3d sampleTrainingPose(const ViewSphere& sphere, int view,
                                     const ViewSimulation& simulation, std::mt19937& rng);

}  // namespace vdc
