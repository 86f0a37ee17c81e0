#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>

#include "view_direction_classification/evaluation/ppf_baseline.h"
#include "view_direction_classification/geometry/surface_sampling.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Settings of the ICP that follows PPF in the baseline (PCL's usual recipe: a coarse pose from
// PPF, refined by ICP). Defaults measured on 10 sequences x 5 views of `vdc evaluate`'s protocol
// (default mug, noise, unoccluded), ICP from each view's PPF pose, medians of axis and position
// error: pairs up to 5 mm 0.08 deg / 0.15 mm, 1 cm 0.10 deg / 0.48 mm, 2 cm 0.28 deg / 1.26 mm,
// 3 cm 0.75 deg / 3.46 mm (PPF alone 1.26 deg / 1.67 mm); 20, 50 or 100 iterations gave the same
// at 1 cm (doc/evaluation.md, "Baseline").
struct BaselineIcpParameters {
  double model_spacing = 0.003;  // [m] of the model's surface samples (mesh normals)
  std::uint32_t model_seed = 1;  // of that sampling
  // Pairs further apart are not used: wider lets pairs across the mug's 4 mm wall and the handle's
  // gap in; it also bounds how far off the PPF pose may be.
  double max_correspondence_distance = 0.005;  // [m]
  int max_iterations = 50;
  // Fewer scene points, camera-facing samples or pairs in an iteration (at least 6 are used: six
  // unknowns): no refinement.
  int min_correspondences = 10;
};

// What ICP made of a starting pose.
struct BaselineIcpResult {
  // false: too few correspondences, or pairs that leave the pose undetermined (a flat patch); the
  // pose is then the starting pose.
  bool converged = false;
  Eigen::Isometry3d camera_from_object = Eigen::Isometry3d::Identity();
  double fitness_m2 = 0;  // PCL's fitness: mean squared distance of the final correspondences
  double milliseconds = 0;
};

// Point-to-plane ICP (pcl::IterativeClosestPointWithNormals) between a scene with normals
// (PpfBaseline::sceneWithNormals, camera frame) and the mesh's surface samples that face the
// camera under the starting pose (back-face culled with the mesh normals). The scene is ICP's
// source and the samples its target: every scene point was seen, so its pairs are real, while a
// sample may face the camera and still be hidden; the samples' exact mesh normals serve the
// point-to-plane error. Point-to-plane rather than point-to-point: it slides along the mug's
// smooth body instead of snapping sample to sample, so it converges in fewer iterations. Not
// GICP: it would estimate covariances of both clouds from neighbours on every call, ignoring the
// mesh's own normals, at several times the cost.
class BaselineIcp {
 public:
  // Throws vdc::Error for an empty mesh or invalid parameters.
  explicit BaselineIcp(const TriangleMesh& mesh, const BaselineIcpParameters& parameters = {});

  // Never throws for cloud content: a scene or a visible model part with fewer than
  // min_correspondences points gives converged = false and the starting pose.
  BaselineIcpResult align(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& camera_scene,
                          const Eigen::Isometry3d& camera_from_object) const;

  const BaselineIcpParameters& parameters() const { return parameters_; }

 private:
  BaselineIcpParameters parameters_;
  SurfaceSamples model_;
};

// The baseline recipe on one camera-frame cloud: PPF, then ICP from its pose.
struct PpfIcpMatch {
  PpfMatch ppf;
  std::optional<BaselineIcpResult> icp;  // none when PPF found no pose
  // The recipe's answer: ICP's pose when it converged, else PPF's; none without a PPF pose.
  std::optional<Eigen::Isometry3d> pose() const;
};
PpfIcpMatch matchPpfIcp(PpfBaseline& ppf, const BaselineIcp& icp,
                        const pcl::PointCloud<pcl::PointXYZ>& camera_cloud);

}  // namespace vdc
