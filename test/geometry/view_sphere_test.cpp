#include "view_direction_classification/geometry/view_sphere.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

std::vector<double> nearestNeighbourAngles(const ViewSphere& sphere) {
  std::vector<double> angles;
  for (int m = 0; m < sphere.size(); ++m) {
    double closest = M_PI;
    for (int j = 0; j < sphere.size(); ++j) {
      if (j != m) closest = std::min(closest, angle(sphere.direction(m), sphere.direction(j)));
    }
    angles.push_back(closest);
  }
  return angles;
}

// Uniform directions on the sphere with a fixed seed.
std::vector<Eigen::Vector3d> uniformDirections(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < count; ++i) {
    out.push_back(Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized());
  }
  return out;
}

class ViewSphereCounts : public ::testing::TestWithParam<int> {};

TEST_P(ViewSphereCounts, DirectionsAreUnitDistinctAndNearUniform) {
  const ViewSphere sphere(GetParam());
  ASSERT_EQ(sphere.size(), GetParam());
  for (const auto& d : sphere.directions()) EXPECT_NEAR(d.norm(), 1.0, 1e-12);
  const std::vector<double> angles = nearestNeighbourAngles(sphere);
  const auto [low, high] = std::minmax_element(angles.begin(), angles.end());
  EXPECT_GT(*low, 0.0);
  // Spread of the nearest-neighbour angle: the icospheres stay within 20 %, the Fibonacci lattice
  // (its poles are its weakest spot) within 50 %.
  EXPECT_LT(
      *high / *low,
      GetParam() == 12 || GetParam() == 42 || GetParam() == 162 || GetParam() == 642 ? 1.2 : 1.5);
  double mean = 0;
  for (double a : angles) mean += a;
  EXPECT_NEAR(sphere.neighbourAngle(), mean / angles.size(), 1e-12);
  // Area per direction 4 pi / M; for a hexagonal packing the neighbour angle is about
  // sqrt(8 pi / (sqrt(3) M)).
  EXPECT_NEAR(sphere.neighbourAngle(), std::sqrt(8 * M_PI / (std::sqrt(3.0) * GetParam())),
              0.15 * std::sqrt(8 * M_PI / (std::sqrt(3.0) * GetParam())));
}

TEST_P(ViewSphereCounts, BoundingCapContainsTheWholeCell) {
  const ViewSphere sphere(GetParam());
  for (const auto& u : uniformDirections(20000, 3)) {
    const int m = sphere.nearest(u);
    EXPECT_LE(angle(u, sphere.direction(m)), sphere.cellRadius(m)) << "cell " << m;
  }
}

TEST_P(ViewSphereCounts, CellSamplesStayInTheCellAndMatchUniformDirectionsInIt) {
  const ViewSphere sphere(GetParam());
  const int m = sphere.size() / 3;
  std::mt19937 rng(17);
  double mean_angle = 0.0;
  const int samples = 4000;
  Eigen::Vector3d mean_direction = Eigen::Vector3d::Zero();
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector3d d = sphere.sampleInCell(m, rng);
    ASSERT_EQ(sphere.nearest(d), m);
    ASSERT_NEAR(d.norm(), 1.0, 1e-12);
    mean_angle += angle(d, sphere.direction(m)) / samples;
    mean_direction += d / samples;
  }
  // Reference: uniform directions on the whole sphere that fall into cell m.
  double reference_angle = 0.0;
  Eigen::Vector3d reference_direction = Eigen::Vector3d::Zero();
  int in_cell = 0;
  for (const auto& u : uniformDirections(4000 * sphere.size(), 5)) {
    if (sphere.nearest(u) != m) continue;
    reference_angle += angle(u, sphere.direction(m));
    reference_direction += u;
    ++in_cell;
  }
  reference_angle /= in_cell;
  reference_direction /= in_cell;
  EXPECT_NEAR(mean_angle, reference_angle, 0.03 * reference_angle);
  // The cell's centroid: off-centre sampling would shift it by a sizeable part of the cell.
  EXPECT_LT((mean_direction - reference_direction).norm(), 0.03 * sphere.cellRadius(m));
}

INSTANTIATE_TEST_SUITE_P(IcosphereAndFibonacci, ViewSphereCounts,
                         ::testing::Values(12, 42, 162, 7, 100));

TEST(Icosphere, IsAClosedOutwardUnitMeshWithTheSubdivisionCounts) {
  for (int level = 0; level <= 3; ++level) {
    const Icosphere sphere = makeIcosphere(level);
    const int split = 1 << (2 * level);  // 4^level
    EXPECT_EQ(sphere.vertices.size(), static_cast<std::size_t>(10 * split + 2));
    ASSERT_EQ(sphere.faces.size(), static_cast<std::size_t>(20 * split));
    for (const Eigen::Vector3d& v : sphere.vertices) EXPECT_NEAR(v.norm(), 1.0, 1e-12);
    std::map<std::pair<int, int>, int> directed_edges;
    for (const Eigen::Vector3i& f : sphere.faces) {
      const Eigen::Vector3d &a = sphere.vertices[f[0]], &b = sphere.vertices[f[1]],
                            &c = sphere.vertices[f[2]];
      EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0.0) << "face not outward at level " << level;
      for (int e = 0; e < 3; ++e) ++directed_edges[{f[e], f[(e + 1) % 3]}];
    }
    // Closed and consistently oriented: every edge is used once in each direction.
    for (const auto& [edge, count] : directed_edges) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(directed_edges.count({edge.second, edge.first}), 1u);
    }
  }
  EXPECT_THROW(makeIcosphere(-1), Error);
  EXPECT_THROW(makeIcosphere(7), Error);
}

TEST(ViewSphere, DefaultIsTheLevelOneIcosphere) {
  const ViewSphere sphere;
  ASSERT_EQ(sphere.size(), 42);
  // The 12 icosahedron vertices are among the directions ...
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  const Eigen::Vector3d vertex = Eigen::Vector3d(0, 1, phi).normalized();
  bool found = false;
  for (const auto& d : sphere.directions()) found = found || (d - vertex).norm() < 1e-12;
  EXPECT_TRUE(found);
  // ... and every direction's nearest neighbour is half an icosahedron edge away.
  const double half_edge = 0.5 * std::acos(1.0 / std::sqrt(5.0));
  for (double a : nearestNeighbourAngles(sphere)) EXPECT_NEAR(a, half_edge, 0.06);
  const std::vector<double> angles = nearestNeighbourAngles(sphere);
  EXPECT_NEAR(*std::min_element(angles.begin(), angles.end()), half_edge, 1e-9);
}

TEST(ViewSphere, IcosahedronIsPerfectlyUniform) {
  const double edge = std::acos(1.0 / std::sqrt(5.0));
  for (double a : nearestNeighbourAngles(ViewSphere(12))) EXPECT_NEAR(a, edge, 1e-12);
}

TEST(ViewSphere, Level3IcosphereHas642Directions) { EXPECT_EQ(ViewSphere(642).size(), 642); }

TEST(ViewSphere, DirectionsAreDeterministic) {
  EXPECT_EQ(ViewSphere(42).directions(), ViewSphere(42).directions());
  EXPECT_EQ(ViewSphere(99).directions(), ViewSphere(99).directions());
}

TEST(ViewSphere, NearestOfAGridDirectionIsItselfAndIgnoresLength) {
  const ViewSphere sphere;
  for (int m = 0; m < sphere.size(); ++m) {
    EXPECT_EQ(sphere.nearest(sphere.direction(m)), m);
    EXPECT_EQ(sphere.nearest(3.0 * sphere.direction(m)), m);
  }
}

TEST(ViewSphere, TwoDirectionsSplitTheSphereIntoHemispheres) {
  const ViewSphere sphere(2);
  std::mt19937 rng(1);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(sphere.nearest(sphere.sampleInCell(1, rng)), 1);
}

TEST(ViewSphere, BadArgumentsThrow) {
  EXPECT_THROW(ViewSphere(1), Error);
  EXPECT_THROW(ViewSphere(0), Error);
  EXPECT_THROW(ViewSphere(-5), Error);
  const ViewSphere sphere;
  EXPECT_THROW(sphere.direction(42), Error);
  EXPECT_THROW(sphere.direction(-1), Error);
  std::mt19937 rng(1);
  EXPECT_THROW(sphere.sampleInCell(42, rng), Error);
  EXPECT_THROW(sphere.nearest(Eigen::Vector3d::Zero()), Error);
  EXPECT_THROW(sphere.nearest(Eigen::Vector3d(std::nan(""), 0, 1)), Error);
}

}  // namespace
}  // namespace vdc
