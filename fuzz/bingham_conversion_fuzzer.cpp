// libFuzzer target: view_direction_classification/BinghamMixture -> the core's BinghamMixture
// (vdc::fromBinghamMixtureMsg), as the server converts the estimator's ~estimate and a
// next-best-view request's belief, followed by what the server computes from it first (the MAP
// orientation). A refused message must throw vdc::Error; an accepted one must give a unit MAP
// orientation and survive the round trip back to a message and again to the core.

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "fuzzed_messages.h"
#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/ros/bingham_conversions.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  const vdc::BinghamMixtureMsg msg = vdc::fuzz::fuzzedBinghamMixtureMsg(data);
  vdc::BinghamMixture mixture;
  try {
    mixture = vdc::fromBinghamMixtureMsg(msg);
  } catch (const vdc::Error&) {
    return 0;  // refused with a message: what the server logs or answers
  }
  const Eigen::Vector4d map = vdc::mapEstimate(mixture);
  if (!map.allFinite() || std::abs(map.norm() - 1.0) > 1e-6) std::abort();
  // What the core accepted, written as a message, is accepted again with the same components.
  const vdc::BinghamMixture again = vdc::fromBinghamMixtureMsg(vdc::toBinghamMixtureMsg(mixture));
  if (again.size() != mixture.size()) std::abort();
  for (std::size_t k = 0; k < mixture.size(); ++k) {
    if (again.component(k).concentrations() != mixture.component(k).concentrations()) std::abort();
  }
  return 0;
}
