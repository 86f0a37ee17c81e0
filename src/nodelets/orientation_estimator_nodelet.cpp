#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <exception>
#include <memory>

#include "../ros/orientation_estimator_ros.h"

namespace vdc {

// The orientation_estimator as a nodelet: beside a camera driver in one manager, clouds arrive
// without serialisation.
class OrientationEstimatorNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      estimator_ =
          std::make_unique<OrientationEstimatorRos>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& error) {
      // A manager hosts other nodelets too: a bad model or parameter leaves this one inert
      // (and says why) instead of taking the manager down.
      NODELET_FATAL("%s", error.what());
    }
  }

  std::unique_ptr<OrientationEstimatorRos> estimator_;
};

}  // namespace vdc

PLUGINLIB_EXPORT_CLASS(vdc::OrientationEstimatorNodelet, nodelet::Nodelet)
