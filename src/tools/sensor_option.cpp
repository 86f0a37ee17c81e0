#include "sensor_option.h"

#include "view_direction_classification/common/error.h"

namespace vdc::tools {

CLI::Option* addSensorOption(CLI::App& command, std::string* name) {
  return command
      .add_option("--sensor", *name,
                  "depth camera the renders imitate: " + depthSensorNames() + "|" + kNoSensor +
                      " (default kinect_gaussian: Gaussian axial noise; none: exact depths)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            if (text == kNoSensor) return "";
            try {
              parseDepthSensor(text);
            } catch (const Error& error) {
              return error.what();
            }
            return "";
          },
          "SENSOR"));
}

SensorSelection selectSensor(const std::string& name, bool no_noise) {
  SensorSelection selection;
  if (name.empty()) {
    selection.noise = !no_noise;
    return selection;
  }
  if (name == kNoSensor) {
    selection.noise = false;
    return selection;
  }
  if (no_noise) throw Error("--no-noise contradicts --sensor " + name + " (use --sensor none)");
  selection.sensor = parseDepthSensor(name);
  return selection;
}

std::string selectionName(bool noise, DepthSensor sensor) {
  return noise ? sensorName(sensor) : kNoSensor;
}

}  // namespace vdc::tools
