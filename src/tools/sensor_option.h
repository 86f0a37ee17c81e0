#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "view_direction_classification/geometry/sensor_model.h"

namespace vdc::tools {

// `--sensor NAME` of `vdc train`, `vdc evaluate` and `vdc evaluate-scenes`: the depth camera the
// renders imitate (geometry/sensor_model.h), or `none` for exact depths (as --no-noise).
constexpr const char* kNoSensor = "none";

struct SensorSelection {
  bool noise = true;
  DepthSensor sensor = DepthSensor::kKinectGaussian;
};

// Declares --sensor on `command`, bound to *name (which must outlive the parse); an unknown
// name is a usage error.
CLI::Option* addSensorOption(CLI::App& command, std::string* name);

// What --sensor `name` (empty: not given, the default kinect_gaussian) and --no-noise ask for.
// Throws vdc::Error when --no-noise is given with a sensor other than none.
SensorSelection selectSensor(const std::string& name, bool no_noise);

// The selection's name as --sensor takes it: "none" without noise.
std::string selectionName(bool noise, DepthSensor sensor);

}  // namespace vdc::tools
