#pragma once

#include <Eigen/Dense>

#include <random>

#include "view_direction_classification/bingham/bingham.h"

namespace vdc {

// A Bingham distribution with concentrations z and random orthonormal axes (fixed by the seed),
// so tests do not depend on axis-aligned special cases.
inline BinghamDistribution makeDistribution(const Eigen::Vector3d& z, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::Matrix4d m;
  for (int i = 0; i < 16; ++i) m(i) = normal(generator);
  const Eigen::Matrix4d basis = Eigen::HouseholderQR<Eigen::Matrix4d>(m).householderQ();
  return BinghamDistribution(z, basis.leftCols<3>());
}

}  // namespace vdc
