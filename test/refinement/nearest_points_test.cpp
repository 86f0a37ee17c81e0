#include "view_direction_classification/refinement/nearest_points.h"

#include <gtest/gtest.h>

#include "view_direction_classification/common/error.h"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace vdc {
namespace {

std::vector<Eigen::Vector3f> randomPoints(int count, float extent, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> coordinate(-extent, extent);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < count; ++i) {
    points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  }
  return points;
}

// The nearest point by brute force: index and squared distance.
std::pair<int, float> bruteForceNearest(const std::vector<Eigen::Vector3f>& points,
                                        const Eigen::Vector3f& query) {
  std::pair<int, float> best(-1, std::numeric_limits<float>::infinity());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float squared = (points[i] - query).squaredNorm();
    if (squared < best.second) best = {static_cast<int>(i), squared};
  }
  return best;
}

TEST(NearestPoints, FindsTheExactNearestPointOfEveryQuery) {
  const std::vector<Eigen::Vector3f> points = randomPoints(2000, 0.05f, 1);
  const NearestPoints nearest(points);
  // Queries near the points and far from them (a wrong pose's cloud lies off the model).
  const std::vector<Eigen::Vector3f> queries = randomPoints(500, 0.2f, 2);
  std::vector<int> indices;
  std::vector<float> squared;
  nearest.search(queries, &indices, &squared);
  ASSERT_EQ(indices.size(), queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto [index, distance] = bruteForceNearest(points, queries[i]);
    EXPECT_EQ(indices[i], index) << "query " << i;
    EXPECT_FLOAT_EQ(squared[i], distance) << "query " << i;
  }
}

TEST(NearestPoints, ABoundedSearchReportsTheNearestWithinTheBoundAndNothingBeyond) {
  const std::vector<Eigen::Vector3f> points = randomPoints(2000, 0.05f, 3);
  const NearestPoints nearest(points);
  const std::vector<Eigen::Vector3f> queries = randomPoints(500, 0.1f, 4);
  const double bound = 0.01;
  std::vector<int> indices;
  std::vector<float> squared;
  nearest.search(queries, &indices, &squared, bound);
  int within = 0, beyond = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto [index, distance] = bruteForceNearest(points, queries[i]);
    if (distance <= bound * bound) {
      ++within;
      EXPECT_EQ(indices[i], index) << "query " << i;
      EXPECT_FLOAT_EQ(squared[i], distance) << "query " << i;
    } else {
      ++beyond;
      EXPECT_EQ(indices[i], -1) << "query " << i;
      EXPECT_EQ(squared[i], std::numeric_limits<float>::infinity()) << "query " << i;
    }
  }
  // Both kinds of query were asked.
  EXPECT_GT(within, 50);
  EXPECT_GT(beyond, 50);
}

TEST(NearestPoints, APointAtExactlyTheBoundIsStillReported) {
  const NearestPoints nearest({Eigen::Vector3f(0.0f, 0.0f, 0.0f), Eigen::Vector3f(1.0f, 0, 0)});
  std::vector<int> indices;
  std::vector<float> squared;
  nearest.search({Eigen::Vector3f(0.0f, 0.0f, 0.25f)}, &indices, &squared, 0.25);
  EXPECT_EQ(indices[0], 0);
  EXPECT_FLOAT_EQ(squared[0], 0.0625f);
}

TEST(NearestPoints, AnEmptySetAnswersEveryQueryWithNone) {
  const NearestPoints nearest({});
  std::vector<int> indices;
  std::vector<float> squared;
  nearest.search({Eigen::Vector3f::Zero(), Eigen::Vector3f::Ones()}, &indices, &squared);
  ASSERT_EQ(indices.size(), 2u);
  EXPECT_EQ(indices[0], -1);
  EXPECT_EQ(squared[1], std::numeric_limits<float>::infinity());
}

TEST(NearestPoints, QueriesFarOffOrNotFiniteFindNothingWithinABoundAndDoNotStopTheSearch) {
  const NearestPoints nearest(randomPoints(100, 0.05f, 5));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float huge = 0.5f * std::numeric_limits<float>::max();
  std::vector<int> indices;
  std::vector<float> squared;
  // A kilometre off: its squared distance is finite, so only the bound leaves it unanswered.
  nearest.search({Eigen::Vector3f(1000.0f, 0.0f, 0.0f), Eigen::Vector3f(huge, -huge, huge),
                  Eigen::Vector3f(nan, 0.0f, 0.0f), Eigen::Vector3f::Zero()},
                 &indices, &squared, 0.1);
  EXPECT_EQ(indices[0], -1);
  EXPECT_EQ(indices[1], -1);
  EXPECT_EQ(indices[2], -1);
  EXPECT_GE(indices[3], 0);
}

TEST(NearestPoints, AFacingFilterSkipsPointsWhoseNormalTurnsAwayFromTheQuerysCamera) {
  // Two sides of a thin wall: the outside at x = 0 faces -x, the inside at x = 4 mm faces +x. A
  // query 1 mm behind the outside, nearer the inside, seen by a camera at x = -1.
  const NearestPoints wall({Eigen::Vector3f(0.0f, 0.0f, 0.0f), Eigen::Vector3f(0.004f, 0.0f, 0.0f)},
                           {Eigen::Vector3f(-1.0f, 0.0f, 0.0f), Eigen::Vector3f(1.0f, 0.0f, 0.0f)});
  const std::vector<Eigen::Vector3f> queries{Eigen::Vector3f(0.003f, 0.0f, 0.0f)};
  std::vector<int> indices;
  std::vector<float> squared;
  wall.search(queries, &indices, &squared);
  EXPECT_EQ(indices[0], 1);  // unfiltered: the inside, 1 mm away
  const std::vector<Eigen::Vector3f> towards_camera{Eigen::Vector3f(-1.0f, 0.0f, 0.0f)};
  const NearestPoints::FacingFilter facing{&towards_camera, 0.0f};
  wall.search(queries, &indices, &squared, 0.01, &facing);
  EXPECT_EQ(indices[0], 0);  // the outside, 3 mm away
  EXPECT_NEAR(squared[0], 0.003f * 0.003f, 1e-9f);
  // Within a bound that only the inside meets: nothing.
  wall.search(queries, &indices, &squared, 0.002, &facing);
  EXPECT_EQ(indices[0], -1);
}

TEST(NearestPoints, AFacingFilterNeedsNormalsAndOneDirectionPerQuery) {
  const std::vector<Eigen::Vector3f> points{Eigen::Vector3f::Zero()};
  const std::vector<Eigen::Vector3f> queries{Eigen::Vector3f::Zero(), Eigen::Vector3f::Ones()};
  std::vector<int> indices;
  std::vector<float> squared;
  const std::vector<Eigen::Vector3f> one{Eigen::Vector3f::UnitX()};
  const NearestPoints::FacingFilter facing{&one, 0.0f};
  EXPECT_THROW(NearestPoints(points).search(queries, &indices, &squared, 1.0, &facing), Error);
  const NearestPoints with_normals(points, {Eigen::Vector3f::UnitX()});
  EXPECT_THROW(with_normals.search(queries, &indices, &squared, 1.0, &facing), Error);
  EXPECT_THROW(NearestPoints(points, {}), Error);
}

}  // namespace
}  // namespace vdc
