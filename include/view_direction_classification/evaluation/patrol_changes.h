#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <random>
#include <string>
#include <vector>

#include "view_direction_classification/evaluation/scene_generation.h"

namespace vdc {

// A table that changes while a robot patrols it (evaluation/patrol_evaluation.h): between two
// passes of the camera, known objects are moved, taken away or put (back) on the table, and
// distractors are moved. The objects keep their ids over the patrol, so that what the object
// memory says after a change can be checked against each object's history.

// A known object of the patrol.
struct PatrolObject {
  int id = 0;                // stable over the patrol, unique
  PlacedKnownObject placed;  // its model and pose (the last one it had, when removed)
  bool present = true;
};

struct PatrolScene {
  Eigen::Vector2d table_size = Eigen::Vector2d(1.2, 0.8);
  std::vector<PatrolObject> objects;  // every known object that was ever on the table
  std::vector<ScenePart> distractors;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // what the views look at, fixed
  std::vector<Eigen::Isometry3d> world_from_camera;  // one pass's arc
};

// The generated scene with every known object present, ids 0, 1, ...
PatrolScene patrolSceneOf(const TableScene& scene);

// The present objects and the distractors as a scene to render; *ids (if given) gets each known
// object's id, in the scene's order.
TableScene presentScene(const PatrolScene& scene, std::vector<int>* ids = nullptr);

enum class PatrolChangeKind {
  kMoved,            // a known object slid and turned on the table
  kRemoved,          // a known object taken away
  kAdded,            // one taken away put back, or a new object of a library model
  kDistractorMoved,  // an unknown object slid and turned
};
const char* patrolChangeKindName(PatrolChangeKind kind);

struct PatrolChange {
  PatrolChangeKind kind = PatrolChangeKind::kMoved;
  int object = -1;    // the known object's id, or the distractor's index
  std::string model;  // the known object's model (empty for a distractor)
  // The pose it left (moved, removed) and the pose it got (moved, added); for a removal `to`,
  // for an addition `from`, is the same pose.
  Eigen::Isometry3d from = Eigen::Isometry3d::Identity(), to = Eigen::Isometry3d::Identity();
};

struct PatrolChangeSettings {
  int changes = 2;                          // per round
  double min_move = 0.03, max_move = 0.30;  // [m] a move's distance on the table
  double distractor_share = 0.2;            // probability that a change moves a distractor instead
  // [m] about the scene's centre: where moved and added objects may go, so that the arc that
  // looked at the table first still sees them.
  double place_radius = 0.3;
  double gap = 0.002;  // [m] kept between footprints, as the generator's contact gap
  int attempts = 200;  // free places tried per change
};

// Throws vdc::Error naming the first bad setting.
void checkPatrolChangeSettings(const PatrolChangeSettings& settings);

// Applies settings.changes random changes to *scene, each object changed at most once, and
// returns them in order. A move or an addition that finds no free place in settings.attempts
// tries becomes a removal (of a present object) or is dropped, so fewer changes may be returned.
// Known objects added anew are of `models`, in their mesh frame standing on the table.
// Deterministic in (scene, models, settings, the rng's state).
std::vector<PatrolChange> applyRandomChanges(const std::vector<KnownModel>& models,
                                             const PatrolChangeSettings& settings,
                                             std::mt19937& rng, PatrolScene* scene);

}  // namespace vdc
