#pragma once

#include <string>
#include <vector>

namespace vdc {

// Which depth camera the renderer imitates (doc/method.md, "Depth sensor models").
//   kKinectGaussian  today's default: Gaussian axial noise only (depth_noise.h), bit for bit.
//   kStructuredLight Kinect v1 / Xtion / Carmine: quantised disparity, edge dropouts, shadows.
//   kActiveStereo    RealSense D4xx: subpixel disparity noise, edge dropouts, narrow shadows.
//   kTimeOfFlight    Kinect v2 / Azure Kinect: small axial noise, flying pixels at depth edges.
enum class DepthSensor { kKinectGaussian, kStructuredLight, kActiveStereo, kTimeOfFlight };

// The parameters of one model; sensorModel() gives each kind's published figures (the numbers
// and their sources are in sensor_model.cpp). A model whose fields are zero does nothing: each
// effect is switched on by its own parameter, so a test can isolate one.
struct SensorModel {
  DepthSensor kind = DepthSensor::kKinectGaussian;
  // Triangulating sensors measure disparity d = focal_px * baseline / z [px]. focal_px is the
  // sensor's own (not the render camera's): its disparity grid is a property of the device.
  double disparity_focal_px = 0.0;
  double baseline = 0.0;            // [m]; the projector / second imager sits at +x (optical)
  double disparity_sigma_px = 0.0;  // Gaussian disparity noise [px]: axial error grows with z^2
  double disparity_step_px = 0.0;   // disparity quantisation [px]; 0: none
  // Axial Gaussian noise sigma(z) = axial_sigma_m + axial_sigma_per_m2 * z^2 [m] (time of flight).
  double axial_sigma_m = 0.0, axial_sigma_per_m2 = 0.0;
  // Pixels the projector (second imager) at (baseline, 0, 0) cannot see are lost.
  bool shadows = false;
  // Depth edges: a pixel lies on one when a pixel within edge_band_px (Chebyshev) has no depth or
  // a depth differing by more than edge_jump_ratio * z.
  double edge_jump_ratio = 0.02;
  int edge_band_px = 1;
  double edge_dropout = 0.0;  // probability that an edge pixel is lost
  // Probability that an edge pixel mixes foreground and background (time of flight): its depth
  // is drawn uniformly between the nearest and farthest depth of its band, along its own ray. A
  // mixture with nothing (a silhouette against empty space) is too dim and is lost instead.
  double flying_pixel = 0.0;
};

// The model of a kind with its published parameters.
SensorModel sensorModel(DepthSensor kind);

// "kinect_gaussian", "structured_light", "active_stereo", "tof".
const char* sensorName(DepthSensor kind);
// The kind of a name above; throws vdc::Error listing the names for anything else.
DepthSensor parseDepthSensor(const std::string& name);
// The names above, joined with '|' (for usage texts).
std::string depthSensorNames();

// Throws vdc::Error naming the first bad parameter (negative or non-finite values, a probability
// outside [0, 1], a disparity model without a focal length or baseline, shadows without a
// baseline).
void checkSensorModel(const SensorModel& model);

}  // namespace vdc
