#include "instance_messages.h"

#include <cmath>
#include <cstdint>

#include "view_direction_classification/ros/bingham_conversions.h"
#include "view_direction_classification/ros/geometry_conversions.h"

namespace vdc {

using ObjectInstanceMsg = view_direction_classification::ObjectInstance;

std::optional<InstancePose> reportedPose(const SceneEstimator& estimator,
                                         const ObjectInstance& instance) {
  // An instance the views no longer support well enough is not reported until they do again,
  // or it is dropped.
  if (!estimator.identified(instance)) return std::nullopt;
  const auto position = instance.estimator->positionEstimate();
  if (!position) return std::nullopt;
  return InstancePose{*position, instance.estimator->mapOrientation()};
}

std::optional<ObjectInstanceMsg> toObjectInstanceMsg(const SceneEstimator& scene,
                                                     const ObjectInstance& instance,
                                                     const std_msgs::Header& header,
                                                     const InstanceMessageSettings& settings) {
  const std::optional<InstancePose> pose = reportedPose(scene, instance);
  if (!pose) return std::nullopt;
  const bool gone = instance.presence.state == InstanceState::kGone;
  const OrientationEstimator& estimator = *instance.estimator;
  ObjectInstanceMsg entry;
  entry.id = static_cast<std::uint32_t>(instance.id);
  entry.name = instance.name;
  entry.model = scene.library().models()[instance.model].name;
  entry.identity_probability = instance.identity_probability;
  entry.pose =
      toPoseWithCovarianceMsg(pose->position, pose->orientation,
                              estimator.positionCovariance().value_or(settings.position_variance *
                                                                      Eigen::Matrix3d::Identity()),
                              estimator.orientationCovariance());
  entry.belief = toBinghamMixtureMsg(estimator.belief());
  entry.belief.header = header;
  entry.belief.object_id = instance.name;
  entry.belief.map_orientation = toQuaternionMsg(pose->orientation);
  entry.belief.entropy = estimator.entropy();
  entry.views_fused = entry.belief.views_fused = static_cast<std::uint32_t>(estimator.viewsFused());
  entry.cone90_deg = entry.belief.cone90_deg = estimator.spread().cone90 * 180.0 / M_PI;
  entry.converged = entry.belief.converged = entry.cone90_deg <= settings.converged_cone90_deg;
  entry.last_seen = instance.last_seen ? ros::Time(*instance.last_seen) : ros::Time();
  entry.state = gone ? ObjectInstanceMsg::GONE : ObjectInstanceMsg::PRESENT;
  if (gone && instance.presence.gone_since) {
    entry.gone_since = ros::Time(*instance.presence.gone_since);
  }
  return entry;
}

std::vector<ObjectInstanceMsg> reportedInstances(const SceneEstimator& estimator,
                                                 const std_msgs::Header& header,
                                                 const InstanceMessageSettings& settings) {
  std::vector<ObjectInstanceMsg> reported;
  for (const ObjectInstance& instance : estimator.instances()) {
    if (auto entry = toObjectInstanceMsg(estimator, instance, header, settings)) {
      reported.push_back(std::move(*entry));
    }
  }
  return reported;
}

}  // namespace vdc
