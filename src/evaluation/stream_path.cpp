#include "view_direction_classification/evaluation/stream_path.h"

#include <cmath>
#include <random>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

constexpr double kDegree = M_PI / 180.0;
// A view's optical axis may miss the object origin by this much (relative to its distance).
constexpr double kLookAtTolerance = 1e-6;

// The camera's pose about the object: R_OC and its distance to the origin along the optical axis.
struct ArcEnd {
  Eigen::Quaterniond object_from_camera;
  double distance;
};

ArcEnd arcEndOf(const Eigen::Isometry3d& camera_from_object, int view) {
  // The object origin in the camera frame must lie on the optical axis (+z).
  const Eigen::Vector3d origin = camera_from_object.translation();
  const double distance = origin.norm();
  if (!(distance > 0.0) || !camera_from_object.matrix().allFinite() ||
      origin.head<2>().norm() > kLookAtTolerance * distance || origin.z() <= 0.0) {
    throw Error("stream path: view " + std::to_string(view) +
                " does not look at the object origin");
  }
  return {Eigen::Quaterniond(camera_from_object.linear().transpose()).normalized(), distance};
}

Eigen::Isometry3d cameraFromObjectAt(const ArcEnd& end) {
  Eigen::Isometry3d camera_from_object = Eigen::Isometry3d::Identity();
  camera_from_object.linear() = end.object_from_camera.toRotationMatrix().transpose();
  camera_from_object.translation() = Eigen::Vector3d(0.0, 0.0, end.distance);
  return camera_from_object;
}

}  // namespace

void checkStreamPathSettings(const StreamPathSettings& s) {
  if (!(s.rate_hz > 0.0) || !std::isfinite(s.rate_hz)) {
    throw Error("the stream rate must be positive and finite, got " + std::to_string(s.rate_hz) +
                " Hz");
  }
  if (!(s.min_speed_deg_s > 0.0) || !(s.max_speed_deg_s >= s.min_speed_deg_s) ||
      !std::isfinite(s.max_speed_deg_s)) {
    throw Error("the camera's turn rates must satisfy 0 < min <= max, got " +
                std::to_string(s.min_speed_deg_s) + " and " + std::to_string(s.max_speed_deg_s) +
                " deg/s");
  }
  if (!(s.dwell_s >= 0.0) || !std::isfinite(s.dwell_s)) {
    throw Error("the dwell time must be >= 0 and finite, got " + std::to_string(s.dwell_s) + " s");
  }
}

std::vector<StreamFrame> streamPath(const std::vector<Eigen::Isometry3d>& views,
                                    const StreamPathSettings& settings, std::uint32_t seed) {
  checkStreamPathSettings(settings);
  if (views.empty()) throw Error("stream path: no views");
  std::vector<ArcEnd> ends;
  for (std::size_t v = 0; v < views.size(); ++v) {
    ends.push_back(arcEndOf(views[v], static_cast<int>(v)));
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> speed(settings.min_speed_deg_s * kDegree,
                                               settings.max_speed_deg_s * kDegree);
  // The schedule: [dwell at 0][arc 0 -> 1][dwell at 1]...[dwell at n-1], as segment end times.
  std::vector<double> arc_start(views.size(), 0.0), arc_duration(views.size(), 0.0);
  double t = settings.dwell_s;
  for (std::size_t v = 0; v + 1 < views.size(); ++v) {
    arc_start[v] = t;
    const double angle = ends[v].object_from_camera.angularDistance(ends[v + 1].object_from_camera);
    arc_duration[v] = angle / speed(rng);
    t += arc_duration[v] + settings.dwell_s;
  }
  const double total = t;

  std::vector<StreamFrame> frames;
  const double step = 1.0 / settings.rate_hz;
  std::size_t v = 0;
  for (long k = 0;; ++k) {
    const double time = static_cast<double>(k) * step;
    if (time > total + 1e-12) break;
    // Advance to the segment holding `time`: view v's dwell ends where its arc starts.
    while (v + 1 < views.size() && time >= arc_start[v] + arc_duration[v]) ++v;
    StreamFrame frame;
    frame.time = time;
    frame.view = static_cast<int>(v);
    if (v + 1 < views.size() && time > arc_start[v]) {
      const double s = arc_duration[v] > 0.0 ? (time - arc_start[v]) / arc_duration[v] : 1.0;
      const ArcEnd between{ends[v].object_from_camera.slerp(s, ends[v + 1].object_from_camera),
                           (1.0 - s) * ends[v].distance + s * ends[v + 1].distance};
      frame.camera_from_object = cameraFromObjectAt(between);
    } else {
      frame.dwelling = true;
      frame.camera_from_object = cameraFromObjectAt(ends[v]);
    }
    frames.push_back(frame);
  }
  return frames;
}

}  // namespace vdc
