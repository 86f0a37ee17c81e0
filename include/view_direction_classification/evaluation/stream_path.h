#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace vdc {

// A continuous camera path through a sequence's views, sampled as a camera stream would be
// (issue 14's stream evaluation): the camera dwells at each view, then turns about the object to
// the next one at a constant rate drawn per arc, and a frame is taken every 1 / rate_hz seconds.
struct StreamPathSettings {
  double rate_hz = 30.0;  // frames per second, > 0
  // Each arc's turn rate [deg/s], uniform in [min, max] (0 < min <= max).
  double min_speed_deg_s = 10.0;
  double max_speed_deg_s = 30.0;
  double dwell_s = 2.0;  // [s] >= 0, at every view, the first included
};

// One frame of the path.
struct StreamFrame {
  double time = 0.0;  // [s] from the start, frame k at k / rate_hz
  Eigen::Isometry3d camera_from_object = Eigen::Isometry3d::Identity();  // T_CO
  int view = 0;           // the view the camera is at (dwelling) or last left (on an arc)
  bool dwelling = false;  // at view `view`, not moving
};

// Throws vdc::Error naming the first bad setting.
void checkStreamPathSettings(const StreamPathSettings& settings);

// The frames of the path through `views` (T_CO poses that look at the object origin, as
// makeEvaluationSequence's): dwell at view 0, arc to view 1, dwell, ... dwell at the last. An
// arc turns the camera's pose about the object origin: its orientation R_OC is interpolated
// (slerp) and its position is the interpolated distance back along the optical axis, so every
// frame looks at the origin. The arc's rate is the rotation angle of R_OC per second.
// Deterministic in (views, settings, seed). Throws vdc::Error for bad settings, no views or a
// view that does not look at the origin.
std::vector<StreamFrame> streamPath(const std::vector<Eigen::Isometry3d>& views,
                                    const StreamPathSettings& settings, std::uint32_t seed);

}  // namespace vdc
