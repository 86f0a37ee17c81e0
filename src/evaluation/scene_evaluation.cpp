#include "view_direction_classification/evaluation/scene_evaluation.h"

#include <chrono>
#include <cmath>
#include <random>
#include <utility>

#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc {
namespace {

void countCandidates(const SceneUpdate& update, SceneViewRecord* record) {
  record->segmented = update.segmented;
  record->segmentation_ms = update.segmentation_ms;
  record->stage_ms = update.stage_ms;
  record->candidates = static_cast<int>(update.candidates.size());
  for (const CandidateOutcome& candidate : update.candidates) {
    if (candidate.new_instance) ++record->new_instances;
  }
}

// Feeds one scene's views in order to a fresh estimator and records each.
void evaluateScene(int scene_index, const std::vector<SceneEvaluationModel>& models,
                   const std::vector<TriangleMesh>& distractors,
                   const SceneEvaluationSettings& settings, std::vector<SceneViewRecord>* records,
                   const std::function<void()>& view_done) {
  const std::uint32_t seed = settings.seed + static_cast<std::uint32_t>(scene_index);
  const TableScene scene =
      generateTableScene(knownModelsOf(models), distractors, settings.generation, seed);
  // The camera the models were trained for: the scene layer compares its clouds with theirs.
  const TableSceneRenderer renderer(scene, intrinsicsOf(models.front().bundle->parameters));
  SceneEstimator estimator(libraryOf(models), settings.estimator);
  std::mt19937 rng(seed);
  for (std::size_t v = 0; v < scene.world_from_camera.size(); ++v) {
    const Eigen::Isometry3d& world_from_camera = scene.world_from_camera[v];
    const SceneView view = renderer.render(
        world_from_camera, DepthNoiseModel{settings.noise, sensorModel(settings.sensor)}, &rng);
    SceneViewRecord record;
    record.scene = scene_index;
    record.view = static_cast<int>(v) + 1;
    record.models = static_cast<int>(models.size());
    const auto start = std::chrono::steady_clock::now();
    const SceneUpdate update =
        estimator.update(view.cloud, world_from_camera, static_cast<double>(v));
    record.time_ms = millisecondsSince(start);
    countCandidates(update, &record);
    record.truth = viewTruth(scene, view);
    record.estimates = confirmedEstimates(estimator);
    record.metrics = sceneViewMetrics(record.truth, record.estimates, settings.metrics);
    record.false_kinds =
        classifyFalseIdentifications(record.truth, record.estimates, record.metrics);
    record.missed = missedObjects(record.truth, record.metrics, settings.metrics);
    records->push_back(std::move(record));
    view_done();
  }
}

}  // namespace

ModelLibrary libraryOf(const std::vector<SceneEvaluationModel>& models) {
  std::vector<std::pair<std::string, std::shared_ptr<const ModelBundle>>> entries;
  for (const SceneEvaluationModel& model : models) entries.emplace_back(model.name, model.bundle);
  return ModelLibrary(std::move(entries));
}

std::vector<KnownModel> knownModelsOf(const std::vector<SceneEvaluationModel>& models) {
  std::vector<KnownModel> known;
  for (const SceneEvaluationModel& model : models) known.push_back({model.name, model.mesh});
  return known;
}

void checkSceneEvaluationSettings(const SceneEvaluationSettings& settings) {
  if (settings.scenes < 1) throw Error("scene evaluation: scenes must be at least 1");
  checkSceneGenerationSettings(settings.generation);
  checkSceneEstimatorParameters(settings.estimator);
  if (!(settings.metrics.visible_fraction >= 0.0) || !(settings.metrics.match_distance >= 0.0)) {
    throw Error("scene evaluation: visible fraction and match distance must be >= 0");
  }
}

const char* falseIdentificationKindName(FalseIdentificationKind kind) {
  switch (kind) {
    case FalseIdentificationKind::kOnDistractor:
      return "distractor";
    case FalseIdentificationKind::kWrongModel:
      return "wrong_model";
    case FalseIdentificationKind::kDuplicate:
      return "duplicate";
    case FalseIdentificationKind::kElsewhere:
      return "elsewhere";
  }
  return "?";
}

std::vector<InstanceEstimate> confirmedEstimates(const SceneEstimator& estimator) {
  std::vector<InstanceEstimate> estimates;
  for (const ObjectInstance& instance : estimator.instances()) {
    const std::optional<Eigen::Isometry3d> pose = believedPose(*instance.estimator);
    if (!estimator.confirmed(instance) || !pose) continue;
    InstanceEstimate estimate;
    estimate.model = estimator.library().models()[instance.model].name;
    estimate.world_from_object = *pose;
    estimate.cone90_deg = instance.estimator->spread().cone90 * 180.0 / M_PI;
    estimate.identity_probability = instance.identity_probability;
    estimates.push_back(estimate);
  }
  return estimates;
}

std::vector<int> missedObjects(const ViewTruth& truth, const SceneViewMetrics& metrics,
                               const SceneMetricSettings& settings) {
  std::vector<bool> identified(truth.known.size(), false);
  for (const IdentifiedInstance& instance : metrics.identified) identified[instance.truth] = true;
  std::vector<int> missed;
  for (std::size_t k = 0; k < truth.known.size(); ++k) {
    if (!identified[k] && truth.known[k].visible_fraction > settings.visible_fraction) {
      missed.push_back(static_cast<int>(k));
    }
  }
  return missed;
}

std::vector<FalseIdentificationKind> classifyFalseIdentifications(
    const ViewTruth& truth, const std::vector<InstanceEstimate>& estimates,
    const SceneViewMetrics& metrics, double near) {
  std::vector<FalseIdentificationKind> kinds;
  for (const FalseIdentification& false_identification : metrics.false_identifications) {
    if (false_identification.on_distractor) {
      kinds.push_back(FalseIdentificationKind::kOnDistractor);
      continue;
    }
    const InstanceEstimate& estimate = estimates[false_identification.estimate];
    // The nearest known object decides: a wrong model on it, or a second estimate of its model.
    const KnownObjectTruth* nearest = nullptr;
    double nearest_distance = near;
    for (const KnownObjectTruth& object : truth.known) {
      const double distance =
          (object.world_from_object.translation() - estimate.world_from_object.translation())
              .norm();
      if (distance <= nearest_distance) nearest = &object, nearest_distance = distance;
    }
    if (nearest == nullptr) {
      kinds.push_back(FalseIdentificationKind::kElsewhere);
    } else {
      kinds.push_back(nearest->model == estimate.model ? FalseIdentificationKind::kDuplicate
                                                       : FalseIdentificationKind::kWrongModel);
    }
  }
  return kinds;
}

std::vector<SceneViewRecord> evaluateScenes(const std::vector<SceneEvaluationModel>& models,
                                            const std::vector<TriangleMesh>& distractors,
                                            const SceneEvaluationSettings& settings,
                                            const SceneEvaluationProgress& progress) {
  checkSceneEvaluationSettings(settings);
  if (models.empty()) throw Error("scene evaluation: the library has no model");
  std::vector<SceneViewRecord> records;
  const int total = settings.scenes * settings.generation.views;
  int done = 0;
  const auto view_done = [&] {
    if (progress) progress(++done, total);
  };
  for (int s = 0; s < settings.scenes; ++s) {
    evaluateScene(s, models, distractors, settings, &records, view_done);
  }
  return records;
}

}  // namespace vdc
