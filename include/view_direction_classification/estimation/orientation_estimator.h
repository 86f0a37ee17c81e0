#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/estimation/object_segmentation.h"
#include "view_direction_classification/estimation/orientation_filter.h"

namespace vdc {

// Online settings of the estimator (config/estimator.yaml). Feature settings are not here: they
// come from the model bundle, so online features match the training ones.
struct EstimatorParameters {
  int n_feat = 0;      // most certain features summed per view; <= 0: the bundle's value
  double kappa = 0.0;  // girdle concentration; <= 0: defaultViewConcentration(view spacing)
  // K_max of the belief. The first value was 200; on the evaluation (10 x 12 views, all and r_vis
  // 5 cm) 50 gives the same median errors at a quarter of the fusion time (doc/method.md,
  // "Defaults").
  int max_components = 50;
  int min_features = 10;     // a view with fewer features is skipped (no update)
  double min_weight = 1e-3;  // measurement components below this p_sum are dropped
  // Belief components lighter than this fraction of the heaviest are dropped after each fusion
  // (and their products never computed). 1e-3 gave the same median errors on the evaluation but
  // no faster updates in the estimator benchmark (fewer merges, more refits), so it stays 1e-6.
  double belief_weight_floor = 1e-6;
  // Segmentation of each cloud. Its roi_centre is a point of the fixed frame (where an object
  // stands still while the camera moves); update() moves it into each cloud's frame.
  SegmentationParameters segmentation;
};

// Wall-clock time of each stage of one update [ms].
struct UpdateTiming {
  double segmentation = 0, features = 0, classification = 0, measurement = 0, fusion = 0, total = 0;

  // Stage-wise sums and means over many updates (benchmarks, the evaluation).
  UpdateTiming& operator+=(const UpdateTiming& other) {
    segmentation += other.segmentation;
    features += other.features;
    classification += other.classification;
    measurement += other.measurement;
    fusion += other.fusion;
    total += other.total;
    return *this;
  }
  UpdateTiming& operator/=(double count) {
    segmentation /= count;
    features /= count;
    classification /= count;
    measurement /= count;
    fusion /= count;
    total /= count;
    return *this;
  }
};

// What one view did.
struct ViewUpdate {
  bool updated = false;     // false: skipped, the belief is unchanged
  std::string skip_reason;  // why it was skipped (one sentence), empty when updated
  int object_points = 0;    // points left after segmentation
  int features = 0;
  Eigen::VectorXd p_sum;  // M, the view's summed distribution (when updated)
  Eigen::Vector3d observed_centroid_world = Eigen::Vector3d::Zero();
  UpdateTiming timing;
};

// The paper's online estimator without ROS (doc/method.md sections 5, 8-10): one depth cloud of the
// object and the camera pose in the fixed frame in, the fused Bingham mixture over q_WO out.
class OrientationEstimator {
 public:
  // Throws vdc::Error for invalid parameters.
  OrientationEstimator(std::shared_ptr<const ModelBundle> model, EstimatorParameters parameters);

  // cloud: in the camera frame (any frame whose pose is world_from_camera; need not be optical,
  // need not be organised; NaN points allowed). Segments (the region of interest moved from the
  // fixed frame into the cloud's frame with world_from_camera), computes features, classifies, sums
  // the n_feat most certain, builds the measurement along the actual line of sight to the
  // object, moves it into the fixed frame and fuses it. Never throws for cloud content: empty,
  // NaN or too small clouds are skipped with a reason. Throws vdc::Error for a non-finite pose.
  ViewUpdate update(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                    const Eigen::Isometry3d& world_from_camera);
  // Back to the uniform prior (forgets the position too).
  void reset();

  const BinghamMixture& belief() const { return filter_.belief(); }
  int updateCount() const { return filter_.updateCount(); }
  Eigen::Vector4d mapOrientation() const;  // q_WO (w, x, y, z), w >= 0
  double entropy() const;
  // Object origin in the fixed frame: the last observed centroid minus R_WO times the stored
  // centroid offset of the training direction the camera sees it from under the MAP
  // orientation. Empty before the first update.
  std::optional<Eigen::Vector3d> positionEstimate() const;
  // 3 x 3 covariance of the orientation's rotation vector [rad^2] (world frame), from the
  // belief's spread around its MAP: for the ROS pose's covariance.
  Eigen::Matrix3d orientationCovariance() const;

  const ModelBundle& model() const { return *model_; }
  const EstimatorParameters& parameters() const { return parameters_; }
  double kappa() const { return kappa_; }

 private:
  std::shared_ptr<const ModelBundle> model_;
  EstimatorParameters parameters_;
  double kappa_;
  OrientationFilter filter_;
  std::optional<Eigen::Vector3d> last_centroid_world_, last_camera_position_world_;
  // The MAP costs a search over every component: computed once per belief, on first request.
  mutable std::optional<Eigen::Vector4d> map_cache_;
};

}  // namespace vdc
