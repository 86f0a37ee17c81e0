#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

namespace vdc::test {

// Random unit quaternions (w, x, y, z), uniform on S^3: four standard normals, normalised (the
// normal distribution is rotation-invariant). Every test draws its random orientations here.
// libstdc++'s std::normal_distribution makes its normals in pairs and keeps the second for the
// next call, so draws from one distribution differ from draws with a fresh one each time; both
// forms are offered, and which one a test uses is part of what its fixed seed means.

// `count` quaternions from one normal distribution.
template <typename Generator>
std::vector<Eigen::Vector4d> randomUnitQuaternions(int count, Generator& generator) {
  std::normal_distribution<double> normal;
  std::vector<Eigen::Vector4d> quaternions(static_cast<std::size_t>(count));
  for (Eigen::Vector4d& q : quaternions) {
    q = Eigen::Vector4d(normal(generator), normal(generator), normal(generator), normal(generator))
            .normalized();
  }
  return quaternions;
}

// The same from a std::mt19937_64 seeded with `seed`.
inline std::vector<Eigen::Vector4d> randomUnitQuaternionsFromSeed(int count, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  return randomUnitQuaternions(count, generator);
}

// One quaternion from a fresh normal distribution, for tests that interleave orientations with
// other draws from the same generator.
template <typename Generator>
Eigen::Vector4d randomUnitQuaternion(Generator& generator) {
  return randomUnitQuaternions(1, generator).front();
}

}  // namespace vdc::test
