// Benchmarks of the Bingham library (Google Benchmark) and an accuracy table comparing the exact
// normaliser with a libbingham-style interpolated lookup table.
//
//   make -C <build> vdc_bingham_benchmark && <build>/vdc_bingham_benchmark
#include "view_direction_classification/bingham/bingham.h"
#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/bingham/bingham_normalizer.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/estimation/view_measurement.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using vdc::BinghamDistribution;
using vdc::BinghamMixture;

const std::vector<Eigen::Vector3d>& normalizerRegimes() {
  static const std::vector<Eigen::Vector3d> regimes{
      {-1, -1, 0}, {-50, -20, -5}, {-1e3, -1e3, -100}, {-1e5, -1e5, -1e5}, {-1e5, -1, 0}};
  return regimes;
}

void BM_Normalizer(benchmark::State& state) {
  const Eigen::Vector3d z = normalizerRegimes()[state.range(0)];
  for (auto _ : state) benchmark::DoNotOptimize(vdc::binghamNormalizer(z));
  state.SetLabel("z = (" + std::to_string(z(0)) + ", " + std::to_string(z(1)) + ", " +
                 std::to_string(z(2)) + ")");
}
BENCHMARK(BM_Normalizer)->DenseRange(0, 4);

void BM_NormalizerWithGradient(benchmark::State& state) {
  const Eigen::Vector3d z = normalizerRegimes()[state.range(0)];
  for (auto _ : state) benchmark::DoNotOptimize(vdc::binghamNormalizerWithGradient(z));
}
BENCHMARK(BM_NormalizerWithGradient)->DenseRange(0, 4);

Eigen::Vector4d randomRotation(std::mt19937_64& generator) {
  std::normal_distribution<double> normal;
  return Eigen::Vector4d(normal(generator), normal(generator), normal(generator), normal(generator))
      .normalized();
}

BinghamDistribution centredOn(const Eigen::Vector4d& q, const Eigen::Vector3d& z) {
  BinghamDistribution::Axes axes;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector4d pure = Eigen::Vector4d::Zero();
    pure(i + 1) = 1.0;
    axes.col(i) = vdc::quaternionMultiply(pure, q);
  }
  return BinghamDistribution(z, axes);
}

void BM_ComponentProduct(benchmark::State& state) {
  std::mt19937_64 generator(1);
  const BinghamDistribution a = centredOn(randomRotation(generator), {-300, -100, -20});
  const BinghamDistribution b = centredOn(randomRotation(generator), {-40, -40, 0});
  for (auto _ : state) benchmark::DoNotOptimize(vdc::multiply(a, b));
}
BENCHMARK(BM_ComponentProduct);

// A 200-component belief (sharp hypotheses around random orientations) and a 42-girdle view
// measurement (uniform p_sum over a 42-direction Fibonacci lattice).
BinghamMixture beliefWith200Components() {
  std::mt19937_64 generator(2);
  std::vector<double> weights;
  std::vector<BinghamDistribution> components;
  std::uniform_real_distribution<double> weight(0.1, 1.0);
  for (int k = 0; k < 200; ++k) {
    weights.push_back(weight(generator));
    components.push_back(centredOn(randomRotation(generator), {-400, -150, -60}));
  }
  return BinghamMixture(weights, components);
}

BinghamMixture measurementWith42Girdles() {
  std::vector<Eigen::Vector3d> directions;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < 42; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / 42;
    const double r = std::sqrt(1.0 - z * z);
    directions.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  const Eigen::VectorXd p = Eigen::VectorXd::Constant(42, 1.0 / 42);
  return vdc::viewMeasurement(p, directions, vdc::defaultViewConcentration(0.55));
}

void BM_MixtureProduct42x200WithReduction(benchmark::State& state) {
  const BinghamMixture belief = beliefWith200Components();
  const BinghamMixture measurement = measurementWith42Girdles();
  std::size_t kept = 0;
  for (auto _ : state) {
    const BinghamMixture posterior = vdc::reduce(vdc::multiply(belief, measurement));
    kept = posterior.size();
    benchmark::DoNotOptimize(kept);
  }
  state.counters["components_kept"] = static_cast<double>(kept);
}
BENCHMARK(BM_MixtureProduct42x200WithReduction)->Unit(benchmark::kMillisecond);

void BM_Map200Components(benchmark::State& state) {
  const BinghamMixture belief = beliefWith200Components();
  for (auto _ : state) benchmark::DoNotOptimize(vdc::mapEstimate(belief));
}
BENCHMARK(BM_Map200Components)->Unit(benchmark::kMillisecond);

// A libbingham-style table: 73 nodes per axis over [-900, 0], denser near 0 (here quadratic
// spacing, z_i = -900 (i/72)^2), trilinear interpolation, concentrations clamped at -900. Only
// the 8 nodes around a query are evaluated (exactly, by our normaliser), which is what a full
// precomputed table would hold there.
double tableLookup(const Eigen::Vector3d& z) {
  constexpr int kNodes = 73;
  const auto node = [](int i) { return -900.0 * std::pow(i / (kNodes - 1.0), 2); };
  int lower[3];
  double fraction[3];
  for (int a = 0; a < 3; ++a) {
    const double clamped = std::max(-900.0, std::min(0.0, z(a)));
    // node(i) is decreasing in i; find i with node(i) >= clamped >= node(i+1).
    const double position = (kNodes - 1.0) * std::sqrt(-clamped / 900.0);
    lower[a] = std::min(kNodes - 2, static_cast<int>(position));
    fraction[a] = (node(lower[a]) - clamped) / (node(lower[a]) - node(lower[a] + 1));
  }
  double value = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    Eigen::Vector3d at;
    double weight = 1.0;
    for (int a = 0; a < 3; ++a) {
      const int bit = (corner >> a) & 1;
      at(a) = node(lower[a] + bit);
      weight *= bit ? fraction[a] : 1.0 - fraction[a];
    }
    value += weight * vdc::binghamNormalizer(at);
  }
  return value;
}

void printAccuracyTable() {
  std::printf("\nAccuracy of F(-k,-k,0) against the closed form 2 pi^2 (1 - e^-k) / k\n");
  std::printf("%10s %16s %14s %16s %14s\n", "k", "exact F", "rel. error", "table F",
              "table rel.err");
  for (double k : {10.0, 100.0, 500.0, 2000.0, 1e4, 1e5}) {
    const double truth = -2.0 * M_PI * M_PI * std::expm1(-k) / k;
    const double exact = vdc::binghamNormalizer(Eigen::Vector3d(-k, -k, 0.0));
    const double table = tableLookup(Eigen::Vector3d(-k, -k, 0.0));
    std::printf("%10g %16.10g %14.2e %16.10g %14.2e\n", k, exact, std::abs(exact - truth) / truth,
                table, std::abs(table - truth) / truth);
  }
  std::printf("Off-grid points (reference: the exact normaliser)\n");
  for (const Eigen::Vector3d& z :
       {Eigen::Vector3d(-37.3, -12.1, -3.3), Eigen::Vector3d(-250.5, -80.2, -0.7),
        Eigen::Vector3d(-3000, -1200, -10)}) {
    const double exact = vdc::binghamNormalizer(z);
    const double table = tableLookup(z);
    std::printf("  z = (%g, %g, %g): exact %.10g, table %.10g, table rel. error %.2e\n", z(0), z(1),
                z(2), exact, table, std::abs(table - exact) / exact);
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  printAccuracyTable();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
