#pragma once

#include <nodelet/nodelet.h>

#include <exception>
#include <memory>

namespace vdc {

// The nodelet form of a `...Ros` shell class (the class runNode runs as a node of its own):
// RosClass(ros::NodeHandle node, ros::NodeHandle private_node) sets everything up and throws on
// a fatal start-up problem. A manager hosts other nodelets too, so such a problem leaves this
// nodelet inert with one fatal line saying why, instead of taking the manager down.
//
// RosClass gets the nodelet's single-threaded node handles: its callbacks run one at a time, on
// one of the manager's worker threads at a time (alongside the other nodelets' callbacks), as
// under ros::spin() in the node. Its log lines go to the logger named after the nodelet
// (getName(), the private namespace), as NODELET_* would.
template <typename RosClass>
class ShellNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      shell_ = std::make_unique<RosClass>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& error) {
      NODELET_FATAL("%s: %s", getName().c_str(), error.what());
    }
  }

  std::unique_ptr<RosClass> shell_;
};

}  // namespace vdc
