#pragma once

#include <std_msgs/Header.h>
#include <view_direction_classification/ObjectInstance.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc {

// An instance's pose as the node reports it (~instances, its tf frame, its markers).
struct InstancePose {
  Eigen::Vector3d position;
  Eigen::Vector4d orientation;  // MAP, (w, x, y, z)
};

// What the message needs besides the instance: the node's estimator settings.
struct InstanceMessageSettings {
  double position_variance = 0.0025;  // [m^2] when the refinement gave no covariance
  double converged_cone90_deg = 15.0;
};

// The instance's pose if the node reports it: identified (its identity probability at least
// identity_min_probability) and with a position estimate. Present or gone.
std::optional<InstancePose> reportedPose(const SceneEstimator& estimator,
                                         const ObjectInstance& instance);

// The instance as ~instances lists it (header: the fixed frame and the stamp of the answer);
// nullopt for an instance not reported (reportedPose). One converter for the topic and the
// ~query_instances service, so that both say the same about an instance.
std::optional<view_direction_classification::ObjectInstance> toObjectInstanceMsg(
    const SceneEstimator& estimator, const ObjectInstance& instance, const std_msgs::Header& header,
    const InstanceMessageSettings& settings);

// Every reported instance, in the estimator's order.
std::vector<view_direction_classification::ObjectInstance> reportedInstances(
    const SceneEstimator& estimator, const std_msgs::Header& header,
    const InstanceMessageSettings& settings);

}  // namespace vdc
