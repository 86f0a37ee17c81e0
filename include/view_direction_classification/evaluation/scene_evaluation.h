#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "view_direction_classification/evaluation/scene_generation.h"
#include "view_direction_classification/evaluation/scene_metrics.h"
#include "view_direction_classification/recognition/scene_estimator.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// Recognising every known object of cluttered table scenes with the scene layer: each seeded
// scene's views are fed in order to one SceneEstimator, and after each view its confirmed
// instances are scored against the truth (sceneViewMetrics).

// A library entry: the name estimates carry, its trained bundle and the mesh the scenes place
// (the bundle's object frame must be the mesh's).
struct SceneEvaluationModel {
  std::string name;
  std::shared_ptr<const ModelBundle> bundle;
  TriangleMesh mesh;
};

struct SceneEvaluationSettings {
  int scenes = 10;
  std::uint32_t seed = 1;  // scene s is generated with seed + s, its noise drawn from that too
  bool noise = true;
  DepthSensor sensor = DepthSensor::kKinectGaussian;  // imitated when noise is on
  SceneGenerationSettings generation;  // its `views` is the number of views per scene
  SceneMetricSettings metrics;
  // The node's defaults: each instance's estimator is EstimatorParameters{}.
  SceneEstimatorParameters estimator;
};

// The library of the models (their names and bundles), and the models as the scene generator
// places them (their names and meshes); shared with the patrol evaluation.
ModelLibrary libraryOf(const std::vector<SceneEvaluationModel>& models);
std::vector<KnownModel> knownModelsOf(const std::vector<SceneEvaluationModel>& models);

// Throws vdc::Error naming the first bad setting.
void checkSceneEvaluationSettings(const SceneEvaluationSettings& settings);

// Why a false identification is false, read off the truth (for the failure analysis).
enum class FalseIdentificationKind {
  kOnDistractor,  // on an unknown object
  kWrongModel,    // near a known object of another model
  kDuplicate,     // near a known object of its model, already identified or too far off
  kElsewhere,     // near nothing the scene holds (the table, a fragment)
};
const char* falseIdentificationKindName(FalseIdentificationKind kind);

// One view of one scene, after the estimator fused it.
struct SceneViewRecord {
  int scene = 0;  // 0-based
  int view = 1;   // 1-based: the number of views fed so far
  ViewTruth truth;
  std::vector<InstanceEstimate> estimates;  // the confirmed instances
  SceneViewMetrics metrics;
  std::vector<FalseIdentificationKind> false_kinds;  // per metrics.false_identifications
  std::vector<int> missed;  // visible known objects no estimate identified (into truth.known)
  int candidates = 0;       // segmentation's candidates on this view
  int new_instances = 0;    // candidates identified as a new instance on this view
  int models = 0;           // in the library
  bool segmented = false;
  double time_ms = 0.0;  // SceneEstimator::update, wall clock
  double segmentation_ms = 0.0;
  SceneStageTimes stage_ms;  // the rest of a segmented view's time, stage by stage
};

// Called after each view: views done and the total.
using SceneEvaluationProgress = std::function<void(int done, int total)>;

// Runs every scene; deterministic but for the times. Throws vdc::Error for bad settings, an
// empty library, or a scene the generator cannot place.
std::vector<SceneViewRecord> evaluateScenes(const std::vector<SceneEvaluationModel>& models,
                                            const std::vector<TriangleMesh>& distractors,
                                            const SceneEvaluationSettings& settings,
                                            const SceneEvaluationProgress& progress = {});

// The estimator's confirmed instances as estimates (MAP orientation, position estimate, cone90).
std::vector<InstanceEstimate> confirmedEstimates(const SceneEstimator& estimator);

// The visible known objects (above settings.visible_fraction) that metrics did not identify.
std::vector<int> missedObjects(const ViewTruth& truth, const SceneViewMetrics& metrics,
                               const SceneMetricSettings& settings);

// Each false identification's kind: within `near` [m] of a known object's origin counts as near.
std::vector<FalseIdentificationKind> classifyFalseIdentifications(
    const ViewTruth& truth, const std::vector<InstanceEstimate>& estimates,
    const SceneViewMetrics& metrics, double near = 0.05);

}  // namespace vdc
