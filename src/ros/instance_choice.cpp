#include "instance_choice.h"

#include <cmath>
#include <limits>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// An instance's spread for kMostUncertain: a NaN cone (no spread known) counts as the widest,
// so an instance the estimator cannot judge is looked at rather than ignored.
double spreadOf(const ObjectInstanceMsg& instance) {
  return std::isnan(instance.cone90_deg) ? std::numeric_limits<double>::infinity()
                                         : instance.cone90_deg;
}

bool gone(const ObjectInstanceMsg& instance) { return instance.state == ObjectInstanceMsg::GONE; }

// Among the instances present: a gone one's place was seen free, no view of it helps.
const ObjectInstanceMsg* mostUncertain(const ObjectInstancesMsg& latest) {
  const ObjectInstanceMsg* chosen = nullptr;
  for (const ObjectInstanceMsg& instance : latest.instances) {
    if (gone(instance)) continue;
    if (chosen == nullptr) {
      chosen = &instance;
      continue;
    }
    const double spread = spreadOf(instance), chosen_spread = spreadOf(*chosen);
    if (spread > chosen_spread || (spread == chosen_spread && instance.id < chosen->id)) {
      chosen = &instance;
    }
  }
  return chosen;
}

std::string knownNames(const ObjectInstancesMsg& latest) {
  std::string names;
  for (const ObjectInstanceMsg& instance : latest.instances) {
    names += (names.empty() ? "" : ", ") + instance.name;
  }
  return names;
}

}  // namespace

const ObjectInstanceMsg& chooseInstance(const ObjectInstancesMsg* latest,
                                        const std::string& wanted) {
  const std::string nothing_to_plan = ", so there is no instance '" + wanted + "' to plan for.";
  if (latest == nullptr) {
    throw Error("No instances received yet on the server's `instances` topic" + nothing_to_plan);
  }
  if (latest->instances.empty()) {
    throw Error("The latest instances message has no instance" + nothing_to_plan);
  }
  if (wanted == kMostUncertain) {
    const ObjectInstanceMsg* chosen = mostUncertain(*latest);
    if (chosen == nullptr) {
      throw Error("Every instance of the latest instances message is gone" + nothing_to_plan);
    }
    return *chosen;
  }
  for (const ObjectInstanceMsg& instance : latest->instances) {
    if (instance.name != wanted) continue;
    if (gone(instance)) {
      throw Error("Instance '" + wanted +
                  "' is gone: the camera saw its place free, so there is no view to plan for it.");
    }
    return instance;
  }
  throw Error("Unknown instance '" + wanted + "': the latest instances are " + knownNames(*latest) +
              " (or ask for \"" + kMostUncertain + "\").");
}

void LatestInstances::keep(const ObjectInstancesMsg& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  latest_ = message;
}

ObjectInstanceMsg LatestInstances::choose(const std::string& wanted) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return chooseInstance(latest_ ? &*latest_ : nullptr, wanted);
}

}  // namespace vdc
