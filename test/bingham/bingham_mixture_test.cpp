#include "view_direction_classification/bingham/bingham_mixture.h"
#include "support/random_unit_quaternions.h"
#include "view_direction_classification/bingham/bingham.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace vdc {
namespace {

constexpr double kTwoPiSquared = 2.0 * M_PI * M_PI;

// A Bingham centred on q whose three axes are the pure unit quaternions (x) q, concentrations z:
// z(i) controls the spread of rotations about world axis i applied on the left of q.
BinghamDistribution centredOn(const Eigen::Vector4d& q, const Eigen::Vector3d& z) {
  BinghamDistribution::Axes axes;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector4d pure = Eigen::Vector4d::Zero();
    pure(i + 1) = 1.0;
    axes.col(i) = quaternionMultiply(pure, q);
  }
  return BinghamDistribution(z, axes);
}

Eigen::Vector4d rotationAbout(double x, double y, double z, double angle_deg) {
  return quaternionFromAxisAngle(Eigen::Vector3d(x, y, z), angle_deg * M_PI / 180.0);
}

double angleDeg(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  return 2.0 * std::acos(std::min(1.0, std::abs(a.dot(b)))) * 180.0 / M_PI;
}

// Midpoint rule over hyperspherical coordinates of S^3 (volume element sin^2 psi sin theta).
template <typename Function>
double integrateOverSphere(Function f, int n) {
  double sum = 0.0;
  const double dpsi = M_PI / n, dtheta = M_PI / n, dphi = 2.0 * M_PI / (2 * n);
  for (int a = 0; a < n; ++a) {
    const double psi = (a + 0.5) * dpsi;
    for (int b = 0; b < n; ++b) {
      const double theta = (b + 0.5) * dtheta;
      const double volume = std::pow(std::sin(psi), 2) * std::sin(theta) * dpsi * dtheta * dphi;
      for (int c = 0; c < 2 * n; ++c) {
        const double phi = (c + 0.5) * dphi;
        const Eigen::Vector4d x(std::cos(psi), std::sin(psi) * std::cos(theta),
                                std::sin(psi) * std::sin(theta) * std::cos(phi),
                                std::sin(psi) * std::sin(theta) * std::sin(phi));
        sum += f(x) * volume;
      }
    }
  }
  return sum;
}

TEST(BinghamMixture, DefaultIsTheUniformDistribution) {
  const BinghamMixture uniform;
  ASSERT_EQ(uniform.size(), 1u);
  EXPECT_NEAR(uniform.density(Eigen::Vector4d(0, 0, 1, 0)), 1.0 / kTwoPiSquared, 1e-14);
  EXPECT_NEAR(uniform.entropy(), std::log(kTwoPiSquared), 1e-12);
}

TEST(BinghamMixture, RejectsEmptyMismatchedAndInvalidWeights) {
  const BinghamDistribution b;
  EXPECT_THROW(BinghamMixture({}, {}), Error);
  EXPECT_THROW(BinghamMixture({1.0, 2.0}, {b}), Error);
  EXPECT_THROW(BinghamMixture({-1.0}, {b}), Error);
  EXPECT_THROW(BinghamMixture({NAN}, {b}), Error);
  EXPECT_THROW(BinghamMixture({0.0}, {b}), Error);
  EXPECT_THROW(BinghamMixture::fromLogWeights({NAN}, {b}), Error);
  EXPECT_THROW(BinghamMixture::fromLogWeights({-std::numeric_limits<double>::infinity()}, {b}),
               Error);
  EXPECT_THROW(BinghamMixture().density(Eigen::Vector4d(2, 0, 0, 0)), Error);
}

TEST(BinghamMixture, ProductWeightsMatchBruteForceIntegrationOverAGridOfTheSphere) {
  const Eigen::Vector4d q1 = rotationAbout(1, 0, 0, 40), q2 = rotationAbout(0, 1, 1, -70);
  const BinghamMixture a({0.3, 0.7}, {centredOn(q1, {-12, -6, -2}), centredOn(q2, {-9, -9, -1})});
  const BinghamMixture b({0.6, 0.4}, {centredOn(rotationAbout(0, 0, 1, 30), {-10, -4, -3}),
                                      centredOn(rotationAbout(1, 1, 0, 110), {-7, -5, -5})});
  const BinghamMixture product = multiply(a, b);
  ASSERT_EQ(product.size(), 4u);
  std::vector<double> brute_force;
  double total = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      const double overlap = integrateOverSphere(
          [&](const Eigen::Vector4d& x) {
            return a.component(i).density(x) * b.component(j).density(x);
          },
          60);
      brute_force.push_back(a.weight(i) * b.weight(j) * overlap);
      total += brute_force.back();
    }
  }
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(product.weight(k), brute_force[k] / total, 1e-3 * brute_force[k] / total) << k;
  }
  // And pointwise: the product mixture is a b / integral(a b).
  const Eigen::Vector4d x = rotationAbout(1, 2, 3, 25);
  EXPECT_NEAR(product.density(x), a.density(x) * b.density(x) / total, 1e-3 * product.density(x));
}

TEST(BinghamMixture, ExactWeightsPreferTheHypothesisThatAgreesWithTheMeasurement) {
  // Two equally weighted hypotheses; a measurement that agrees with the first. Weights from
  // w_i w_j alone (libbingham) would stay 50/50.
  const Eigen::Vector4d first = rotationAbout(0, 0, 1, 0), second = rotationAbout(0, 0, 1, 90);
  const BinghamMixture prior(
      {0.5, 0.5}, {centredOn(first, {-50, -50, -50}), centredOn(second, {-50, -50, -50})});
  const BinghamMixture measurement({1.0}, {centredOn(first, {-20, -20, -20})});
  const BinghamMixture posterior = multiply(prior, measurement);
  EXPECT_GT(posterior.weight(0), 0.999);
}

TEST(BinghamMixture, TwoGirdlesFromDifferentDirectionsFuseAtTheirIntersection) {
  // Girdle 1: rotations about world z of q_true are free; girdle 2: about world x.
  const Eigen::Vector4d truth = rotationAbout(1, -2, 0.5, 63);
  const double kappa = 40.0;
  const BinghamMixture first({1.0}, {centredOn(truth, {-kappa, -kappa, 0.0})});
  const BinghamMixture second({1.0}, {centredOn(truth, {0.0, -kappa, -kappa})});
  const BinghamMixture fused = multiply(first, second);
  ASSERT_EQ(fused.size(), 1u);
  const BinghamDistribution& c = fused.component(0);
  EXPECT_LT(angleDeg(c.mode(), truth), 1e-6);
  EXPECT_LE(c.concentrations()(2), -kappa + 1e-9);  // no free direction left
}

TEST(BinghamMixture, AFittedPoseTimesViewGirdlesKeepsThePoseAndWeighsItsHypotheses) {
  // Two verified poses (sigma about 1.5 degrees), half a turn apart about z, and a belief of two
  // view girdles (concentration 18), each passing a few degrees from one of them: the exact
  // product moves each pose towards its girdle, the sharpness ratio keeps the poses where the fit
  // put them, and the poses are weighed alike either way.
  const Eigen::Vector4d pose_a = rotationAbout(1, 2, 3, 40);
  const Eigen::Vector4d pose_b = quaternionMultiply(rotationAbout(0, 0, 1, 180), pose_a);
  const BinghamMixture poses({0.5, 0.5}, {centredOn(pose_a, {-3000, -3000, -3000}),
                                          centredOn(pose_b, {-3000, -3000, -3000})});
  const BinghamMixture girdles(
      {0.8, 0.2},
      {centredOn(quaternionMultiply(rotationAbout(0, 1, 0, 6), pose_a), {0.0, -18.0, -18.0}),
       centredOn(quaternionMultiply(rotationAbout(1, 0, 0, 6), pose_b), {-18.0, 0.0, -18.0})});
  const BinghamMixture exact = multiply(girdles, poses, 1e-6);
  const BinghamMixture kept = multiply(girdles, poses, 1e-6, 10.0);
  ASSERT_EQ(exact.size(), kept.size());
  ASSERT_EQ(kept.size(), 2u);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const Eigen::Vector4d& pose = k == 0 ? pose_a : pose_b;
    EXPECT_LT(angleDeg(kept.component(k).mode(), pose), 1e-9);
    EXPECT_GT(angleDeg(exact.component(k).mode(), pose), 0.01);
    EXPECT_NEAR(kept.weight(k), exact.weight(k), 0.02);
  }
  EXPECT_GT(kept.weight(0), 0.75);  // the girdle that carries more weight still says which
  EXPECT_THROW(multiply(girdles, poses, 0.0, 0.5), Error);
}

// Many random concentrated components, so most pairwise products are negligible.
BinghamMixture randomConcentratedMixture(int count, double concentration, unsigned seed) {
  std::mt19937 rng(seed);
  const std::vector<Eigen::Vector4d> modes = test::randomUnitQuaternions(count, rng);
  std::vector<double> weights;
  std::vector<BinghamDistribution> components;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector4d& q = modes[static_cast<std::size_t>(k)];
    components.push_back(centredOn(q, Eigen::Vector3d(-concentration, -concentration,
                                                      -concentration * (k % 3 == 0 ? 0.01 : 1))));
    weights.push_back(1.0 + k % 5);
  }
  return BinghamMixture(weights, components);
}

TEST(BinghamMixture, ProductWithAWeightFloorKeepsExactlyTheComponentsAboveIt) {
  const BinghamMixture a = randomConcentratedMixture(30, 200.0, 1);
  const BinghamMixture b = randomConcentratedMixture(20, 50.0, 2);
  const double floor = 1e-6;
  const BinghamMixture full = multiply(a, b);
  const BinghamMixture pruned = multiply(a, b, floor);
  const double heaviest = *std::max_element(full.weights().begin(), full.weights().end());
  std::vector<double> expected;
  for (double w : full.weights()) {
    if (w >= floor * heaviest) expected.push_back(w);
  }
  ASSERT_EQ(pruned.size(), expected.size());
  ASSERT_LT(pruned.size(), full.size());  // the floor really removed something here
  double expected_total = 0.0;
  for (double w : expected) expected_total += w;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_NEAR(pruned.weight(k), expected[k] / expected_total, 1e-12);
  }
  // And what the filter keeps is unchanged.
  const BinghamMixture reduced_full = reduce(full);
  const BinghamMixture reduced_pruned = reduce(pruned);
  ASSERT_EQ(reduced_full.size(), reduced_pruned.size());
  for (std::size_t k = 0; k < reduced_full.size(); ++k) {
    EXPECT_NEAR(reduced_full.weight(k), reduced_pruned.weight(k), 1e-9);
    EXPECT_LT(angleDeg(reduced_full.component(k).mode(), reduced_pruned.component(k).mode()), 1e-4);
  }
  EXPECT_THROW(multiply(a, b, 1.0), Error);
  EXPECT_THROW(multiply(a, b, -0.1), Error);
}

TEST(BinghamMixture, ReductionDropsLightMergesNearAndCapsCount) {
  const Eigen::Vector4d q = rotationAbout(0, 1, 0, 10);
  const Eigen::Vector4d near = rotationAbout(0, 1, 0, 11);  // 1 degree away
  const Eigen::Vector4d far = rotationAbout(0, 1, 0, 100);
  const BinghamMixture mixture(
      {0.5, 0.3, 0.2 - 1e-8, 1e-8},
      {centredOn(q, {-100, -100, -100}), centredOn(near, {-100, -100, -100}),
       centredOn(far, {-100, -100, -100}), centredOn(far, {-1, -1, -1})});
  const BinghamMixture reduced = reduce(mixture);
  ASSERT_EQ(reduced.size(), 2u);
  EXPECT_NEAR(reduced.weight(0), 0.8, 1e-6);
  // The merged component sits between its parents, nearer the heavier.
  EXPECT_LT(angleDeg(reduced.component(0).mode(), rotationAbout(0, 1, 0, 10.375)), 0.05);
  EXPECT_LT(angleDeg(reduced.component(1).mode(), far), 1e-6);

  MixtureReductionOptions capped;
  capped.max_components = 1;
  EXPECT_EQ(reduce(mixture, capped).size(), 1u);
  capped.max_components = 0;
  EXPECT_THROW(reduce(mixture, capped), Error);
}

TEST(BinghamMixture, ReductionKeepsGirdlesWithACommonModeButDifferentCirclesApart) {
  const Eigen::Vector4d q = rotationAbout(1, 0, 0, 20);
  const BinghamMixture girdles({0.5, 0.5},
                               {centredOn(q, {-40, -40, 0}), centredOn(q, {0, -40, -40})});
  EXPECT_EQ(reduce(girdles).size(), 2u);
}

TEST(BinghamMixture, MapFindsTheHighestPeakEvenBetweenComponentModes) {
  const Eigen::Vector4d q = rotationAbout(0, 0, 1, 0), p = rotationAbout(0, 0, 1, 20);
  // Two broad, overlapping components: the density peaks between their modes.
  const BinghamMixture mixture({0.5, 0.5},
                               {centredOn(q, {-5, -5, -5}), centredOn(p, {-5, -5, -5})});
  const Eigen::Vector4d map = mapEstimate(mixture);
  EXPECT_LT(angleDeg(map, rotationAbout(0, 0, 1, 10)), 1e-4);
  EXPECT_GE(map(0), 0.0);
  // A heavy sharp hypothesis wins over a light one.
  const BinghamMixture two({0.2, 0.8}, {centredOn(q, {-500, -500, -500}),
                                        centredOn(rotationAbout(1, 0, 0, 90), {-500, -500, -500})});
  EXPECT_LT(angleDeg(mapEstimate(two), rotationAbout(1, 0, 0, 90)), 1e-6);
}

TEST(BinghamMixture, MapIsAtLeastAsGoodAsTheBestOfManyRandomPoints) {
  const BinghamMixture mixture({0.4, 0.35, 0.25},
                               {centredOn(rotationAbout(1, 0, 0, 30), {-8, -3, -1}),
                                centredOn(rotationAbout(0, 1, 0, 45), {-20, -2, 0}),
                                centredOn(rotationAbout(0, 0, 1, -60), {-6, -6, -6})});
  const double at_map = mixture.logDensity(mapEstimate(mixture));
  for (const Eigen::Vector4d& x : test::randomUnitQuaternionsFromSeed(20000, 3)) {
    ASSERT_LE(mixture.logDensity(x), at_map + 1e-9);
  }
}

TEST(BinghamMixture, EntropyIsExactForOneComponentAndAddsLogTwoForTwoSeparatedEqualOnes) {
  const BinghamDistribution c = centredOn(rotationAbout(1, 0, 0, 0), {-300, -300, -300});
  EXPECT_DOUBLE_EQ(BinghamMixture({1.0}, {c}).entropy(), c.entropy());
  const BinghamMixture two({0.5, 0.5},
                           {c, centredOn(rotationAbout(1, 0, 0, 120), {-300, -300, -300})});
  EXPECT_NEAR(two.entropy(), c.entropy() + std::log(2.0), 0.05);
  EXPECT_EQ(two.entropy(), two.entropy());  // fixed seed: repeatable
}

TEST(BinghamMixture, RotatedMixtureDensityFollowsTheRotation) {
  const BinghamMixture mixture({0.4, 0.6}, {centredOn(rotationAbout(1, 0, 0, 30), {-8, -3, -1}),
                                            centredOn(rotationAbout(0, 1, 0, 45), {-20, -2, 0})});
  const Eigen::Vector4d r = rotationAbout(1, 1, 1, 77);
  const Eigen::Vector4d x = rotationAbout(2, 0, 1, 33);
  EXPECT_NEAR(mixture.rotated(r).logDensity(quaternionMultiply(r, x)), mixture.logDensity(x),
              1e-10);
}

}  // namespace
}  // namespace vdc
