#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

#include "view_direction_classification/geometry/sensor_model.h"
#include "view_direction_classification/informativeness/informativeness.h"
#include "view_direction_classification/learning/view_classifier.h"

namespace vdc {

// Everything needed to reproduce training and to run online with identical settings.
struct TrainingParameters {
  std::string mesh_name;
  int views = 42;
  int clouds_per_view = 20;
  std::uint32_t seed = 1;
  double distance = 0.6, distance_jitter = 0.1;
  bool noise = true;
  // The depth camera simulated for training (sensor_model.h); bundles written before it was
  // recorded trained with the default.
  DepthSensor sensor = DepthSensor::kKinectGaussian;
  int image_width = 640, image_height = 480;
  double fx = 525, fy = 525, cx = 319.5, cy = 239.5;
  double keypoint_voxel = 0.004, normal_radius = 0.01, fpfh_radius = 0.03, support_voxel = 0.007;
  int min_neighbours = 10;
  int n_feat = 50;
  double surface_spacing = 0.002, score_radius = 0.005;
  // K-means routing (the authors' thesis): on the mug, 4 clusters raise held-out accuracy from
  // 0.145 to 0.171 (42 x 20 views) and make handle points score better than the body.
  int clusters = 4;
  double l2 = 1e-4;
};

// The trained model of one object: classifier and informativeness (doc/method.md, "Model
// bundle"). M = view_directions.size(), N = surface_points.size().
struct ModelBundle {
  // 2 added surface/bounds; version-1 files still load (bounds from the surface points).
  static constexpr int kFormatVersion = 2;
  TrainingParameters parameters;
  std::vector<Eigen::Vector3d> view_directions;                  // M, object frame, unit
  ViewClassifier classifier;                                     // trained, over M views
  std::vector<Eigen::Vector3f> surface_points, surface_normals;  // N
  // The object's extent: the axis-aligned bounding box of the mesh in the object frame (tabletop
  // segmentation takes the cluster whose size fits it).
  Eigen::AlignedBox3d bounds;
  ViewInformativeness view_informativeness;                      // v (M), ranking, C (M x M)
  Eigen::MatrixXf score_matrix;                                  // K, N x M
  Eigen::VectorXf global_scores;                                 // g, N
  Eigen::MatrixXd
      centroid_offsets;  // M x 3: mean visible-part centroid per direction, object frame
  HeldOutMetrics held_out;
};

// Writes one HDF5 file (plain datasets and attributes in groups, readable by h5dump and h5py;
// layout documented in model_bundle.cpp). The file is written beside `path` under a temporary
// name and renamed at the end, so `path` never holds a half-written bundle. Throws vdc::Error
// naming the file if the bundle is inconsistent (the same checks as loading) or writing fails.
void saveModelBundle(const ModelBundle& bundle, const std::string& path);

// Reads and checks a bundle: the file exists and is HDF5, carries our format attribute, its
// version is not newer than kFormatVersion, every dataset and attribute is present with
// consistent shapes and finite values. Otherwise throws vdc::Error with one line naming the file
// and the problem, e.g. "model.h5: dataset classifier/weights has 7 rows, expected 34".
ModelBundle loadModelBundle(const std::string& path);

}  // namespace vdc
