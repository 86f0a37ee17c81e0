#pragma once

#include <Eigen/Geometry>

#include <optional>
#include <vector>

#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/recognition/model_library.h"

namespace vdc {

struct ObjectInstance;

// The pose an instance's estimator believes (its MAP orientation at its position estimate), or
// nothing before it has a position.
std::optional<Eigen::Isometry3d> believedPose(const OrientationEstimator& estimator);

// Whether an object just identified is one the memory already holds, found a little off its
// believed place: moved a few centimetres, or cut into pieces that the instance's pose did not
// explain. Two objects of one model cannot fill the same space, so when the model at the new
// pose and at an instance's believed pose share much of their volume they are one object. The
// centroid association and the moved-instance rule (InstancePresence::movedInstance) miss this
// case: a big object's pieces have centroids a decimetre from the instance's, and a place half
// covered by the moved object is not seen free.
class InstanceOverlap {
 public:
  explicit InstanceOverlap(const ModelLibrary& library);

  // In [0, 1]: the fraction of the model's convex hull at `a` that lies inside its hull at `b`
  // (the shared volume over the hull's; the hull, not the surface, because another object
  // cannot stand in a mug's cavity either). 1 for one pose, 0 for two objects side by side
  // (a little more for a handle reaching into the other's hull); 0.36-0.47 for a mug moved 4 cm,
  // 0.13-0.25 for 6 cm.
  double overlap(int model, const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) const;

  // The index of the instance of `model` that is not gone and whose believed pose overlaps
  // world_from_object most, by at least `min_overlap`; -1 if none does.
  int overlappingInstance(const std::vector<ObjectInstance>& instances, int model,
                          const Eigen::Isometry3d& world_from_object, double min_overlap) const;

 private:
  // The fraction of the hull's volume samples at samples_pose inside the hull at hull_pose.
  double insideFraction(int model, const Eigen::Isometry3d& samples_pose,
                        const Eigen::Isometry3d& hull_pose) const;

  // One model's convex hull, in its own frame.
  struct ModelHull {
    Eigen::AlignedBox3d box;               // the model's bounds: a quick test before the planes
    std::vector<Eigen::Vector4d> planes;   // facets n . x + d = 0, n out
    std::vector<Eigen::Vector3d> samples;  // a grid of points inside it
  };
  std::vector<ModelHull> hulls_;  // per library model
};

}  // namespace vdc
