#include "view_direction_classification/bop/bop_metrics.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

BopPose compose(const BopPose& a, const BopPose& b) {  // a after b
  return {a.R * b.R, a.R * b.t + a.t};
}

Eigen::Vector3d apply(const BopPose& pose, const Eigen::Vector3d& x) { return pose.R * x + pose.t; }

// A rotation by `angle` about the axis through `offset`: x -> R (x - offset) + offset.
BopPose rotationAbout(const BopContinuousSymmetry& symmetry, double angle) {
  BopPose pose;
  pose.R = Eigen::AngleAxisd(angle, symmetry.axis.normalized()).toRotationMatrix();
  pose.t = symmetry.offset - pose.R * symmetry.offset;
  return pose;
}

std::vector<BopPose> discretisedContinuous(const BopModelInfo& info, double max_step) {
  std::vector<BopPose> rotations;
  if (info.symmetries_continuous.empty()) return rotations;
  // Half a turn in steps of max_step, i.e. a full turn in 2 pi / (pi / max_step) radians.
  const int steps = static_cast<int>(std::ceil(M_PI / max_step));
  const double step = 2.0 * M_PI / steps;
  for (const BopContinuousSymmetry& symmetry : info.symmetries_continuous) {
    for (int i = 0; i < steps; ++i) rotations.push_back(rotationAbout(symmetry, i * step));
  }
  return rotations;
}

// The largest distance between two point lists of the same length, after `project`.
template <typename Project>
double maximumDistance(const BopPose& a, const BopPose& b,
                       const std::vector<Eigen::Vector3d>& vertices, const Project& project) {
  double largest = 0.0;
  for (const Eigen::Vector3d& x : vertices) {
    largest = std::max(largest, (project(apply(a, x)) - project(apply(b, x))).norm());
  }
  return largest;
}

template <typename Project>
double minimumOverSymmetries(const BopPose& estimate, const BopPose& truth,
                             const std::vector<Eigen::Vector3d>& vertices,
                             const std::vector<BopPose>& symmetries, const Project& project) {
  if (vertices.empty()) return 0.0;
  if (symmetries.empty()) return maximumDistance(estimate, truth, vertices, project);
  double best = std::numeric_limits<double>::infinity();
  for (const BopPose& symmetry : symmetries) {
    best = std::min(best, maximumDistance(estimate, compose(truth, symmetry), vertices, project));
  }
  return best;
}

std::vector<double> steps(double first, double step, int count, double scale) {
  std::vector<double> values;
  for (int i = 0; i < count; ++i) values.push_back((first + i * step) * scale);
  return values;
}

}  // namespace

std::vector<BopPose> bopSymmetryTransformations(const BopModelInfo& info, double max_step) {
  if (!(max_step > 0.0)) throw Error("symmetry discretisation step must be > 0");
  std::vector<BopPose> discrete{BopPose{}};
  discrete.insert(discrete.end(), info.symmetries_discrete.begin(), info.symmetries_discrete.end());
  const std::vector<BopPose> continuous = discretisedContinuous(info, max_step);
  if (continuous.empty()) return discrete;
  std::vector<BopPose> combined;
  for (const BopPose& d : discrete) {
    for (const BopPose& c : continuous) combined.push_back(compose(c, d));
  }
  return combined;
}

double maximumSymmetryAwareSurfaceDistance(const BopPose& estimate, const BopPose& truth,
                                           const std::vector<Eigen::Vector3d>& vertices,
                                           const std::vector<BopPose>& symmetries) {
  return minimumOverSymmetries(estimate, truth, vertices, symmetries,
                               [](const Eigen::Vector3d& x) { return x; });
}

double maximumSymmetryAwareProjectionDistance(const BopPose& estimate, const BopPose& truth,
                                              const std::vector<Eigen::Vector3d>& vertices,
                                              const std::vector<BopPose>& symmetries,
                                              const CameraIntrinsics& camera) {
  const auto project = [&camera](const Eigen::Vector3d& x) {
    return Eigen::Vector2d(camera.fx * x.x() / x.z() + camera.cx,
                           camera.fy * x.y() / x.z() + camera.cy);
  };
  return minimumOverSymmetries(estimate, truth, vertices, symmetries, project);
}

std::vector<double> mssdThresholds(double diameter) { return steps(0.05, 0.05, 10, diameter); }

std::vector<double> mspdThresholds(int image_width) {
  return steps(5.0, 5.0, 10, image_width / 640.0);
}

double averageRecall(const std::vector<double>& errors, int targets,
                     const std::vector<double>& thresholds) {
  if (targets <= 0 || thresholds.empty()) return 0.0;
  double sum = 0.0;
  for (const double threshold : thresholds) {
    const auto correct = std::count_if(errors.begin(), errors.end(),
                                       [threshold](double e) { return e <= threshold; });
    sum += std::min(1.0, static_cast<double>(correct) / targets);
  }
  return sum / static_cast<double>(thresholds.size());
}

}  // namespace vdc
