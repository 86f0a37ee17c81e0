#pragma once

#include <sensor_msgs/PointCloud2.h>
#include <view_direction_classification/BinghamMixture.h>
#include <view_direction_classification/GetHeatmap.h>
#include <view_direction_classification/GetNextBestView.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "informativeness_server_ros_parameters.h"
#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/planning/next_best_view.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// The surface set of `model` as a PointCloud2 (x, y, z, rgb) in `frame`, coloured by `scores`
// on the paper's scale, black at `black_at` (the ~heatmap topic and ~get_heatmap's cloud).
sensor_msgs::PointCloud2 colouredSurface(const ModelBundle& model, const Eigen::VectorXf& scores,
                                         double black_at, const std::string& frame);

// What the informativeness server answers, without ROS transport: the services' requests and the
// estimates it tracks, on one model. InformativenessServerRos owns one and feeds it from its
// service servers, its subscriber and tf; the fuzz target (fuzz/server_requests_fuzzer.cpp)
// calls it with requests built from bytes. Every method is safe to call from several threads.
class InformativenessServerRequests {
 public:
  // fixed_frame <- frame, for a frame other than the fixed frame; throws vdc::Error naming the
  // frame and `what` if there is no such transform (tf's lookup with the server's timeout).
  using FrameLookup = std::function<Eigen::Isometry3d(const std::string& frame, const char* what)>;

  // Throws vdc::Error if the model's parts do not agree in size (ViewUtilityScorer).
  InformativenessServerRequests(std::shared_ptr<const ModelBundle> model,
                                InformativenessServerRosParameters parameters, FrameLookup lookup);

  const ModelBundle& model() const { return *model_; }
  const ViewUtilityScorer& scorer() const { return *scorer_; }

  // ~get_heatmap and ~next_best_view: fill the response, or on any invalid request leave it
  // empty with success = false and a message saying why.
  void getHeatmap(const view_direction_classification::GetHeatmap::Request& request,
                  view_direction_classification::GetHeatmap::Response& response) const;
  void nextBestView(const view_direction_classification::GetNextBestView::Request& request,
                    view_direction_classification::GetNextBestView::Response& response);

  // The settings of later requests: a reconfigure (cfg/InformativenessServer.cfg) changes the
  // utility settings while the server runs. A request in flight finishes with the settings it
  // started with.
  void setParameters(const InformativenessServerRosParameters& parameters);
  InformativenessServerRosParameters parameters() const;

  // Keeps an estimate as the belief of later requests. Throws vdc::Error (the belief kept so far
  // stays) for an estimate outside the fixed frame or an invalid mixture.
  void receiveEstimate(const view_direction_classification::BinghamMixture& msg);

 private:
  // Throw vdc::Error for an invalid request; fill the response on success.
  void answerHeatmap(const view_direction_classification::GetHeatmap::Request& request,
                     view_direction_classification::GetHeatmap::Response& response) const;
  void answerNextBestView(const view_direction_classification::GetNextBestView::Request& request,
                          view_direction_classification::GetNextBestView::Response& response);
  // Identity for an empty frame or `fixed_frame`, else lookup_.
  Eigen::Isometry3d lookupFixedFrom(const std::string& frame, const std::string& fixed_frame,
                                    const char* what) const;

  std::shared_ptr<const ModelBundle> model_;
  std::unique_ptr<ViewUtilityScorer> scorer_;
  FrameLookup lookup_;

  mutable std::mutex parameters_mutex_;  // reconfigure against the requests reading them
  InformativenessServerRosParameters parameters_;

  std::mutex
      belief_mutex_;  // the estimate callback and the services (see InformativenessServerRos)
  std::optional<BinghamMixture> latest_belief_;
  Eigen::Vector4d latest_map_ = Eigen::Vector4d(1, 0, 0, 0);
};

}  // namespace vdc
