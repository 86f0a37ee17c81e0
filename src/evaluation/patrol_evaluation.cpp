#include "view_direction_classification/evaluation/patrol_evaluation.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <utility>

#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/patrol_truth.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc {
namespace {

// The changes' generator draws from its own sequence, so that a change of the noise (or of the
// number of views) does not change what happens on the table.
constexpr std::uint32_t kChangeSeedOffset = 0x9e3779b9u;
// [m] How far above the arc's last pose the camera looks away: far enough that the estimator
// takes the frame as a new one (min_camera_translation).
constexpr double kLookAwayLift = 1.0;

PatrolChangeSource randomChanges(const std::vector<SceneEvaluationModel>& models,
                                 const PatrolSettings& settings) {
  auto rng = std::make_shared<std::mt19937>(settings.seed ^ kChangeSeedOffset);
  auto known = std::make_shared<const std::vector<KnownModel>>(knownModelsOf(models));
  const PatrolChangeSettings changes = settings.changes;
  return [rng, known, changes](int, PatrolScene* scene) {
    return applyRandomChanges(*known, changes, *rng, scene);
  };
}

// Everything the patrol keeps between views.
class Patrol {
 public:
  Patrol(const std::vector<SceneEvaluationModel>& models,
         const std::vector<TriangleMesh>& distractors, const PatrolSettings& settings)
      : settings_(settings),
        intrinsics_(intrinsicsOf(models.front().bundle->parameters)),
        scene_(patrolSceneOf(generateTableScene(knownModelsOf(models), distractors,
                                                settings.generation, settings.seed))),
        estimator_(libraryOf(models), settings.estimator),
        noise_rng_(settings.seed) {}

  PatrolScene* scene() { return &scene_; }
  PatrolResult& result() { return result_; }

  // Follows the changes made before `pass` from now on.
  void recordChanges(int pass, const std::vector<PatrolChange>& changes) {
    for (const PatrolChange& change : changes) {
      if (change.kind == PatrolChangeKind::kDistractorMoved) continue;
      for (ChangeNotice& notice : result_.notices) {
        if (notice.object == change.object && !notice.noticed) notice.superseded = true;
      }
      if (change.kind != PatrolChangeKind::kAdded) {
        vacated_[change.object] = {change.object, change.model, change.from, 0.0};
      }
      result_.notices.push_back({pass, change.kind, change.object, change.model});
    }
  }

  PatrolPassRecord runPass(int pass, const std::function<void()>& view_done) {
    PatrolPassRecord record;
    record.pass = pass;
    std::vector<int> ids;
    const TableScene present = presentScene(scene_, &ids);
    const TableSceneRenderer renderer(present, intrinsics_);
    const PatrolTruthRenderer truths(scene_, present, ids, vacatedPlaces(), intrinsics_);
    std::vector<double> times;
    for (const Eigen::Isometry3d& world_from_camera : scene_.world_from_camera) {
      times.push_back(feedView(renderer, truths, world_from_camera, &record));
      view_done();
    }
    lookAway();
    record.views = static_cast<int>(times.size());
    record.mean_time_ms = std::accumulate(times.begin(), times.end(), 0.0) / times.size();
    record.max_time_ms = *std::max_element(times.begin(), times.end());
    countMemory(&record);
    return record;
  }

 private:
  // Renders one view, feeds it and scores the memory after it; returns the update's time [ms].
  double feedView(const TableSceneRenderer& renderer, const PatrolTruthRenderer& truths,
                  const Eigen::Isometry3d& world_from_camera, PatrolPassRecord* record) {
    const SceneView view =
        renderer.render(world_from_camera, DepthNoiseModel{settings_.noise}, &noise_rng_);
    const auto start = std::chrono::steady_clock::now();
    estimator_.update(view.cloud, world_from_camera, time_++);
    const double time_ms = millisecondsSince(start);
    const PatrolTruth truth = truths.truth(view, world_from_camera);
    record->metrics = patrolMemoryMetrics(truth, confirmedEstimates(estimator_), settings_.metrics);
    record->max_duplicates = std::max(record->max_duplicates, record->metrics.duplicates);
    record->max_stale = std::max(record->max_stale, record->metrics.stale);
    followNotices(truth, record->metrics);
    return time_ms;
  }

  std::vector<VacatedPlace> vacatedPlaces() const {
    std::vector<VacatedPlace> places;
    for (const auto& entry : vacated_) places.push_back(entry.second);
    return places;
  }

  void followNotices(const PatrolTruth& truth, const PatrolMemoryMetrics& metrics) {
    for (ChangeNotice& notice : result_.notices) {
      advanceNotice(changeReflected(notice, truth, metrics),
                    changePlaceSeen(notice, truth, settings_.metrics), &notice);
    }
  }

  // A frame without points from a pose away from the table: the robot turned to elsewhere. It
  // is evidence of nothing, and makes the next pass's first view a new frame to the estimator.
  void lookAway() {
    Eigen::Isometry3d away = scene_.world_from_camera.back();
    away.translation().z() += kLookAwayLift;
    estimator_.update(pcl::PointCloud<pcl::PointXYZ>(), away, time_++);
  }

  void countMemory(PatrolPassRecord* record) const {
    record->objects_ever = static_cast<int>(scene_.objects.size());
    for (const ObjectInstance& instance : estimator_.instances()) {
      ++record->instances;
      if (instance.presence.state == InstanceState::kGone) ++record->gone_instances;
    }
  }

  const PatrolSettings& settings_;
  CameraIntrinsics intrinsics_;
  PatrolScene scene_;
  SceneEstimator estimator_;
  std::mt19937 noise_rng_;
  double time_ = 0.0;                    // [s] one per frame
  std::map<int, VacatedPlace> vacated_;  // per object id: the last place it left
  PatrolResult result_;
};

}  // namespace

void checkPatrolSettings(const PatrolSettings& settings) {
  if (settings.passes < 1) throw Error("patrol: passes must be at least 1");
  checkSceneGenerationSettings(settings.generation);
  checkPatrolChangeSettings(settings.changes);
  checkPatrolMetricSettings(settings.metrics);
  checkSceneEstimatorParameters(settings.estimator);
}

PatrolResult evaluatePatrol(const std::vector<SceneEvaluationModel>& models,
                            const std::vector<TriangleMesh>& distractors,
                            const PatrolSettings& settings, const PatrolProgress& progress,
                            PatrolChangeSource changes) {
  checkPatrolSettings(settings);
  if (models.empty()) throw Error("patrol: the library has no model");
  if (!changes) changes = randomChanges(models, settings);
  Patrol patrol(models, distractors, settings);
  const int total = settings.passes * settings.generation.views;
  int done = 0;
  const auto view_done = [&] {
    if (progress) progress(++done, total);
  };
  for (int pass = 1; pass <= settings.passes; ++pass) {
    std::vector<PatrolChange> made;
    if (pass > 1) made = changes(pass, patrol.scene());
    patrol.recordChanges(pass, made);
    PatrolPassRecord record = patrol.runPass(pass, view_done);
    record.changes = std::move(made);
    patrol.result().passes.push_back(std::move(record));
  }
  return std::move(patrol.result());
}

}  // namespace vdc
