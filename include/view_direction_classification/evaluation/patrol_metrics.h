#pragma once

#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "view_direction_classification/evaluation/patrol_changes.h"
#include "view_direction_classification/evaluation/scene_metrics.h"

namespace vdc {

// What the object memory (the scene estimator's confirmed instances) says about a patrolled table
// after a view, against the truth: which present objects it has right, which it holds twice,
// which places it still fills with an object that left them, and when it took in each change.

struct PatrolMetricSettings {
  double match_distance = 0.02;     // [m] a right instance: position within this ...
  double match_rotation_deg = 5.0;  // ... and rotation within this of a present object
  double near = 0.05;               // [m] an instance this close to an object's origin is on it
  double visible_fraction = 0.3;    // an object (or a free place) counts as seen above this
};

// Throws vdc::Error naming the first bad setting.
void checkPatrolMetricSettings(const PatrolMetricSettings& settings);

// A place a known object left (moved away or taken away): an instance of its model still
// confirmed there is stale.
struct VacatedPlace {
  int object = -1;  // the object's id
  std::string model;
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  double visible_fraction = 0.0;  // of the object at this place, were it there (seen free)
};

struct PatrolTruth {
  std::vector<KnownObjectTruth> present;  // the present known objects
  std::vector<int> ids;                   // their ids, per present
  std::vector<VacatedPlace> vacated;      // each object's last place left, if it has one
};

struct PatrolMemoryMetrics {
  int present = 0;  // known objects on the table
  int confirmed = 0;
  int right = 0;       // present objects with a right instance (one to one)
  int duplicates = 0;  // confirmed instances on a present object beyond its first
  int stale = 0;       // confirmed instances on a vacated place and on no present object of
                       // their model
  std::vector<bool> object_right;  // per present
  std::vector<bool> place_stale;   // per vacated
};

// The memory's state against the truth. Throws vdc::Error for bad settings.
PatrolMemoryMetrics patrolMemoryMetrics(const PatrolTruth& truth,
                                        const std::vector<InstanceEstimate>& confirmed,
                                        const PatrolMetricSettings& settings = {});

// One change to a known object followed over the views after it.
struct ChangeNotice {
  int pass = 0;  // the pass it was seen first on (1-based; it happened before that pass)
  PatrolChangeKind kind = PatrolChangeKind::kMoved;
  int object = -1;
  std::string model;
  int views = 0;        // views fed since the change, up to its notice
  int place_views = 0;  // of those, views that saw its place (free, or the object moved there)
  bool noticed = false;
  bool superseded = false;  // the object changed again before the memory took it in
};

// Whether the memory reflects the change: a removal when no instance is stale at its place, a
// move when the object is right at its new place and none stale at the old one, an addition
// when the object is right. `truth` and `metrics` are of the same view.
bool changeReflected(const ChangeNotice& notice, const PatrolTruth& truth,
                     const PatrolMemoryMetrics& metrics);

// Whether the view saw the change's place: the free place of a removal, the new place of a move
// or an addition (visible above settings.visible_fraction).
bool changePlaceSeen(const ChangeNotice& notice, const PatrolTruth& truth,
                     const PatrolMetricSettings& settings);

// Counts one view into a change not noticed yet; `reflected` and `place_seen` of that view.
void advanceNotice(bool reflected, bool place_seen, ChangeNotice* notice);

}  // namespace vdc
