#pragma once

#include <Eigen/Geometry>

#include <memory>
#include <vector>

#include "view_direction_classification/recognition/model_library.h"

namespace vdc {

class NearestPoints;
struct ObjectInstance;

// Whether two identified objects of different models would stand inside each other. A small
// piece of an object lets a wrong model verify well with most of it hidden behind the rest of the
// object (a cow on a piece of an elephant's legs, the cow's body behind the elephant's); the
// whole-scene verification takes the hidden body for hidden, which it would be if the elephant
// were not there. Once the elephant is identified too, the two models overlap in space, which no
// two objects do. Judged on the surfaces, not the hulls: a convex hull includes the space between
// an animal's legs, where another object may well stand.
class InstanceCollision {
 public:
  explicit InstanceCollision(const ModelLibrary& library);
  ~InstanceCollision();

  // In [0, 1]: the larger of the shares of each model's surface samples (a few hundred, evenly
  // strided) that lie deeper than `depth` [m] inside the other model at its pose, inside told by
  // the nearest surface sample's outward normal. 0 for objects side by side or touching.
  double penetration(int model_a, const Eigen::Isometry3d& a, int model_b,
                     const Eigen::Isometry3d& b, double depth) const;

  // The index of the instance of another model than `model`, neither gone nor seen out of its
  // place on this frame (presence.last_check), that `model` at world_from_object penetrates most,
  // by more than `min_penetration`; -1 if none does.
  int collidingInstance(const std::vector<ObjectInstance>& instances, int model,
                        const Eigen::Isometry3d& world_from_object, double depth,
                        double min_penetration) const;

 private:
  // The share of `samples_model`'s strided samples at samples_pose deeper than depth inside
  // `body_model` at body_pose.
  double insideShare(int samples_model, const Eigen::Isometry3d& samples_pose, int body_model,
                     const Eigen::Isometry3d& body_pose, double depth) const;

  struct ModelBody {
    std::unique_ptr<const NearestPoints> surface;  // all samples, object frame
    std::vector<Eigen::Vector3f> points, normals;  // the samples and their outward normals
    std::vector<Eigen::Vector3f> probes;           // a strided subset of the samples
    double radius = 0.0;                           // [m] the bounds' half diagonal
  };
  std::vector<ModelBody> bodies_;  // per library model
};

}  // namespace vdc
