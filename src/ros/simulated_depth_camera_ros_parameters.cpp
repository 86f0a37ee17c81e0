#include "simulated_depth_camera_ros_parameters.h"

#include <algorithm>
#include <cmath>
#include <sstream>

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

ParameterRule<std::vector<double>> tableSize() {
  const ParameterRule<std::vector<double>> two = finiteNumbers(2, "[x, y] in metres");
  return {two.words + ", both positive, or [0, 0] for no table",
          [two](const std::vector<double>& v) {
            return two.accepts(v) && ((v[0] > 0.0 && v[1] > 0.0) || (v[0] == 0.0 && v[1] == 0.0));
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
           finiteGroupsOf(3, "(x, y, z triples in the object frame)"))
      .add("table_size", &P::table_size, tableSize())
      .add("distractors", &P::distractors, anyString())
      .add("distractor_poses", &P::distractor_poses,
           finiteGroupsOf(6, "(x, y, z, roll, pitch, yaw per distractor, in the fixed frame)"));
  return table;
}

}  // namespace

std::vector<std::string> distractorDescriptions(const std::string& distractors) {
  std::vector<std::string> descriptions;
  std::stringstream stream(distractors);
  for (std::string item; std::getline(stream, item, ';');) {
    const auto first = item.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    descriptions.push_back(item.substr(first, item.find_last_not_of(" \t") - first + 1));
  }
  return descriptions;
}

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
  const std::size_t distractors = distractorDescriptions(p.distractors).size();
  if (p.distractor_poses.size() != 6 * distractors) {
    throw parameterError("distractor_poses",
                         "one x, y, z, roll, pitch, yaw pose per distractor (" +
                             std::to_string(distractors) + " in ~distractors)",
                         describeParameterValue(p.distractor_poses));
  }
  return p;
}

}  // namespace vdc
