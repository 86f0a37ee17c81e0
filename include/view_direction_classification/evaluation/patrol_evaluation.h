#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "view_direction_classification/evaluation/patrol_changes.h"
#include "view_direction_classification/evaluation/patrol_metrics.h"
#include "view_direction_classification/evaluation/scene_evaluation.h"
#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc {

// The object memory over time (issue 30 item 6): a robot patrols a seeded table scene. On each
// pass the camera goes along the scene's arc, feeding its views to one SceneEstimator, then
// looks away (a frame without points), and before the next pass a few known objects are moved,
// taken away or put on the table and distractors moved (applyRandomChanges). After every view
// the confirmed instances are scored against the table as it is (patrolMemoryMetrics), and each
// change to a known object is followed until the memory reflects it (ChangeNotice).

struct PatrolSettings {
  int passes = 6;
  std::uint32_t seed = 1;  // the scene, its noise and its changes
  bool noise = true;
  SceneGenerationSettings generation;  // its `views` is the number of views per pass
  PatrolChangeSettings changes;        // its `changes` is the number per pass after the first
  PatrolMetricSettings metrics;
  SceneEstimatorParameters estimator;  // the node's defaults
};

// Throws vdc::Error naming the first bad setting.
void checkPatrolSettings(const PatrolSettings& settings);

// One pass, after its last view.
struct PatrolPassRecord {
  int pass = 1;  // 1-based
  int views = 0;
  std::vector<PatrolChange> changes;      // made before this pass
  PatrolMemoryMetrics metrics;            // after its last view
  int max_duplicates = 0, max_stale = 0;  // over its views
  int instances = 0;                      // the memory's size: instances kept, gone ones included
  int gone_instances = 0;                 // of those, marked gone
  int objects_ever = 0;  // known objects that were on the table at some time, this pass's too
  double mean_time_ms = 0.0, max_time_ms = 0.0;  // SceneEstimator::update per arc view
};

struct PatrolResult {
  std::vector<PatrolPassRecord> passes;
  std::vector<ChangeNotice> notices;  // per change to a known object, in the order made
};

// The changes made before pass `pass` (2, 3, ...): applied to *scene and returned. The
// default is applyRandomChanges with the settings' changes and a seeded generator; a test
// scripts its own.
using PatrolChangeSource = std::function<std::vector<PatrolChange>(int pass, PatrolScene* scene)>;

// Called after each view: views done and the total.
using PatrolProgress = std::function<void(int done, int total)>;

// Runs the patrol; deterministic but for the times. Throws vdc::Error for bad settings, an
// empty library, or a scene the generator cannot place.
PatrolResult evaluatePatrol(const std::vector<SceneEvaluationModel>& models,
                            const std::vector<TriangleMesh>& distractors,
                            const PatrolSettings& settings, const PatrolProgress& progress = {},
                            PatrolChangeSource changes = {});

}  // namespace vdc
