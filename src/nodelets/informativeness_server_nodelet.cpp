#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <exception>
#include <memory>

#include "../ros/informativeness_server_ros.h"

namespace vdc {

// The informativeness server as a nodelet. A bad model bundle leaves it inert with one fatal
// line (a nodelet cannot exit its manager, and the other nodelets should keep running).
class InformativenessServerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      server_ = std::make_unique<InformativenessServerRos>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& error) {
      NODELET_FATAL("%s: %s", getName().c_str(), error.what());
    }
  }

  std::unique_ptr<InformativenessServerRos> server_;
};

}  // namespace vdc

PLUGINLIB_EXPORT_CLASS(vdc::InformativenessServerNodelet, nodelet::Nodelet)
