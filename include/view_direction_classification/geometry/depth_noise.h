#pragma once

namespace vdc {

// Axial noise of a Kinect-type structured-light sensor (Nguyen, Izadi, Lovell 2012): a depth z
// [m] is measured with Gaussian error of standard deviation sigma(z), along the pixel's ray.
// The lateral noise of that model (about a pixel) is below the FPFH support scale and left out.
struct DepthNoiseModel {
  bool enabled = true;
  double sigma(double z) const { return 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4); }
};

}  // namespace vdc
