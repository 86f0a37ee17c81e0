#include "half_turn_axes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vdc {

namespace {

struct HalfTurnFrame {
  Eigen::Vector3d centre;  // on the main axis, in the middle of the samples' extent along it
  Eigen::Vector3d e1, e2;  // orthonormal, orthogonal to the main axis; azimuth 0 is e1
};

HalfTurnFrame halfTurnFrame(const std::vector<Eigen::Vector3d>& points,
                            const Eigen::ParametrizedLine<double, 3>& main_axis,
                            const Eigen::Vector3d& first_guess) {
  const Eigen::Vector3d d = main_axis.direction().normalized();
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const Eigen::Vector3d& p : points) {
    const double along = d.dot(p - main_axis.origin());
    low = std::min(low, along);
    high = std::max(high, along);
  }
  HalfTurnFrame frame;
  frame.centre = main_axis.origin() + 0.5 * (low + high) * d;
  Eigen::Vector3d e1 = first_guess - d.dot(first_guess) * d;
  if (e1.norm() < 1e-6) e1 = d.unitOrthogonal();
  frame.e1 = e1.normalized();
  frame.e2 = d.cross(frame.e1);
  return frame;
}

Eigen::Vector3d azimuthDirection(const HalfTurnFrame& frame, double azimuth) {
  return std::cos(azimuth) * frame.e1 + std::sin(azimuth) * frame.e2;
}

// Mean squared distance, truncated, of the points turned by half a turn about (centre, u) to
// the surface.
double halfTurnMisfit(const std::vector<Eigen::Vector3d>& points, const NearestPoints& nearest,
                      const Eigen::Vector3d& centre, const Eigen::Vector3d& u, double truncation) {
  const Eigen::Matrix3d turn = 2.0 * u * u.transpose() - Eigen::Matrix3d::Identity();
  std::vector<Eigen::Vector3f> turned;
  turned.reserve(points.size());
  for (const Eigen::Vector3d& p : points)
    turned.push_back((centre + turn * (p - centre)).cast<float>());
  std::vector<int> indices;
  std::vector<float> squared;
  nearest.search(turned, &indices, &squared, truncation);
  const double cap = truncation * truncation;
  double sum = 0.0;
  for (const float s : squared) sum += std::isfinite(s) ? std::min<double>(s, cap) : cap;
  return sum / static_cast<double>(std::max<std::size_t>(1, turned.size()));
}

// The azimuth with the least misfit among `start` and those in [from, to] (steps of `step`);
// of equals, `start` and then the earlier.
double bestAzimuth(const std::vector<Eigen::Vector3d>& points, const NearestPoints& nearest,
                   const HalfTurnFrame& frame, double truncation, double start, double from,
                   double to, double step) {
  const auto misfit = [&](double azimuth) {
    return halfTurnMisfit(points, nearest, frame.centre, azimuthDirection(frame, azimuth),
                          truncation);
  };
  double best = start;
  double best_misfit = misfit(start);
  const int steps = static_cast<int>(std::lround((to - from) / step));
  for (int k = 0; k <= steps; ++k) {
    const double azimuth = from + k * step;
    const double value = misfit(azimuth);
    // A relative margin keeps equals (a surface of revolution) where they were whatever rounding
    // says.
    if (value < best_misfit * (1.0 - 1e-3)) {
      best_misfit = value;
      best = azimuth;
    }
  }
  return best;
}

}  // namespace

std::vector<Eigen::ParametrizedLine<double, 3>> halfTurnAxes(
    const pcl::PointCloud<pcl::PointNormal>& samples, const NearestPoints& nearest,
    const Eigen::ParametrizedLine<double, 3>& main_axis, const Eigen::Vector3d& first_guess,
    int max_samples) {
  const std::size_t stride =
      std::max<std::size_t>(1, samples.size() / static_cast<std::size_t>(std::max(1, max_samples)));
  std::vector<Eigen::Vector3d> points;
  Eigen::AlignedBox3d box;
  for (std::size_t i = 0; i < samples.size(); i += stride) {
    points.push_back(samples.points[i].getVector3fMap().cast<double>());
    box.extend(points.back());
  }
  const HalfTurnFrame frame = halfTurnFrame(points, main_axis, first_guess);
  const double truncation = std::max(1e-3, 0.1 * box.diagonal().norm());
  const double coarse_step = 3.0 * M_PI / 180.0;
  const double fine_step = 0.25 * M_PI / 180.0;
  // Half a turn about u and about -u are the same: azimuths in [0, 180) degrees.
  const double coarse = bestAzimuth(points, nearest, frame, truncation, 0.0, coarse_step,
                                    M_PI - coarse_step, coarse_step);
  const double azimuth = bestAzimuth(points, nearest, frame, truncation, coarse,
                                     coarse - coarse_step, coarse + coarse_step, fine_step);
  const Eigen::Vector3d first = azimuthDirection(frame, azimuth);
  const Eigen::Vector3d second = main_axis.direction().normalized().cross(first);
  return {Eigen::ParametrizedLine<double, 3>(frame.centre, first),
          Eigen::ParametrizedLine<double, 3>(frame.centre, second)};
}

}  // namespace vdc
