// libFuzzer target: the informativeness server's request handling without ROS transport
// (InformativenessServerRequests, which the node's service servers and estimate subscriber call):
// up to four GetHeatmap / GetNextBestView requests, estimates and ~instances messages built from
// the bytes, on a real model bundle, served alone or also as a library of two names (instances
// of "cube", of "other" which is not loaded, or of any name; requests naming one of them,
// "most_uncertain" or anything). tf is replaced by fixed transforms for the frames "object" and
// "camera" (every other frame is unknown, as tf would say). Every request must be answered: success
// with a response of the promised shape (every candidate ranked once, best first, finite utilities;
// a score per surface point), or failure with a message. An invalid estimate must throw vdc::Error.
//
// The model: $VDC_FUZZ_MODEL, else the model bundle seed of the model_bundle target
// (fuzz/corpus/model_bundle/cube_tiny.h5, a real model trained small so each input runs fast:
// `vdc train --quick --views 4 --clouds-per-view 1 --clusters 1` on a 4 cm cube, 547 surface
// points).
//
// Also the object memory's ~query_instances answers (instance_query.h, the orientation_estimator's;
// pure message handling, so it shares this target): requests of any model name and id against the
// last fuzzed ~instances, over the library names "cube" and "other". Every request must be answered
// with a message, only instances that match it, in id order.

#include <fuzzer/FuzzedDataProvider.h>
#include <ros/time.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "../src/ros/informativeness_server_requests.h"
#include "../src/ros/instance_query.h"
#include "fuzzed_messages.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace {

using vdc::fuzz::fuzzedDouble;
using view_direction_classification::GetHeatmap;
using view_direction_classification::GetNextBestView;
using view_direction_classification::QueryInstances;

std::shared_ptr<const vdc::ModelBundle> model() {
  static const auto bundle = [] {
    ros::Time::init();  // the responses' stamps, without a node
    const char* path = std::getenv("VDC_FUZZ_MODEL");
    return std::make_shared<const vdc::ModelBundle>(vdc::loadModelBundle(
        path ? path : VDC_SOURCE_DIR "/fuzz/corpus/model_bundle/cube_tiny.h5"));
  }();
  return bundle;
}

// What tf would answer for a world with the object and one camera in it.
Eigen::Isometry3d lookupFixedFrom(const std::string& frame, const char* what) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (frame == "object") {
    pose.translate(Eigen::Vector3d(0.05, -0.02, 0.1));
    pose.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  } else if (frame == "camera") {
    pose.translate(Eigen::Vector3d(0.4, 0.3, 0.5));
    pose.rotate(Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 1, 0).normalized()));
  } else {
    throw vdc::Error(std::string("The ") + what + " are in frame '" + frame +
                     "', which tf cannot transform into the fixed frame.");
  }
  return pose;
}

std::string pickString(FuzzedDataProvider& data, const std::array<const char*, 3>& known) {
  const std::size_t pick = data.ConsumeIntegralInRange<std::size_t>(0, known.size());
  return pick < known.size() ? known[pick] : data.ConsumeRandomLengthString(24);
}

double coordinate(FuzzedDataProvider& data) {
  return data.ConsumeBool() ? data.ConsumeFloatingPointInRange(-2.0, 2.0) : fuzzedDouble(data);
}

std::string instanceName(FuzzedDataProvider& data) {
  return pickString(data, {"", "cube_1", "most_uncertain"});
}

GetHeatmap::Request heatmapRequest(FuzzedDataProvider& data, int views) {
  GetHeatmap::Request request;
  request.mode = data.ConsumeBool() ? data.ConsumeIntegralInRange<std::uint8_t>(0, 3)
                                    : data.ConsumeIntegral<std::uint8_t>();
  request.view_index = data.ConsumeBool() ? data.ConsumeIntegralInRange(-1, views)
                                          : data.ConsumeIntegral<std::int32_t>();
  request.direction.x = coordinate(data);
  request.direction.y = coordinate(data);
  request.direction.z = coordinate(data);
  request.scaling = pickString(data, {"", "median", "max"});
  request.instance = instanceName(data);
  return request;
}

// An ~instances message: a few instances of the loaded model, of one the server lacks, or of
// any name, with fuzzed poses, beliefs, cones and states; now and then in another frame.
view_direction_classification::ObjectInstances instancesMessage(FuzzedDataProvider& data) {
  view_direction_classification::ObjectInstances message;
  message.header.frame_id = data.ConsumeBool() ? "world" : vdc::fuzz::fuzzedFrame(data);
  const int count = data.ConsumeIntegralInRange(0, 4);
  for (int i = 0; i < count; ++i) {
    view_direction_classification::ObjectInstance instance;
    instance.id = data.ConsumeIntegral<std::uint32_t>();
    instance.model = pickString(data, {"cube", "other", ""});
    instance.name = pickString(data, {"cube_1", "cube_2", "other_1"});
    instance.identity_probability = fuzzedDouble(data);
    instance.pose.pose.position.x = coordinate(data);
    instance.pose.pose.position.y = coordinate(data);
    instance.pose.pose.position.z = coordinate(data);
    instance.pose.pose.orientation = vdc::fuzz::fuzzedQuaternionMsg(data);
    instance.belief = vdc::fuzz::fuzzedBinghamMixtureMsg(data);
    instance.cone90_deg =
        data.ConsumeBool() ? data.ConsumeFloatingPointInRange(0.0, 180.0) : fuzzedDouble(data);
    // Any value: PRESENT, GONE, or one no estimator sends.
    instance.state = data.ConsumeIntegral<std::uint8_t>();
    message.instances.push_back(instance);
  }
  return message;
}

GetNextBestView::Request nextBestViewRequest(FuzzedDataProvider& data) {
  GetNextBestView::Request request;
  request.instance = instanceName(data);
  request.candidates.header.frame_id = vdc::fuzz::fuzzedFrame(data);
  const int candidates = data.ConsumeIntegralInRange(0, 12);
  for (int i = 0; i < candidates; ++i) {
    geometry_msgs::Pose pose;
    pose.position.x = coordinate(data);
    pose.position.y = coordinate(data);
    pose.position.z = coordinate(data);
    pose.orientation = vdc::fuzz::fuzzedQuaternionMsg(data);
    request.candidates.poses.push_back(pose);
  }
  request.sample_count = data.ConsumeBool() ? data.ConsumeIntegralInRange(-1, 64)
                                            : data.ConsumeIntegral<std::int32_t>();
  request.sample_distance =
      data.ConsumeBool() ? data.ConsumeFloatingPointInRange(0.0, 2.0) : fuzzedDouble(data);
  request.utility = pickString(data, {"", "informativeness", "information_gain"});
  request.use_belief = data.ConsumeBool();
  if (request.use_belief) request.belief = vdc::fuzz::fuzzedBinghamMixtureMsg(data);
  request.use_occluder = data.ConsumeBool();
  if (request.use_occluder) request.occluder = vdc::fuzz::fuzzedPointCloud2(data);
  return request;
}

QueryInstances::Request queryRequest(FuzzedDataProvider& data) {
  QueryInstances::Request request;
  request.model = pickString(data, {"", "cube", "other"});
  request.id = data.ConsumeBool() ? data.ConsumeIntegralInRange(-1, 4)
                                  : data.ConsumeIntegral<std::int32_t>();
  request.include_gone = data.ConsumeBool();
  return request;
}

void checkQuery(const QueryInstances::Request& request, const QueryInstances::Response& response) {
  if (response.message.empty()) std::abort();
  for (std::size_t i = 0; i < response.instances.size(); ++i) {
    const auto& instance = response.instances[i];
    if (!request.model.empty() && instance.model != request.model) std::abort();
    if (request.id != 0 && std::int64_t(instance.id) != request.id) std::abort();
    if (!request.include_gone && instance.state == instance.GONE) std::abort();
    if (i > 0 && instance.id < response.instances[i - 1].id) std::abort();
  }
}

void checkHeatmap(const GetHeatmap::Response& response, std::size_t surface_points) {
  if (!response.success) {
    if (response.message.empty()) std::abort();
    return;
  }
  if (response.scores.size() != surface_points ||
      std::size_t(response.cloud.width) * response.cloud.height != surface_points) {
    std::abort();
  }
  if (!(response.min <= response.median && response.median <= response.max)) std::abort();
}

void checkNextBestView(const GetNextBestView::Request& request,
                       const GetNextBestView::Response& response) {
  if (!response.success) {
    if (response.message.empty()) std::abort();
    return;
  }
  const std::size_t count = response.ranked.poses.size();
  if (count == 0 || response.utilities.size() != count ||
      response.candidate_indices.size() != count) {
    std::abort();
  }
  if (!request.candidates.poses.empty() && count != request.candidates.poses.size()) std::abort();
  std::vector<bool> seen(count, false);
  for (std::size_t i = 0; i < count; ++i) {
    const int index = response.candidate_indices[i];
    if (index < 0 || std::size_t(index) >= count || seen[index]) std::abort();
    seen[index] = true;
    if (!std::isfinite(response.utilities[i])) std::abort();
    if (i > 0 && response.utilities[i] > response.utilities[i - 1]) std::abort();
  }
  if (response.best_index != response.candidate_indices[0]) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  vdc::InformativenessServerRosParameters parameters;
  parameters.belief_samples_per_component = data.ConsumeIntegralInRange(0, 8);
  // A fresh server per input, so an input's outcome does not depend on the ones before it: the
  // one model alone, or with a library naming it "cube".
  vdc::ServedLibrary library;
  if (data.ConsumeBool()) library.emplace_back("cube", model());
  vdc::InformativenessServerRequests server(model(), parameters, lookupFixedFrom, library);
  const int views = server.scorer().viewCount();
  view_direction_classification::ObjectInstances remembered;  // what the queries ask
  for (int step = 0; step < 4 && data.remaining_bytes() > 0; ++step) {
    switch (data.ConsumeIntegralInRange(0, 4)) {
      case 0: {
        GetHeatmap::Response response;
        server.getHeatmap(heatmapRequest(data, views), response);
        checkHeatmap(response, server.model().surface_points.size());
        break;
      }
      case 1: {
        const GetNextBestView::Request request = nextBestViewRequest(data);
        GetNextBestView::Response response;
        server.nextBestView(request, response);
        checkNextBestView(request, response);
        break;
      }
      case 2:
        try {
          server.receiveEstimate(vdc::fuzz::fuzzedBinghamMixtureMsg(data));
        } catch (const vdc::Error&) {
          // ignored with a throttled warning by the node
        }
        break;
      case 3:
        remembered = instancesMessage(data);
        try {
          server.receiveInstances(remembered);
        } catch (const vdc::Error&) {
          // ignored with a throttled warning by the node
        }
        break;
      default: {
        const QueryInstances::Request request = queryRequest(data);
        QueryInstances::Response response;
        vdc::answerQuery(request, {"cube", "other"}, remembered.instances, response);
        checkQuery(request, response);
      }
    }
  }
  return 0;
}
