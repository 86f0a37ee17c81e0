#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <exception>
#include <memory>

#include "../ros/simulated_depth_camera_ros.h"

namespace vdc {

// The simulated camera as a nodelet, so an estimator nodelet in the same manager gets its clouds
// without a copy. A start-up problem leaves it inert with one fatal line (a nodelet cannot exit
// its manager).
class SimulatedDepthCameraNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      camera_ = std::make_unique<SimulatedDepthCameraRos>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& error) {
      NODELET_FATAL("%s: %s", getName().c_str(), error.what());
    }
  }

  std::unique_ptr<SimulatedDepthCameraRos> camera_;
};

}  // namespace vdc

PLUGINLIB_EXPORT_CLASS(vdc::SimulatedDepthCameraNodelet, nodelet::Nodelet)
