#pragma once

// Point-to-plane ICP of observed points against the model's surface (private to refinement:
// PCL's registration types stay out of the public headers).

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include <memory>
#include <vector>

#include "view_direction_classification/refinement/model_surface.h"

namespace vdc {

struct IcpSettings {
  int max_iterations = 100;
  double max_correspondence_distance = 0.015;
  // Converged when a step moves the pose by less than both of these.
  double convergence_translation = 1e-4;  // [m]
  double convergence_rotation_deg = 0.05;
  // Also converged when settle_iterations in a row move the pose by less than both of these in
  // all: ICP circling a minimum that noise keeps its single steps from settling in.
  int settle_iterations = 10;
  double settle_translation = 5e-4;  // [m]
  double settle_rotation_deg = 1.0;
};

struct IcpOutcome {
  bool converged = false;
  bool degenerate = false;  // a step was singular (the surface leaves a motion unconstrained)
  // PCL stopped before a step: fewer point pairs within the correspondence distance than a
  // step needs. Not converged; aligning on from there would stop there again.
  bool too_few_pairs = false;
  // Where ICP stopped: the converged pose, or (not converged, not degenerate) the last one.
  Eigen::Isometry3d object_from_world = Eigen::Isometry3d::Identity();
  double fitness = 0.0;  // [m^2] (converged only)
  int iterations = 0;
  // Nothing more to align from here: converged, degenerate, or stopped for too few pairs.
  bool ended() const { return converged || degenerate || too_few_pairs; }
};

// Aligns one fixed set of observed points (fixed frame) to the model from many starts, with one
// k-d tree of the model for all of them. Not thread-safe.
class IcpAlignment {
 public:
  // point_weights: one per observed point, how much its squared point-to-plane distance counts
  // (e.g. how many raw points a voxel centroid stands for); empty: 1 each.
  IcpAlignment(std::shared_ptr<const ModelSurface> surface,
               pcl::PointCloud<pcl::PointNormal>::Ptr observed_world, IcpSettings settings,
               std::vector<float> point_weights = {});
  ~IcpAlignment();

  // start: object_from_world of the hypothesis.
  IcpOutcome align(const Eigen::Isometry3d& start_object_from_world);
  // The same with another iteration limit (a short alignment that screens restarts).
  IcpOutcome align(const Eigen::Isometry3d& start_object_from_world, int max_iterations);

 private:
  // One run of PCL's ICP (its own convergence criteria).
  IcpOutcome alignOnce(const Eigen::Isometry3d& start_object_from_world, int max_iterations);

  struct Registration;
  std::unique_ptr<Registration> registration_;
};

}  // namespace vdc
