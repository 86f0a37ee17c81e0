#include "view_direction_classification/ros/bingham_conversions.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/ros/geometry_conversions.h"

namespace vdc {
namespace {

// The tolerance of the core's own orthonormality check, applied to the redundant fields too.
constexpr double kTolerance = 1e-6;

std::string componentName(std::size_t index) {
  return "component " + std::to_string(index) + " of the BinghamMixture message";
}

}  // namespace

BinghamComponentMsg toBinghamComponentMsg(double weight, const BinghamDistribution& component) {
  BinghamComponentMsg msg;
  msg.weight = weight;
  for (int i = 0; i < 3; ++i) {
    msg.concentrations[i] = component.concentrations()(i);
    msg.axes[i] = toQuaternionMsg(component.axis(i));
  }
  msg.mode = toQuaternionMsg(component.mode());
  msg.normaliser = component.normalizer();
  return msg;
}

BinghamMixtureMsg toBinghamMixtureMsg(const BinghamMixture& mixture) {
  BinghamMixtureMsg msg;
  msg.components.reserve(mixture.size());
  for (std::size_t k = 0; k < mixture.size(); ++k) {
    msg.components.push_back(toBinghamComponentMsg(mixture.weight(k), mixture.component(k)));
  }
  return msg;
}

BinghamDistribution fromBinghamComponentMsg(const BinghamComponentMsg& msg, std::size_t index) {
  const std::string name = componentName(index);
  BinghamDistribution::Axes axes;
  for (int i = 0; i < 3; ++i) {
    const std::string what = "axis " + std::to_string(i) + " of " + name;
    axes.col(i) = fromQuaternionMsg(msg.axes[i], what.c_str());
  }
  const Eigen::Vector3d concentrations(msg.concentrations[0], msg.concentrations[1],
                                       msg.concentrations[2]);
  std::optional<BinghamDistribution> distribution;
  try {
    distribution.emplace(concentrations, axes);
  } catch (const Error& error) {
    throw Error(name + " is not a valid Bingham distribution: " + error.what());
  }
  const std::string mode_name = "the mode of " + name;
  const Eigen::Vector4d mode = fromQuaternionMsg(msg.mode, mode_name.c_str());
  if (std::abs(mode.dot(distribution->mode())) < 1.0 - kTolerance) {
    throw Error("The mode of " + name + " is not orthogonal to its three axes.");
  }
  const double normaliser = distribution->normalizer();
  if (!std::isfinite(msg.normaliser) ||
      std::abs(msg.normaliser - normaliser) > kTolerance * normaliser) {
    std::ostringstream message;
    message.precision(10);
    message << "The normaliser of " << name << " is " << msg.normaliser
            << ", but its concentrations give " << normaliser << ".";
    throw Error(message.str());
  }
  return *distribution;
}

BinghamMixture fromBinghamMixtureMsg(const BinghamMixtureMsg& msg) {
  if (msg.components.empty()) {
    throw Error(
        "The BinghamMixture message has no components (a uniform belief is one "
        "component with zero concentrations).");
  }
  std::vector<double> weights;
  std::vector<BinghamDistribution> components;
  weights.reserve(msg.components.size());
  components.reserve(msg.components.size());
  for (std::size_t k = 0; k < msg.components.size(); ++k) {
    const double weight = msg.components[k].weight;
    if (!std::isfinite(weight) || weight < 0.0) {
      std::ostringstream message;
      message << "The weight of " << componentName(k) << " is " << weight
              << ", but weights must be finite and >= 0.";
      throw Error(message.str());
    }
    weights.push_back(weight);
    components.push_back(fromBinghamComponentMsg(msg.components[k], k));
  }
  try {
    return BinghamMixture(std::move(weights), std::move(components));
  } catch (const Error& error) {
    throw Error(std::string("The BinghamMixture message is not a valid mixture: ") + error.what());
  }
}

}  // namespace vdc
