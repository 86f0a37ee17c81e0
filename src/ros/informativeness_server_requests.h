#pragma once

#include <sensor_msgs/PointCloud2.h>
#include <view_direction_classification/BinghamMixture.h>
#include <view_direction_classification/GetHeatmap.h>
#include <view_direction_classification/GetNextBestView.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "informativeness_server_ros_parameters.h"
#include "instance_choice.h"
#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/planning/next_best_view.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// The surface set of `model` as a PointCloud2 (x, y, z, rgb) in `frame`, coloured by `scores`
// on the paper's scale, black at `black_at` (the ~heatmap topic and ~get_heatmap's cloud).
sensor_msgs::PointCloud2 colouredSurface(const ModelBundle& model, const Eigen::VectorXf& scores,
                                         double black_at, const std::string& frame);

// The server's model library (~models): each model's name (an ObjectInstance's `model`) and bundle.
using ServedLibrary = std::vector<std::pair<std::string, std::shared_ptr<const ModelBundle>>>;

// What the informativeness server answers, without ROS transport: the services' requests and the
// estimates and instances it tracks, on its one model (a request with an empty `instance`) and
// on its library (a request naming an instance). InformativenessServerRos owns one and feeds it
// from its service servers, its subscribers and tf; the fuzz target
// (fuzz/server_requests_fuzzer.cpp) calls it with requests built from bytes. Every method is safe
// to call from several threads.
class InformativenessServerRequests {
 public:
  // fixed_frame <- frame, for a frame other than the fixed frame; throws vdc::Error naming the
  // frame and `what` if there is no such transform (tf's lookup with the server's timeout).
  using FrameLookup = std::function<Eigen::Isometry3d(const std::string& frame, const char* what)>;

  // `model` may be null when `library` is not empty (a server for instances only). Throws
  // vdc::Error if there is neither, or a model's parts do not agree in size (ViewUtilityScorer).
  InformativenessServerRequests(std::shared_ptr<const ModelBundle> model,
                                InformativenessServerRosParameters parameters, FrameLookup lookup,
                                const ServedLibrary& library = {});

  // The one model (~model); model() and scorer() only if hasSingleModel().
  bool hasSingleModel() const { return model_ != nullptr; }
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
  // Keeps the latest ~instances for the requests that name an instance. Throws vdc::Error (the
  // instances kept so far stay) for a message outside the fixed frame.
  void receiveInstances(const ObjectInstancesMsg& msg);

 private:
  // What a next-best-view request plans for: a model's scorer, the object's pose in the fixed
  // frame and the belief over its orientation (none: uniform), with notes saying where they came
  // from.
  struct Target {
    const ViewUtilityScorer* scorer = nullptr;
    Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
    std::optional<BinghamMixture> belief;
    Eigen::Vector4d map = Eigen::Vector4d(1, 0, 0, 0);
    std::vector<std::string> notes;
    std::string belief_note;  // where `belief` came from: noted unless the request brings one
  };
  // The one object: its tf frame (else the origin, noted) and the latest estimate.
  Target singleObjectTarget(const InformativenessServerRosParameters& settings) const;
  // The instance the request names: its model's scorer, its pose and belief from ~instances.
  Target instanceTarget(const std::string& wanted) const;
  // The instance `wanted` names (see chooseInstance); throws vdc::Error without a library.
  ObjectInstanceMsg chosenInstance(const std::string& wanted) const;
  // The library's scorer for the instance's model; throws vdc::Error if it is not loaded.
  const ViewUtilityScorer& libraryScorer(const ObjectInstanceMsg& instance) const;

  // Throw vdc::Error for an invalid request; fill the response on success.
  void answerHeatmap(const view_direction_classification::GetHeatmap::Request& request,
                     view_direction_classification::GetHeatmap::Response& response) const;
  void answerNextBestView(const view_direction_classification::GetNextBestView::Request& request,
                          view_direction_classification::GetNextBestView::Response& response);
  // Identity for an empty frame or `fixed_frame`, else lookup_.
  Eigen::Isometry3d lookupFixedFrom(const std::string& frame, const std::string& fixed_frame,
                                    const char* what) const;

  std::shared_ptr<const ModelBundle> model_;  // null without ~model
  std::unique_ptr<ViewUtilityScorer> scorer_;
  std::map<std::string, std::unique_ptr<ViewUtilityScorer>> library_;  // by model name
  FrameLookup lookup_;

  mutable std::mutex parameters_mutex_;  // reconfigure against the requests reading them
  InformativenessServerRosParameters parameters_;

  // The estimate callback and the services (see InformativenessServerRos).
  mutable std::mutex belief_mutex_;
  std::optional<BinghamMixture> latest_belief_;
  Eigen::Vector4d latest_map_ = Eigen::Vector4d(1, 0, 0, 0);
  LatestInstances instances_;  // guarded by its own lock
};

}  // namespace vdc
