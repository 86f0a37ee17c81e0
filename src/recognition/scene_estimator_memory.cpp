// SceneEstimator::memory and restoreMemory: the instances a restart carries over
// (scene_memory.h; scene_memory_file.h saves them). Kept apart from scene_estimator.cpp, whose
// subject is the frame update.
#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc {
namespace {

InstanceMemory instanceMemory(const ObjectInstance& instance, const ModelLibrary& library) {
  InstanceMemory m;
  m.id = instance.id;
  m.model = library.models()[instance.model].name;
  m.name = instance.name;
  const std::size_t models = library.models().size();
  for (std::size_t i = 0; i < instance.identity.size(); ++i) {
    if (i < models) {
      m.identity[library.models()[i].name] = instance.identity[i];
    } else {
      m.identity_unknown = instance.identity[i];  // "unknown" is last
    }
  }
  m.identity_probability = instance.identity_probability;
  m.centroid_world = instance.centroid_world;
  m.last_seen = instance.last_seen;
  m.frames_seen = instance.frames_seen;
  m.gone = instance.presence.state == InstanceState::kGone;
  m.absent_frames = instance.presence.absent_frames;
  m.gone_since = instance.presence.gone_since;
  m.estimator = instance.estimator->snapshot();
  return m;
}

// The identity in the library's order, "unknown" last: a model the memory has no probability
// for (added to the library since) gets 0, one no longer in the library is left out.
std::vector<double> identityOf(const InstanceMemory& m, const ModelLibrary& library) {
  std::vector<double> identity;
  for (const LibraryModel& model : library.models()) {
    const auto found = m.identity.find(model.name);
    identity.push_back(found == m.identity.end() ? 0.0 : found->second);
  }
  identity.push_back(m.identity_unknown);
  return identity;
}

// n of a name "<model>_<n>", 0 for any other name.
int nameNumber(const std::string& name, const std::string& model) {
  const std::string prefix = model + "_";
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return 0;
  const std::string digits = name.substr(prefix.size());
  if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return 0;
  return std::stoi(digits);
}

}  // namespace

SceneMemory SceneEstimator::memory() const {
  SceneMemory memory;
  for (const ObjectInstance& instance : instances_) {
    memory.instances.push_back(instanceMemory(instance, library_));
  }
  memory.next_id = next_id_;
  for (int m = 0; m < library_.size(); ++m) {
    memory.instances_named[library_.models()[m].name] = instances_named_[m];
  }
  return memory;
}

void SceneEstimator::restoreMemory(const SceneMemory& memory) {
  // Everything is built into temporaries first, so a refused memory changes nothing.
  std::vector<ObjectInstance> instances;
  std::set<int> ids;
  std::set<std::string> names;
  for (const InstanceMemory& m : memory.instances) {
    const std::string what = "instance " + std::to_string(m.id) + " (" + m.name + ")";
    const int model = library_.find(m.model);
    if (model < 0) throw Error(what + " is a '" + m.model + "', which is no model of the library");
    if (!ids.insert(m.id).second) throw Error(what + ": its id is repeated");
    if (!names.insert(m.name).second) throw Error(what + ": its name is repeated");
    if (m.id < 1 || m.id >= memory.next_id) {
      throw Error(what + ": its id is not in [1, next_id = " + std::to_string(memory.next_id) +
                  "), so a new instance could reuse it");
    }
    if (m.frames_seen < 0) throw Error(what + ": frames_seen is negative");
    if (m.absent_frames < 0) throw Error(what + ": absent_frames is negative");
    ObjectInstance instance;
    instance.id = m.id;
    instance.model = model;
    instance.name = m.name;
    instance.estimator = std::make_unique<OrientationEstimator>(library_.models()[model].bundle,
                                                                parameters_.instance);
    try {
      instance.estimator->restore(m.estimator);
    } catch (const Error& error) {
      throw Error(what + ": " + error.what());
    }
    instance.identity = identityOf(m, library_);
    instance.identity_probability = m.identity_probability;
    instance.centroid_world = m.centroid_world;
    instance.last_seen = m.last_seen;
    instance.frames_seen = m.frames_seen;
    instance.presence.state = m.gone ? InstanceState::kGone : InstanceState::kPresent;
    instance.presence.absent_frames = m.absent_frames;
    instance.presence.gone_since = m.gone_since;
    instances.push_back(std::move(instance));
  }
  std::vector<int> named(library_.size(), 0);
  for (int m = 0; m < library_.size(); ++m) {
    const auto found = memory.instances_named.find(library_.models()[m].name);
    if (found == memory.instances_named.end()) continue;
    if (found->second < 0) throw Error("instances_named of " + found->first + " is negative");
    named[m] = found->second;
  }
  // A new instance must not be named like a remembered one, whatever the counters say.
  for (const ObjectInstance& instance : instances) {
    const int n = nameNumber(instance.name, library_.models()[instance.model].name);
    named[instance.model] = std::max(named[instance.model], n);
  }
  instances_ = std::move(instances);
  instances_named_ = std::move(named);
  next_id_ = memory.next_id;
  unknowns_.clear();
  last_segmented_camera_.reset();
}

}  // namespace vdc
