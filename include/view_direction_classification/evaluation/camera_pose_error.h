#pragma once

#include <Eigen/Geometry>

#include <cstdint>

namespace vdc {

// The error of the camera pose a robot believes (its tf), against the true one the views are
// rendered from. Both parts act in the camera frame, where a hand-eye calibration error lives:
//   T_WC believed = T_WC true * B * N_v
// - B, the hand-eye bias: one per sequence, a rotation by exactly bias_deg about an axis uniform
//   on the sphere and a translation of exactly bias_mm in a direction uniform on the sphere.
// - N_v, the noise of view v: a rotation vector and a translation whose three components are
//   independent Gaussians with standard deviation noise_deg / sqrt(3) and noise_mm / sqrt(3), so
//   that the root mean square rotation angle is noise_deg and the RMS shift is noise_mm.
// A rotation about the camera moves the believed object by its distance times the angle (10 mm
// per degree at 0.6 m), on top of the translation.
struct CameraPoseError {
  double noise_deg = 0.0;  // RMS rotation angle per view [deg]
  double noise_mm = 0.0;   // RMS translation per view [mm]
  double bias_deg = 0.0;   // rotation angle of the constant hand-eye bias [deg]
  double bias_mm = 0.0;    // translation of the constant hand-eye bias [mm]

  // Any part non-zero: otherwise the believed pose is the true one, untouched.
  bool any() const {
    return noise_deg != 0.0 || noise_mm != 0.0 || bias_deg != 0.0 || bias_mm != 0.0;
  }
};

// Throws vdc::Error naming the first value that is negative, not finite, or beyond 180 degrees
// or 1000 mm.
void checkCameraPoseError(const CameraPoseError& error);

// B of `sequence`: deterministic in (seed, sequence), the same for every view of the sequence.
Eigen::Isometry3d handEyeBias(const CameraPoseError& error, std::uint32_t seed, int sequence);

// N_v of `view` in `sequence`: deterministic in (seed, sequence, view).
Eigen::Isometry3d cameraPoseNoise(const CameraPoseError& error, std::uint32_t seed, int sequence,
                                  int view);

// The camera pose the estimator is given for the true `world_from_camera`: exactly the true one
// when !error.any() (so the default evaluation is unchanged bit for bit).
Eigen::Isometry3d believedWorldFromCamera(const Eigen::Isometry3d& world_from_camera,
                                          const CameraPoseError& error, std::uint32_t seed,
                                          int sequence, int view);

}  // namespace vdc
