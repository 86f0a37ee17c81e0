#include "view_direction_classification/bingham/bingham_mixture.h"

#include "view_direction_classification/bingham/bingham_fit.h"
#include "view_direction_classification/bingham/bingham_normalizer.h"
#include "view_direction_classification/bingham/bingham_sampler.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/parallel_for.h"
#include "view_direction_classification/common/quaternion.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <sstream>

namespace vdc {
namespace {

// The mixture's log density and its Euclidean gradient in R^4, from precomputed exponent
// matrices A_k and offsets c_k = log w_k - log F_k.
struct LogDensityModel {
  std::vector<Eigen::Matrix4d> exponents;
  std::vector<double> offsets;

  explicit LogDensityModel(const BinghamMixture& mixture) {
    for (std::size_t k = 0; k < mixture.size(); ++k) {
      exponents.push_back(mixture.component(k).exponentMatrix());
      offsets.push_back(std::log(mixture.weight(k)) - mixture.component(k).logNormalizer());
    }
  }

  double value(const Eigen::Vector4d& x, Eigen::Vector4d* gradient = nullptr) const {
    // The MAP search calls this thousands of times per estimate: no allocation, two passes.
    double largest = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < exponents.size(); ++k) {
      largest = std::max(largest, term(k, x));
    }
    if (gradient != nullptr) gradient->setZero();
    if (!std::isfinite(largest)) return largest;
    double sum = 0.0;
    for (std::size_t k = 0; k < exponents.size(); ++k) {
      const Eigen::Vector4d ax = exponents[k] * x;
      const double share = std::exp(x.dot(ax) + offsets[k] - largest);
      sum += share;
      if (gradient != nullptr) *gradient += 2.0 * share * ax;
    }
    if (gradient != nullptr) *gradient /= sum;
    return largest + std::log(sum);
  }

 private:
  double term(std::size_t k, const Eigen::Vector4d& x) const {
    return x.dot(exponents[k] * x) + offsets[k];
  }
};

// The steps of reduce(): which components take part, how they cluster, which clusters are kept,
// and one moment-matched component per kept cluster.

void checkReductionOptions(const MixtureReductionOptions& options) {
  if (!(options.relative_weight_threshold >= 0.0) || !(options.merge_angle >= 0.0) ||
      !(options.merge_log_density >= 0.0) || options.max_components < 1) {
    throw Error(
        "Mixture reduction options must have a non-negative weight threshold, merge angle and "
        "merge log density, and max_components >= 1.");
  }
}

// The components at least `relative_threshold` times the heaviest, heaviest first (ties in index
// order).
std::vector<std::size_t> componentsHeaviestFirst(const BinghamMixture& mixture,
                                                 double relative_threshold) {
  const double heaviest = *std::max_element(mixture.weights().begin(), mixture.weights().end());
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < mixture.size(); ++k) {
    if (mixture.weight(k) >= relative_threshold * heaviest) order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return mixture.weight(i) > mixture.weight(j);
  });
  return order;
}

// Probe points of a component: its mode, and one standard deviation (at most 45 degrees of
// quaternion arc) along its loosest axis both ways. For a girdle the latter lie on its circle.
using Probes = std::array<Eigen::Vector4d, 3>;

Probes probesOf(const BinghamDistribution& c) {
  const double arc = std::min(M_PI / 4.0, 1.0 / std::sqrt(2.0 * -c.concentrations()(2) + 1e-300));
  return Probes{c.mode(), std::cos(arc) * c.mode() + std::sin(arc) * c.axis(2),
                std::cos(arc) * c.mode() - std::sin(arc) * c.axis(2)};
}

// The two merge tests of MixtureReductionOptions. A product of mixtures gives ~1000 components
// and hundreds of clusters, so they avoid trigonometry: the modes' angle test compares |cos| of
// the half angle.
class MergeTest {
 public:
  explicit MergeTest(const MixtureReductionOptions& options)
      // The rotation angle 2 acos|p.q| is at most merge_angle.
      : min_mode_alignment_(std::cos(std::min(options.merge_angle, M_PI) / 2.0)),
        merge_log_density_(options.merge_log_density) {}

  bool modesClose(const BinghamDistribution& p, const BinghamDistribution& q) const {
    return std::abs(p.mode().dot(q.mode())) >= min_mode_alignment_;
  }

  // q looks like p near p's mode when its density relative to its peak (x^T A x, 0 at the mode)
  // falls at most merge_log_density below p's own at each of p's probe points.
  bool resembles(const BinghamDistribution& p, const Probes& p_probes,
                 const BinghamDistribution& q) const {
    for (const Eigen::Vector4d& x : p_probes) {
      if (x.dot(q.exponentMatrix() * x) < x.dot(p.exponentMatrix() * x) - merge_log_density_) {
        return false;
      }
    }
    return true;
  }

 private:
  double min_mode_alignment_;
  double merge_log_density_;
};

struct Cluster {
  std::vector<std::size_t> members;  // the first is the leader, the heaviest
  Probes leader_probes;              // kept: a leader is tested against many candidates
  double weight = 0.0;               // the members' total
};

// Greedy clustering of `order` (heaviest first): a component joins the first cluster whose
// leader passes both merge tests with it both ways, otherwise it leads a new cluster.
std::vector<Cluster> clusterComponents(const BinghamMixture& mixture,
                                       const std::vector<std::size_t>& order,
                                       const MergeTest& test) {
  std::vector<Cluster> clusters;
  for (std::size_t k : order) {
    const BinghamDistribution& candidate = mixture.component(k);
    std::optional<Probes> candidate_probes;  // computed once it is needed
    Cluster* joined = nullptr;
    for (Cluster& cluster : clusters) {
      const BinghamDistribution& leader = mixture.component(cluster.members.front());
      if (!test.modesClose(leader, candidate)) continue;
      if (!test.resembles(leader, cluster.leader_probes, candidate)) continue;
      if (!candidate_probes) candidate_probes = probesOf(candidate);
      if (!test.resembles(candidate, *candidate_probes, leader)) continue;
      joined = &cluster;
      break;
    }
    if (joined) {
      joined->members.push_back(k);
    } else {
      clusters.push_back(Cluster{{k}, candidate_probes ? *candidate_probes : probesOf(candidate)});
    }
  }
  for (Cluster& cluster : clusters) {
    for (std::size_t k : cluster.members) cluster.weight += mixture.weight(k);
  }
  return clusters;
}

// Merged weights can reorder the clusters: the heaviest `max_components` by total weight, in
// that order (ties in clustering order).
std::vector<const Cluster*> heaviestClusters(const std::vector<Cluster>& clusters,
                                             int max_components) {
  std::vector<const Cluster*> ranked;
  for (const Cluster& cluster : clusters) ranked.push_back(&cluster);
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const Cluster* a, const Cluster* b) { return a->weight > b->weight; });
  if (ranked.size() > static_cast<std::size_t>(max_components)) ranked.resize(max_components);
  return ranked;
}

// One component for a cluster: its leader alone, or the Bingham fitted to the members' weighted
// mean scatter matrix, starting from the leader's concentrations (members passed the merge tests:
// nearly equal).
BinghamDistribution mergeCluster(const BinghamMixture& mixture, const Cluster& cluster) {
  const BinghamDistribution& leader = mixture.component(cluster.members.front());
  if (cluster.members.size() == 1) return leader;
  Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
  for (std::size_t k : cluster.members) {
    scatter += mixture.weight(k) * mixture.component(k).scatterMatrix();
  }
  return fitBinghamToScatter(scatter / cluster.weight, leader.concentrations());
}

}  // namespace

BinghamMixture::BinghamMixture() : weights_{1.0}, components_{BinghamDistribution()} {}

BinghamMixture::BinghamMixture(std::vector<double> weights,
                               std::vector<BinghamDistribution> components)
    : weights_(std::move(weights)), components_(std::move(components)) {
  if (components_.empty()) throw Error("A Bingham mixture needs at least one component.");
  if (weights_.size() != components_.size()) {
    std::ostringstream message;
    message << "A Bingham mixture got " << weights_.size() << " weights for " << components_.size()
            << " components.";
    throw Error(message.str());
  }
  double total = 0.0;
  for (std::size_t k = 0; k < weights_.size(); ++k) {
    if (!std::isfinite(weights_[k]) || weights_[k] < 0.0) {
      std::ostringstream message;
      message << "Bingham mixture weights must be finite and >= 0, but weight " << k << " is "
              << weights_[k] << ".";
      throw Error(message.str());
    }
    total += weights_[k];
  }
  if (!(total > 0.0) || !std::isfinite(total)) {
    throw Error("The weights of a Bingham mixture must have a positive, finite sum.");
  }
  for (double& w : weights_) w /= total;
}

BinghamMixture BinghamMixture::fromLogWeights(const std::vector<double>& log_weights,
                                              std::vector<BinghamDistribution> components) {
  if (log_weights.empty()) throw Error("A Bingham mixture needs at least one component.");
  for (double v : log_weights) {
    if (std::isnan(v) || v == std::numeric_limits<double>::infinity()) {
      throw Error("A Bingham mixture's log weights must not be NaN or +infinity.");
    }
  }
  const double largest = *std::max_element(log_weights.begin(), log_weights.end());
  if (!std::isfinite(largest)) throw Error("All log weights of a Bingham mixture are -infinity.");
  std::vector<double> weights;
  weights.reserve(log_weights.size());
  for (double v : log_weights) weights.push_back(std::exp(v - largest));
  return BinghamMixture(std::move(weights), std::move(components));
}

double BinghamMixture::logDensity(const Eigen::Vector4d& x) const {
  checkUnitQuaternion(x, "at which a Bingham mixture density is evaluated");
  return LogDensityModel(*this).value(x);
}

double BinghamMixture::density(const Eigen::Vector4d& x) const { return std::exp(logDensity(x)); }

std::vector<Eigen::Vector4d> BinghamMixture::sample(int count, std::mt19937_64& generator) const {
  if (count < 0) throw Error("The number of Bingham mixture samples must be >= 0.");
  std::vector<BinghamSampler> samplers;
  for (const BinghamDistribution& c : components_) samplers.emplace_back(c);
  std::discrete_distribution<std::size_t> choose(weights_.begin(), weights_.end());
  std::vector<Eigen::Vector4d> samples;
  samples.reserve(count);
  for (int i = 0; i < count; ++i) samples.push_back(samplers[choose(generator)](generator));
  return samples;
}

double BinghamMixture::entropy(int samples, std::uint64_t seed) const {
  if (components_.size() == 1) return components_.front().entropy();
  if (samples < 1) throw Error("A Monte Carlo entropy estimate needs at least one sample.");
  std::mt19937_64 generator(seed);
  const LogDensityModel model(*this);
  double sum = 0.0;
  for (const Eigen::Vector4d& x : sample(samples, generator)) sum += model.value(x);
  return -sum / samples;
}

BinghamMixture BinghamMixture::rotated(const Eigen::Vector4d& q) const {
  std::vector<BinghamDistribution> rotated;
  rotated.reserve(components_.size());
  for (const BinghamDistribution& c : components_) rotated.push_back(c.rotated(q));
  return BinghamMixture(weights_, std::move(rotated));
}

BinghamMixture multiply(const BinghamMixture& a, const BinghamMixture& b,
                        double relative_weight_floor, double sharpness_ratio) {
  if (!(relative_weight_floor >= 0.0 && relative_weight_floor < 1.0)) {
    throw Error("The relative weight floor of a mixture product must lie in [0, 1).");
  }
  checkSharpnessRatio(sharpness_ratio);
  struct Pair {
    std::size_t i, j;
    double log_weight_bound;
  };
  std::vector<Pair> pairs;
  pairs.reserve(a.size() * b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (a.weight(i) > 0.0 && b.weight(j) > 0.0) pairs.push_back({i, j, 0.0});
    }
  }
  const auto n = static_cast<std::ptrdiff_t>(pairs.size());
  const double log_floor = std::log(relative_weight_floor);  // -inf for 0: nothing is left out
  if (relative_weight_floor > 0.0) {
    // log w_ij = log w_i + log w_j + lambda_max + log F(Z_ij) - log F_i - log F_j, with F(Z_ij)
    // bounded without quadrature: far tighter than F(0) = 2 pi^2 for the concentrated products of
    // a converging filter, where most pairs then need no normaliser at all.
    parallelFor(pairs.size(), hardwareThreads(), [&](int, std::size_t k) {
      Pair& pair = pairs[k];
      const BinghamDistribution& p = a.component(pair.i);
      const BinghamDistribution& q = b.component(pair.j);
      const Eigen::Matrix4d sum = p.exponentMatrix() + q.exponentMatrix();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(sum, Eigen::EigenvaluesOnly);
      const Eigen::Vector4d& eigenvalues = solver.eigenvalues();  // ascending
      const Eigen::Vector3d shifted = eigenvalues.head<3>().array() - eigenvalues(3);
      const double log_normalizer_bound = binghamLogNormalizerUpperBound(shifted.cwiseMin(0.0));
      pair.log_weight_bound = std::log(a.weight(pair.i)) + std::log(b.weight(pair.j)) +
                              eigenvalues(3) + log_normalizer_bound - p.logNormalizer() -
                              q.logNormalizer();
    });
  }
  // The exact weight of the pair with the highest bound is a lower bound on the heaviest weight:
  // every pair whose bound falls below it times the floor can be skipped.
  double heaviest_known = -std::numeric_limits<double>::infinity();
  if (relative_weight_floor > 0.0 && n > 0) {
    const auto top = std::max_element(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
      return x.log_weight_bound < y.log_weight_bound;
    });
    const BinghamProduct product =
        multiplyKeepingSharpFactor(a.component(top->i), b.component(top->j), sharpness_ratio);
    heaviest_known = std::log(a.weight(top->i)) + std::log(b.weight(top->j)) + product.log_scale;
  }
  std::vector<Pair> kept;
  kept.reserve(pairs.size());
  for (const Pair& pair : pairs) {
    if (relative_weight_floor == 0.0 || pair.log_weight_bound >= heaviest_known + log_floor) {
      kept.push_back(pair);
    }
  }
  std::vector<double> log_weights(kept.size());
  std::vector<BinghamDistribution> components(kept.size());
  parallelFor(kept.size(), hardwareThreads(), [&](int, std::size_t k) {
    const Pair& pair = kept[k];
    BinghamProduct product =
        multiplyKeepingSharpFactor(a.component(pair.i), b.component(pair.j), sharpness_ratio);
    log_weights[k] = std::log(a.weight(pair.i)) + std::log(b.weight(pair.j)) + product.log_scale;
    components[k] = std::move(product.distribution);
  });
  if (relative_weight_floor > 0.0) {
    // Exact weights known: drop what the bound let through but the floor does not.
    const double heaviest = *std::max_element(log_weights.begin(), log_weights.end());
    std::vector<double> surviving_weights;
    std::vector<BinghamDistribution> surviving;
    for (std::size_t k = 0; k < kept.size(); ++k) {
      if (log_weights[k] >= heaviest + log_floor) {
        surviving_weights.push_back(log_weights[k]);
        surviving.push_back(std::move(components[k]));
      }
    }
    return BinghamMixture::fromLogWeights(surviving_weights, std::move(surviving));
  }
  return BinghamMixture::fromLogWeights(log_weights, std::move(components));
}

BinghamMixture reduce(const BinghamMixture& mixture, const MixtureReductionOptions& options) {
  checkReductionOptions(options);
  const std::vector<Cluster> clusters = clusterComponents(
      mixture, componentsHeaviestFirst(mixture, options.relative_weight_threshold),
      MergeTest(options));
  const std::vector<const Cluster*> kept = heaviestClusters(clusters, options.max_components);
  // The members' scatter matrices (one normaliser gradient each) and the refit dominate a filter
  // update, so clusters are merged in parallel.
  std::vector<double> weights(kept.size());
  std::vector<BinghamDistribution> components(kept.size());
  parallelFor(kept.size(), hardwareThreads(), [&](int, std::size_t i) {
    components[i] = mergeCluster(mixture, *kept[i]);
    weights[i] = kept[i]->weight;
  });
  return BinghamMixture(std::move(weights), std::move(components));
}

Eigen::Vector4d mapEstimate(const BinghamMixture& mixture, const MapOptions& options) {
  if (options.girdle_start_points < 0 || options.max_iterations < 1) {
    throw Error("MAP options need girdle_start_points >= 0 and max_iterations >= 1.");
  }
  const LogDensityModel model(mixture);
  struct Start {
    Eigen::Vector4d x;
    double value;
  };
  std::vector<Start> starts;
  for (const BinghamDistribution& c : mixture.components()) {
    starts.push_back({c.mode(), model.value(c.mode())});
    if (c.concentrations()(2) > -options.girdle_concentration) {
      for (int i = 1; i <= options.girdle_start_points; ++i) {
        const double t = M_PI * i / (options.girdle_start_points + 1);
        const Eigen::Vector4d x = std::cos(t) * c.mode() + std::sin(t) * c.axis(2);
        starts.push_back({x, model.value(x)});
      }
    }
  }
  std::stable_sort(starts.begin(), starts.end(),
                   [](const Start& a, const Start& b) { return a.value > b.value; });
  if (options.max_refined_starts > 0 &&
      starts.size() > static_cast<std::size_t>(options.max_refined_starts)) {
    starts.resize(options.max_refined_starts);
  }

  // Each start climbs on its own: both cores share the starts; the best of each start's end
  // points is kept, ties going to the earlier start, so the result does not depend on threads.
  std::vector<Start> ends(starts.size());
  parallelFor(starts.size(), hardwareThreads(), [&](int, std::size_t s) {
    const Start start = starts[s];
    Eigen::Vector4d x = start.x;
    double value = start.value;
    double step = -1.0;  // set from the gradient's scale on the first iteration
    for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
      Eigen::Vector4d gradient;
      model.value(x, &gradient);
      const Eigen::Vector4d tangent = gradient - gradient.dot(x) * x;
      const double slope = tangent.squaredNorm();
      if (slope < 1e-24) break;
      if (step < 0.0) step = 1.0 / std::sqrt(slope);  // a first move of about one radian
      // Backtracking (Armijo) along the tangent, then back onto the sphere.
      bool moved = false;
      for (int trial = 0; trial < 60; ++trial, step *= 0.5) {
        const Eigen::Vector4d candidate = (x + step * tangent).normalized();
        const double candidate_value = model.value(candidate);
        if (candidate_value >= value + 1e-4 * step * slope) {
          const double gain = candidate_value - value;
          x = candidate;
          value = candidate_value;
          moved = true;
          if (gain < 1e-14 * std::max(1.0, std::abs(value))) iteration = options.max_iterations;
          break;
        }
      }
      if (!moved) break;
      step *= 2.0;  // let the step grow again after a success
    }
    ends[s] = {x, value};
  });
  Start best = starts.front();
  for (const Start& end : ends) {
    if (end.value > best.value) best = end;
  }
  Eigen::Vector4d result = best.x.normalized();
  return result(0) < 0.0 ? Eigen::Vector4d(-result) : result;
}

}  // namespace vdc
