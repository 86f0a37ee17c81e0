#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace vdc {

// Number of bins of a Fast Point Feature Histogram (PCL's FPFHSignature33).
constexpr int kFpfhBins = 33;

// Settings of the local-feature stage (doc/method.md section 3). Training, scoring and the online
// estimator must use identical values, so they are stored in the model bundle.
struct FeatureParameters {
  double keypoint_voxel = 0.004;  // voxel edge of the keypoint subsample [m]
  double normal_radius = 0.01;    // support radius of the normals, in the full cloud [m]
  double fpfh_radius = 0.03;      // support radius of FPFH (the paper's 3 cm) [m]
  // Voxel edge of the FPFH search surface [m]; 0 keeps the full cloud. At 0.6 m a depth camera
  // samples the surface every ~1.1 mm, so a 3 cm support holds ~2000 points and FPFH costs
  // seconds per view. On the mug (42 x 20 views, 4 clusters) a 7 mm surface keeps held-out
  // accuracy (0.190; 0.193 at 5 mm, 0.171 at 3 mm) and the evaluation's errors at an eighth of
  // the 3 mm cost (doc/method.md, "Defaults"; doc/performance.md).
  double support_voxel = 0.007;
  int min_neighbours = 10;  // keypoints with fewer cloud points within fpfh_radius drop
};

// Whether two settings describe a cloud alike (every field equal).
bool operator==(const FeatureParameters& a, const FeatureParameters& b);
inline bool operator!=(const FeatureParameters& a, const FeatureParameters& b) { return !(a == b); }

// Local features of one cloud: keypoint i (in the cloud's frame) has descriptor row i.
struct FeatureSet {
  std::vector<Eigen::Vector3f> keypoints;
  Eigen::MatrixXf descriptors;  // size() x kFpfhBins, each row an FPFH histogram

  std::size_t size() const { return keypoints.size(); }
  bool empty() const { return keypoints.empty(); }
};

// Keypoints (voxel-grid subsample of the support), normals at the support points (voxel centroids
// of the cloud) from the full cloud within normal_radius, flipped towards `viewpoint`, and FPFH at
// the keypoints with the support as search surface. NaN points are
// ignored; keypoints whose normal or descriptor cannot be computed, or with fewer than
// min_neighbours support points, are dropped, so the result never contains NaN. An empty or all-NaN
// cloud gives an empty set. Throws vdc::Error for non-positive radii. `threads`: how many threads
// share the per-point work (0: the machine's; 1 where the caller already runs clouds in parallel).
FeatureSet computeFeatures(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                           const FeatureParameters& parameters = {},
                           const Eigen::Vector3f& viewpoint = Eigen::Vector3f::Zero(),
                           int threads = 0);

}  // namespace vdc
