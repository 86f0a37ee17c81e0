#pragma once

#include "view_direction_classification/geometry/sensor_model.h"

namespace vdc {

// How the depth renderer corrupts its clouds. `enabled` false: exact depths. With the default
// sensor (DepthSensor::kKinectGaussian) the axial noise of a Kinect-type structured-light sensor
// (Nguyen, Izadi, Lovell 2012): a depth z [m] is measured with Gaussian error of standard
// deviation sigma(z), along the pixel's ray. The lateral noise of that model (about a pixel) is
// below the FPFH support scale and left out. The other sensors (sensor_model.h) replace it.
struct DepthNoiseModel {
  // Not explicit: DepthNoiseModel{false} and `= {false}` keep working as they did.
  DepthNoiseModel(bool enabled_ = true, SensorModel sensor_ = {})
      : enabled(enabled_), sensor(sensor_) {}

  bool enabled;
  SensorModel sensor;
  double sigma(double z) const { return 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4); }
};

}  // namespace vdc
