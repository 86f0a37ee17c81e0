#include "view_direction_classification/evaluation/camera_pose_error.h"

#include <cmath>
#include <random>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/number_text.h"

namespace vdc {
namespace {

// Tags that keep these generators independent of the evaluation's others for the same seed.
constexpr std::uint32_t kBiasStream = 0xb1a5u;
constexpr std::uint32_t kPoseNoiseStream = 0x905eu;
constexpr double kDegToRad = M_PI / 180.0;
constexpr double kMmToM = 1e-3;

// A robot's pose error, not a teleport: up to half a turn and a metre (beyond, the believed
// camera would not even look at the object).
constexpr double kMaxAngleDeg = 180.0;
constexpr double kMaxShiftMm = 1000.0;

void checkPart(double value, double largest, const std::string& name) {
  if (!std::isfinite(value) || value < 0.0 || value > largest) {
    throw Error("the camera pose error's " + name + " must be a number in [0, " +
                std::to_string(static_cast<int>(largest)) + "], got " + numberText(value));
  }
}

// A unit vector uniform on the sphere (a normalised Gaussian vector; a zero vector has
// probability zero, redrawn to be safe).
Eigen::Vector3d uniformDirection(std::mt19937* rng) {
  std::normal_distribution<double> gaussian;
  Eigen::Vector3d d;
  do {
    d = Eigen::Vector3d(gaussian(*rng), gaussian(*rng), gaussian(*rng));
  } while (d.norm() < 1e-9);
  return d.normalized();
}

Eigen::Vector3d gaussianVector(double sigma, std::mt19937* rng) {
  // Standard normals scaled: a distribution with sigma 0 would break its precondition.
  std::normal_distribution<double> gaussian;
  const double x = gaussian(*rng);
  const double y = gaussian(*rng);
  const double z = gaussian(*rng);
  return sigma * Eigen::Vector3d(x, y, z);
}

Eigen::Isometry3d poseOf(const Eigen::Vector3d& rotation_vector, const Eigen::Vector3d& shift) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const double angle = rotation_vector.norm();
  if (angle > 0.0) {
    pose.linear() = Eigen::AngleAxisd(angle, rotation_vector / angle).toRotationMatrix();
  }
  pose.translation() = shift;
  return pose;
}

}  // namespace

void checkCameraPoseError(const CameraPoseError& error) {
  checkPart(error.noise_deg, kMaxAngleDeg, "noise angle [deg]");
  checkPart(error.noise_mm, kMaxShiftMm, "noise shift [mm]");
  checkPart(error.bias_deg, kMaxAngleDeg, "hand-eye bias angle [deg]");
  checkPart(error.bias_mm, kMaxShiftMm, "hand-eye bias shift [mm]");
}

Eigen::Isometry3d handEyeBias(const CameraPoseError& error, std::uint32_t seed, int sequence) {
  std::seed_seq seeds{seed, kBiasStream, static_cast<std::uint32_t>(sequence)};
  std::mt19937 rng(seeds);
  // Both directions are drawn whatever the magnitudes, so that the rotation's axis does not
  // change when only the shift is switched on.
  const Eigen::Vector3d axis = uniformDirection(&rng);
  const Eigen::Vector3d direction = uniformDirection(&rng);
  return poseOf(error.bias_deg * kDegToRad * axis, error.bias_mm * kMmToM * direction);
}

Eigen::Isometry3d cameraPoseNoise(const CameraPoseError& error, std::uint32_t seed, int sequence,
                                  int view) {
  std::seed_seq seeds{seed, kPoseNoiseStream, static_cast<std::uint32_t>(sequence),
                      static_cast<std::uint32_t>(view)};
  std::mt19937 rng(seeds);
  const double per_axis = 1.0 / std::sqrt(3.0);
  const Eigen::Vector3d rotation = gaussianVector(error.noise_deg * kDegToRad * per_axis, &rng);
  const Eigen::Vector3d shift = gaussianVector(error.noise_mm * kMmToM * per_axis, &rng);
  return poseOf(rotation, shift);
}

Eigen::Isometry3d believedWorldFromCamera(const Eigen::Isometry3d& world_from_camera,
                                          const CameraPoseError& error, std::uint32_t seed,
                                          int sequence, int view) {
  if (!error.any()) return world_from_camera;
  return world_from_camera * handEyeBias(error, seed, sequence) *
         cameraPoseNoise(error, seed, sequence, view);
}

}  // namespace vdc
