#include "simulated_depth_camera_ros_parameters.h"

#include <algorithm>
#include <cmath>

namespace vdc {
namespace {

ParameterRule<std::vector<double>> nonZeroDirection() {
  const ParameterRule<std::vector<double>> three = finiteNumbers(3, "[x, y, z]");
  return {three.words + " in the object frame, not all zero",
          [three](const std::vector<double>& v) {
            return three.accepts(v) &&
                   std::any_of(v.begin(), v.end(), [](double c) { return c != 0.0; });
          }};
}

ParameterTable<SimulatedDepthCameraRosParameters> makeTable() {
  using P = SimulatedDepthCameraRosParameters;
  ParameterTable<P> table;
  // ADDING A PARAMETER: a field in SimulatedDepthCameraRosParameters, one line below and its
  // entry in config/simulated_depth_camera.yaml.
  table.add("mesh", &P::mesh, nonEmptyString())
      .add("fixed_frame", &P::fixed_frame, frameName())
      .add("camera_frame", &P::camera_frame, frameName())
      .add("object_frame", &P::object_frame, frameName())
      .add("publish_object_tf", &P::publish_object_tf, anyBoolean())
      .add("object_pose", &P::object_pose,
           finiteNumbers(6, "[x, y, z, roll, pitch, yaw] in the fixed frame"))
      .add("rate", &P::rate, numberAbove(0.0))
      .add("view_direction", &P::view_direction, nonZeroDirection())
      .add("distance", &P::distance, numberAbove(0.0))
      .add("roll", &P::roll, finiteNumber())
      .add("noise", &P::noise, anyBoolean())
      .add("seed", &P::seed, integerAtLeast(0))
      .add("visibility_radius", &P::visibility_radius, numberAtLeast(0.0, "0: no crop"))
      .add("visibility_anchors", &P::visibility_anchors,
           finiteGroupsOf(3, "(x, y, z triples in the object frame)"));
  return table;
}

}  // namespace

const ParameterTable<SimulatedDepthCameraRosParameters>& simulatedDepthCameraParameterTable() {
  static const ParameterTable<SimulatedDepthCameraRosParameters> table = makeTable();
  return table;
}

SimulatedDepthCameraRosParameters readSimulatedDepthCameraRosParameters(
    const ros::NodeHandle& node) {
  SimulatedDepthCameraRosParameters p;
  const ParameterReader reader(node);
  simulatedDepthCameraParameterTable().read(reader, p);
  reader.warnAboutUnknownParameters(simulatedDepthCameraParameterTable().names());
  // tf refuses a transform whose parent is its child.
  if (p.camera_frame == p.fixed_frame) {
    throw parameterError("camera_frame", "different from ~fixed_frame",
                         describeParameterValue(p.camera_frame));
  }
  if (p.publish_object_tf &&
      (p.object_frame == p.fixed_frame || p.object_frame == p.camera_frame)) {
    throw parameterError("object_frame", "different from ~fixed_frame and ~camera_frame",
                         describeParameterValue(p.object_frame));
  }
  return p;
}

}  // namespace vdc
