#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Settings of the single-view baseline (Drost et al. 2010 point-pair features as implemented by
// PCL). Defaults measured on the built-in mug at 0.6 m (doc/evaluation.md, "Baseline").
struct PpfParameters {
  // The model: stratified surface samples with their mesh normals. PCL's training and matching
  // grow faster than O(n^2) in their number: 1 cm gives 581 points on the mug (training ~2.5 s,
  // matching ~0.2 s a view); 7 mm (1185 points) took 160 s to train and 18 s a view.
  double model_spacing = 0.01;   // [m]
  std::uint32_t model_seed = 1;  // of the surface sampling
  // Quantisation of the point-pair angles, requested (Drost: 2 pi / 30). The baseline uses the
  // nearest step PCL's voting cannot overflow (safePpfAngleStep, ppf_angle_step.h): 12.41 degrees
  // (2 pi / 29) for the default; angleStepDeg() gives it.
  double angle_step_deg = 12.0;
  double distance_step = 0.005;  // quantisation of the point-pair distance [m]
  // Scene: PCA normals over normal_radius on the full cloud (the estimator's radius, flipped
  // towards the camera), then one point per scene_spacing cell; every
  // reference_sampling_rate-th of those is a reference point of the voting.
  double normal_radius = 0.01;   // [m]
  double scene_spacing = 0.008;  // [m]
  int reference_sampling_rate = 5;
  // Pose clustering thresholds.
  double cluster_position = 0.01;      // [m]
  double cluster_rotation_deg = 12.0;  // [deg]
  int min_scene_points = 10;  // fewer valid points (or normals) than this: no attempt, no pose
};

// What one match gave.
struct PpfMatch {
  bool found = false;  // false: too few scene points or no pose hypothesis
  Eigen::Isometry3d camera_from_object = Eigen::Isometry3d::Identity();
  double milliseconds = 0;  // wall time of normals + matching
};

// An established single-view baseline for `vdc evaluate` (doc/method.md section 11, "beyond the
// paper"): PCL's point-pair-feature registration (pcl::PPFRegistration, Drost et al. 2010)
// trained on the mesh's surface samples with their normals and matched against one depth cloud.
// It gives an orientation from one view alone, without fusion over views.
// OpenCV's surface_matching PPF3DDetector was tried first and dropped: its quantised model
// sampling averages points and normals per cell, which merges the mug's inner and outer walls
// (4 mm apart) into points with meaningless normals (errors of 60-180 degrees on noise-free
// views), and its training slows down quadratically in identical hash keys (over 18 s at a
// relative step of 0.07 on a cylinder). PCL types of the matcher stay inside the .cpp.
class PpfBaseline {
 public:
  // Samples the surface and trains the detector. Throws vdc::Error for an empty mesh or
  // invalid parameters.
  explicit PpfBaseline(const TriangleMesh& mesh, const PpfParameters& parameters = {});
  ~PpfBaseline();
  PpfBaseline(PpfBaseline&&) noexcept;
  PpfBaseline& operator=(PpfBaseline&&) noexcept;

  // The best pose of the object in a camera-frame cloud (organised or not, NaN allowed). Never
  // throws for cloud content: an empty or too small cloud gives found = false. Not thread-safe
  // (the registration keeps matching state): use one instance per thread.
  PpfMatch match(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud);

  // The cloud's finite points with PCA normals (radius search over normal_radius, flipped towards
  // the camera at the origin), at full resolution: what match() samples and what ICP after PPF
  // aligns to (baseline_icp.h).
  pcl::PointCloud<pcl::PointNormal>::Ptr sceneWithNormals(
      const pcl::PointCloud<pcl::PointXYZ>& camera_cloud) const;
  // match() on a scene sceneWithNormals made (sampled to scene_spacing here; null or too small:
  // found = false). milliseconds counts the matching alone.
  PpfMatch matchScene(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& scene);

  const PpfParameters& parameters() const { return parameters_; }
  // The angle step in use [deg]: the safe one nearest to parameters().angle_step_deg.
  double angleStepDeg() const;
  std::size_t modelPoints() const { return model_points_; }

 private:
  struct Detector;
  PpfParameters parameters_;
  std::size_t model_points_ = 0;
  float angle_step_rad_ = 0;
  std::unique_ptr<Detector> detector_;
};

}  // namespace vdc
