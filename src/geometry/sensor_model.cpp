#include "view_direction_classification/geometry/sensor_model.h"

#include <array>
#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

struct NamedSensor {
  DepthSensor kind;
  const char* name;
};

constexpr std::array<NamedSensor, 4> kSensorNames = {{
    {DepthSensor::kKinectGaussian, "kinect_gaussian"},
    {DepthSensor::kStructuredLight, "structured_light"},
    {DepthSensor::kActiveStereo, "active_stereo"},
    {DepthSensor::kTimeOfFlight, "tof"},
}};

// Kinect v1 (PrimeSense): the IR camera's focal length is about 580 px at 640 x 480 and the
// projector sits 7.5 cm beside it (Khoshelham and Elberink 2012, Sensors 12(2)); the device
// reports disparity in 1/8 px (Konolige and Mihelich, "Technical description of Kinect
// calibration", ROS wiki). Its random error reaches about 4 cm at 5 m (Khoshelham and Elberink),
// i.e. sigma_d = 0.04 m * 580 * 0.075 / 25 = 0.07 px; at 1 m that is 1.6 mm, as Nguyen et al.
// (depth_noise.h) measured. Edge dropouts: one pixel either side of a depth edge, half of them
// lost, which puts the edge statistics of the renders near those of the Kinect-class PCL scan
// (doc/evaluation.md, "Depth sensor models").
SensorModel structuredLight() {
  SensorModel m;
  m.kind = DepthSensor::kStructuredLight;
  m.disparity_focal_px = 580.0;
  m.baseline = 0.075;
  m.disparity_sigma_px = 0.07;
  m.disparity_step_px = 1.0 / 8.0;
  m.shadows = true;
  m.edge_band_px = 1;
  m.edge_dropout = 0.5;
  return m;
}

// RealSense D435 at 848 x 480: focal length about 430 px (87 degree field of view), baseline
// 50 mm, subpixel RMS 0.08 px, so RMS depth error = z^2 * 0.08 / (430 * 0.05) (Grunnet-Jepsen et
// al., "Tuning depth cameras for best performance", Intel white paper 2018); 3.7 mm at 1 m. Its
// subpixel estimate is finer than that noise, so no disparity quantisation. The left-right check
// invalidates depth edges; the occlusion band behind an edge is where the right imager, 5 cm
// away, cannot see: narrower shadows than a Kinect's. Edge dropouts as the Kinect's.
SensorModel activeStereo() {
  SensorModel m;
  m.kind = DepthSensor::kActiveStereo;
  m.disparity_focal_px = 430.0;
  m.baseline = 0.050;
  m.disparity_sigma_px = 0.08;
  m.shadows = true;
  m.edge_band_px = 1;
  m.edge_dropout = 0.5;
  return m;
}

// Kinect v2: axial noise of 1.5-2 mm up to about 3 m facing a plane (Fankhauser et al. 2015,
// "Kinect v2 for mobile robot navigation: evaluation and modeling", ICAR), sigma(z) = 1.5 mm +
// 0.2 mm z^2. A pixel that straddles a depth edge receives light from both surfaces and reports a
// depth between them: flying pixels (Lachat et al. 2015, ISPRS Archives XL-5/W4), half of the
// pixels next to an edge here. No shadows: emitter and sensor are almost coaxial.
SensorModel timeOfFlight() {
  SensorModel m;
  m.kind = DepthSensor::kTimeOfFlight;
  m.axial_sigma_m = 0.0015;
  m.axial_sigma_per_m2 = 0.0002;
  m.edge_band_px = 1;
  m.flying_pixel = 0.5;
  return m;
}

void checkFiniteNonNegative(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0) {
    throw Error(std::string("sensor model: ") + name + " must be finite and >= 0, got " +
                std::to_string(value));
  }
}

void checkProbability(double value, const char* name) {
  if (!(value >= 0.0 && value <= 1.0)) {
    throw Error(std::string("sensor model: ") + name + " must be a probability in [0, 1], got " +
                std::to_string(value));
  }
}

}  // namespace

SensorModel sensorModel(DepthSensor kind) {
  switch (kind) {
    case DepthSensor::kStructuredLight:
      return structuredLight();
    case DepthSensor::kActiveStereo:
      return activeStereo();
    case DepthSensor::kTimeOfFlight:
      return timeOfFlight();
    case DepthSensor::kKinectGaussian:
      break;
  }
  return SensorModel{};
}

const char* sensorName(DepthSensor kind) {
  for (const NamedSensor& s : kSensorNames) {
    if (s.kind == kind) return s.name;
  }
  return "unknown";
}

std::string depthSensorNames() {
  std::string names;
  for (const NamedSensor& s : kSensorNames) {
    if (!names.empty()) names += '|';
    names += s.name;
  }
  return names;
}

DepthSensor parseDepthSensor(const std::string& name) {
  for (const NamedSensor& s : kSensorNames) {
    if (name == s.name) return s.kind;
  }
  throw Error("unknown depth sensor '" + name + "' (expected one of " + depthSensorNames() + ")");
}

void checkSensorModel(const SensorModel& m) {
  checkFiniteNonNegative(m.disparity_focal_px, "disparity_focal_px");
  checkFiniteNonNegative(m.baseline, "baseline");
  checkFiniteNonNegative(m.disparity_sigma_px, "disparity_sigma_px");
  checkFiniteNonNegative(m.disparity_step_px, "disparity_step_px");
  checkFiniteNonNegative(m.axial_sigma_m, "axial_sigma_m");
  checkFiniteNonNegative(m.axial_sigma_per_m2, "axial_sigma_per_m2");
  checkFiniteNonNegative(m.edge_jump_ratio, "edge_jump_ratio");
  checkProbability(m.edge_dropout, "edge_dropout");
  checkProbability(m.flying_pixel, "flying_pixel");
  if (m.edge_band_px < 0 || m.edge_band_px > 16) {
    throw Error("sensor model: edge_band_px must be in [0, 16], got " +
                std::to_string(m.edge_band_px));
  }
  const bool disparity = m.disparity_sigma_px > 0.0 || m.disparity_step_px > 0.0;
  if (disparity && !(m.disparity_focal_px > 0.0 && m.baseline > 0.0)) {
    throw Error(
        "sensor model: disparity noise or quantisation needs a positive disparity_focal_px and "
        "baseline");
  }
  if (m.shadows && !(m.baseline > 0.0)) {
    throw Error("sensor model: shadows need a positive baseline (the projector's offset)");
  }
}

}  // namespace vdc
