#pragma once

#include <Eigen/Core>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/estimation/estimator_snapshot.h"

namespace vdc {

// One ObjectInstance as a restart needs it back. Models are named, not indexed: the library of
// the next run may list them in another order.
struct InstanceMemory {
  int id = 0;
  std::string model;  // the library model's name
  std::string name;   // "<model>_<n>"
  // Identification's probability per model name, and of "unknown" (ObjectInstance::identity).
  std::map<std::string, double> identity;
  double identity_unknown = 0.0;
  double identity_probability = 0.0;
  Eigen::Vector3d centroid_world = Eigen::Vector3d::Zero();
  std::optional<double> last_seen;
  int frames_seen = 0;
  // ObjectInstance::presence: gone (its place seen free), frames of absence in a row, since when.
  bool gone = false;
  int absent_frames = 0;
  std::optional<double> gone_since;
  EstimatorSnapshot estimator;
};

// What a SceneEstimator remembers of its objects (doc/method.md, "Object memory"): the
// instances, and the counters that keep new instances from reusing an id or a name.
struct SceneMemory {
  std::vector<InstanceMemory> instances;
  int next_id = 1;
  std::map<std::string, int> instances_named;  // per model name: instances named so far
};

}  // namespace vdc
