#include "view_direction_classification/evaluation/evaluation.h"

#include <omp.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/geometry/surface_sampling.h"
#include "view_direction_classification/geometry/visibility_crop.h"
#include "view_direction_classification/planning/next_best_view.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc {
namespace {

// Tags that keep the generators of different purposes independent for the same seed.
constexpr std::uint32_t kSequenceStream = 0x5e9u;
constexpr std::uint32_t kNoiseStream = 0x9015eu;
// Spacing of the surface set the visible fractions are measured on (doc/method.md section 1).
constexpr double kFractionSpacing = 0.002;

std::vector<double> visibleFractions(const TriangleMesh& mesh,
                                     const std::vector<Eigen::Vector3d>& anchors,
                                     const EvaluationSettings& settings) {
  const std::vector<double> radii = visibilityRadii(settings);
  std::vector<double> fractions(radii.size(), 1.0);
  bool cropped = false;
  for (const double r : radii) cropped = cropped || r != kAllVisible;
  if (!cropped) return fractions;
  const SurfaceSamples surface = sampleSurface(mesh, kFractionSpacing, settings.seed);
  for (std::size_t k = 0; k < radii.size(); ++k) {
    if (radii[k] != kAllVisible) {
      fractions[k] = surfaceFractionNearAnchors(surface, anchors, radii[k]);
    }
  }
  return fractions;
}

// Index of the next candidate: the random planner takes them in order; a utility planner ranks
// the unused candidates by its utility (the scorer) under the current belief and takes the best.
int chooseCandidate(EvaluationPlanner planner, const ViewUtilityScorer* scorer,
                    const OrientationEstimator& estimator, const EvaluationSequence& sequence,
                    const std::vector<bool>& used, int view, const EvaluationSettings& settings) {
  if (planner == EvaluationPlanner::kRandom || view == 0) return view;
  const Eigen::Isometry3d world_from_object = sequence.worldFromObject();
  std::vector<Eigen::Vector3d> positions;
  std::vector<int> index_of;
  for (std::size_t c = 0; c < sequence.camera_from_object.size(); ++c) {
    if (used[c]) continue;
    positions.push_back(world_from_object * sequence.camera_from_object[c].inverse().translation());
    index_of.push_back(static_cast<int>(c));
  }
  PlanningScene scene;
  // The planner knows only what the estimator knows: its position estimate and its belief.
  scene.object_position = estimator.positionEstimate().value_or(Eigen::Vector3d::Zero());
  scene.belief = estimator.belief();
  scene.orientation = estimator.mapOrientation();
  NextBestViewOptions options;
  options.samples_per_component = settings.samples_per_component;
  options.seed = settings.seed;
  const ViewUtility utility = planner == EvaluationPlanner::kInformativeness
                                  ? ViewUtility::kInformativeness
                                  : ViewUtility::kInformationGain;
  const std::vector<RankedCandidate> ranked =
      rankCandidates(*scorer, positions, utility, scene, options);
  return index_of[static_cast<std::size_t>(ranked.front().index)];
}

struct RunOutput {
  std::vector<double> errors;
  std::vector<int> views_fused;
  std::vector<double> cone90_deg;
  std::vector<double> position_errors_mm;
  std::vector<double> position_mahalanobis;
  int skipped = 0;
  double planning_ms = 0, map_ms = 0;
  UpdateTiming stage_ms;  // sums
  int planned = 0;
};

// sqrt(e^T C^-1 e) of an error e [m] under covariance C [m^2]; NaN without C or for a C that is
// not positive definite.
double mahalanobisDistance(const Eigen::Vector3d& error,
                           const std::optional<Eigen::Matrix3d>& covariance) {
  if (!covariance || !covariance->allFinite()) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::LLT<Eigen::Matrix3d> cholesky(*covariance);
  if (cholesky.info() != Eigen::Success) return std::numeric_limits<double>::quiet_NaN();
  return cholesky.matrixL().solve(error).norm();
}

}  // namespace

void checkEvaluationSettings(const EvaluationSettings& s) {
  if (s.sequences < 1) {
    throw Error("the evaluation needs at least one sequence, got " + std::to_string(s.sequences));
  }
  if (s.views < 1) {
    throw Error("the evaluation needs at least one view per sequence, got " +
                std::to_string(s.views));
  }
  if (s.candidates < s.views) {
    throw Error("the evaluation needs at least as many candidate views (" +
                std::to_string(s.candidates) + ") as views per sequence (" +
                std::to_string(s.views) + ")");
  }
  if (!(s.distance > 0.0) || !std::isfinite(s.distance)) {
    throw Error("the evaluation distance must be positive and finite, got " +
                std::to_string(s.distance) + " m");
  }
  for (const double r : s.visibility_radii) {
    if (!(r > 0.0)) {  // also refuses NaN; infinity is kAllVisible
      throw Error("a visibility radius must be positive, got " + std::to_string(r) + " m");
    }
  }
  if (s.samples_per_component < 0) {
    throw Error("samples per component must not be negative, got " +
                std::to_string(s.samples_per_component));
  }
  if (!(s.stream_rate_hz >= 0.0) || !std::isfinite(s.stream_rate_hz)) {
    throw Error("the stream rate must be >= 0 and finite (0: no stream), got " +
                std::to_string(s.stream_rate_hz) + " Hz");
  }
  if (!(s.stream_dwell_s >= 0.0) || !std::isfinite(s.stream_dwell_s)) {
    throw Error("the stream's dwell time must be >= 0 and finite, got " +
                std::to_string(s.stream_dwell_s) + " s");
  }
  checkCameraPoseError(s.camera_pose_error);
  checkMeshPerturbation(s.mesh_perturbation);
}

TriangleMesh renderedObjectMesh(const TriangleMesh& mesh, const EvaluationSettings& settings) {
  MeshPerturbation perturbation = settings.mesh_perturbation;
  if (!perturbation.any()) return mesh;
  perturbation.seed = settings.seed;
  return perturbMesh(mesh, perturbation);
}

std::vector<double> visibilityRadii(const EvaluationSettings& settings) {
  if (settings.visibility_radii.empty()) return {kAllVisible};
  return settings.visibility_radii;
}

void checkVisibilityAnchors(const std::vector<Eigen::Vector3d>& anchors,
                            const EvaluationSettings& settings) {
  bool cropped = false;
  for (const double r : visibilityRadii(settings)) cropped = cropped || r != kAllVisible;
  if (cropped && anchors.empty()) {
    throw Error("the occlusion settings need at least one visibility anchor point");
  }
  for (const auto& anchor : anchors) {
    if (!anchor.allFinite()) throw Error("a visibility anchor point is not finite");
  }
}

std::string evaluationPlannerName(EvaluationPlanner planner) {
  switch (planner) {
    case EvaluationPlanner::kRandom:
      return "random";
    case EvaluationPlanner::kInformativeness:
      return "informativeness";
    case EvaluationPlanner::kInformationGain:
      return "information_gain";
  }
  return "unknown";
}

Eigen::Isometry3d EvaluationSequence::worldFromObject() const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = quaternionToRotationMatrix(world_from_object);
  return pose;
}

EvaluationSequence makeEvaluationSequence(const EvaluationSettings& settings, int sequence) {
  checkEvaluationSettings(settings);
  std::seed_seq seeds{settings.seed, kSequenceStream, static_cast<std::uint32_t>(sequence)};
  std::mt19937 rng(seeds);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  EvaluationSequence result;
  // Normalised Gaussian vectors are uniform on the sphere (S^3 for the orientation: a uniform
  // random rotation). A zero vector has probability zero; redraw to be safe.
  Eigen::Vector4d q;
  do {
    q = Eigen::Vector4d(gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng));
  } while (q.norm() < 1e-9);
  q.normalize();
  if (q(0) < 0) q = -q;
  result.world_from_object = q;
  result.camera_from_object.reserve(static_cast<std::size_t>(settings.candidates));
  for (int c = 0; c < settings.candidates; ++c) {
    Eigen::Vector3d d;
    do {
      d = Eigen::Vector3d(gaussian(rng), gaussian(rng), gaussian(rng));
    } while (d.norm() < 1e-9);
    const double roll = angle(rng);
    result.camera_from_object.push_back(cameraFromObject(d.normalized(), settings.distance, roll));
  }
  return result;
}

pcl::PointCloud<pcl::PointXYZ> renderEvaluationView(const DepthRenderer& renderer,
                                                    const EvaluationSettings& settings,
                                                    int sequence, int candidate,
                                                    const Eigen::Isometry3d& camera_from_object,
                                                    const std::vector<Eigen::Vector3d>& anchors,
                                                    double radius) {
  std::seed_seq seeds{settings.seed, kNoiseStream, static_cast<std::uint32_t>(sequence),
                      static_cast<std::uint32_t>(candidate)};
  std::mt19937 rng(seeds);
  const DepthNoiseModel noise{settings.noise, sensorModel(settings.sensor)};
  pcl::PointCloud<pcl::PointXYZ> cloud = renderer.render(camera_from_object, noise, &rng);
  if (radius == kAllVisible) return cloud;
  return cropToAnchors(cloud, camera_from_object, anchors, radius);
}

std::optional<int> viewsUntilMedianStaysBelow(const Eigen::VectorXd& median_per_view,
                                              double threshold_deg) {
  std::optional<int> first;
  for (Eigen::Index v = median_per_view.size() - 1; v >= 0 && median_per_view(v) < threshold_deg;
       --v) {
    first = static_cast<int>(v) + 1;
  }
  return first;
}

double medianIgnoringNaN(const double* values, Eigen::Index count) {
  std::vector<double> finite;
  for (Eigen::Index i = 0; i < count; ++i) {
    if (!std::isnan(values[i])) finite.push_back(values[i]);
  }
  if (finite.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(finite.begin(), finite.end());
  const std::size_t n = finite.size();
  return n % 2 ? finite[n / 2] : 0.5 * (finite[n / 2 - 1] + finite[n / 2]);
}

Eigen::VectorXd SettingErrors::medianPositionPerView() const {
  Eigen::VectorXd medians(position_errors_mm.cols());
  for (Eigen::Index v = 0; v < position_errors_mm.cols(); ++v) {
    medians(v) = medianIgnoringNaN(position_errors_mm.col(v).data(), position_errors_mm.rows());
  }
  return medians;
}

Eigen::VectorXd SettingErrors::positionInsideEllipsoid90PerView() const {
  if (position_mahalanobis.size() == 0) return {};
  Eigen::VectorXd fractions(position_mahalanobis.cols());
  for (Eigen::Index v = 0; v < position_mahalanobis.cols(); ++v) {
    int counted = 0, inside = 0;
    for (Eigen::Index s = 0; s < position_mahalanobis.rows(); ++s) {
      const double distance = position_mahalanobis(s, v);
      if (std::isnan(distance)) continue;
      ++counted;
      if (distance * distance <= kChiSquare3At90) ++inside;
    }
    fractions(v) = counted > 0 ? static_cast<double>(inside) / counted
                               : std::numeric_limits<double>::quiet_NaN();
  }
  return fractions;
}

Eigen::VectorXd SettingErrors::medianPerView() const {
  Eigen::VectorXd medians(errors_deg.cols());
  for (Eigen::Index v = 0; v < errors_deg.cols(); ++v) {
    std::vector<double> column(errors_deg.col(v).data(),
                               errors_deg.col(v).data() + errors_deg.rows());
    std::sort(column.begin(), column.end());
    const std::size_t n = column.size();
    medians(v) = n == 0 ? 0.0 : (n % 2 ? column[n / 2] : 0.5 * (column[n / 2 - 1] + column[n / 2]));
  }
  return medians;
}

Eigen::VectorXd SettingErrors::insideCone90PerView() const {
  if (cone90_deg.size() != errors_deg.size() || errors_deg.rows() == 0) return {};
  const Eigen::ArrayXXd inside = (errors_deg.array() <= cone90_deg.array()).cast<double>();
  return inside.colwise().mean().transpose();
}

Eigen::VectorXd SettingErrors::confidentlyWrongPerView(double min_error_deg) const {
  if (cone90_deg.size() != errors_deg.size() || errors_deg.rows() == 0) return {};
  const Eigen::ArrayXXd errors = errors_deg.array();
  const Eigen::ArrayXXd wrong =
      ((errors > 2.0 * cone90_deg.array()) && (errors > min_error_deg)).cast<double>();
  return wrong.colwise().mean().transpose();
}

EvaluationResult evaluateEstimator(std::shared_ptr<const ModelBundle> model,
                                   const TriangleMesh& mesh,
                                   const std::vector<Eigen::Vector3d>& anchors,
                                   EvaluationPlanner planner, const EvaluationSettings& settings,
                                   const ProgressCallback& progress) {
  checkEvaluationSettings(settings);
  checkVisibilityAnchors(anchors, settings);
  if (!model) throw Error("the evaluation needs a model bundle");
  // Fails early (not inside the threads) for bad estimator parameters.
  { const OrientationEstimator check(model, settings.estimator); }
  const DepthRenderer renderer(renderedObjectMesh(mesh, settings), intrinsicsOf(model->parameters));
  std::unique_ptr<ViewUtilityScorer> scorer;
  if (planner != EvaluationPlanner::kRandom) {
    scorer = std::make_unique<ViewUtilityScorer>(model);
  }
  const std::vector<double> radii = visibilityRadii(settings);
  const std::vector<double> fractions = visibleFractions(mesh, anchors, settings);

  const int settings_count = static_cast<int>(radii.size());
  const int runs = settings.sequences * settings_count;
  const std::size_t total_views = static_cast<std::size_t>(runs) * settings.views;
  std::vector<RunOutput> outputs(static_cast<std::size_t>(runs));
  std::size_t done_views = 0;
  std::string failure;
  const std::string stage = "evaluating " + evaluationPlannerName(planner);
  reportProgress(progress, stage, 0, total_views);

  const int threads = settings.threads > 0 ? settings.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int run = 0; run < runs; ++run) {
    const int sequence_index = run / settings_count;
    const double radius = radii[static_cast<std::size_t>(run % settings_count)];
    RunOutput& out = outputs[static_cast<std::size_t>(run)];
    try {
      const EvaluationSequence sequence = makeEvaluationSequence(settings, sequence_index);
      const Eigen::Isometry3d world_from_object = sequence.worldFromObject();
      OrientationEstimator estimator(model, settings.estimator);
      std::vector<bool> used(sequence.camera_from_object.size(), false);
      for (int v = 0; v < settings.views; ++v) {
        const auto plan_start = std::chrono::steady_clock::now();
        const int candidate =
            chooseCandidate(planner, scorer.get(), estimator, sequence, used, v, settings);
        if (planner != EvaluationPlanner::kRandom && v > 0) {
          out.planning_ms += millisecondsSince(plan_start);
          ++out.planned;
        }
        used[static_cast<std::size_t>(candidate)] = true;
        const Eigen::Isometry3d& camera_from_object =
            sequence.camera_from_object[static_cast<std::size_t>(candidate)];
        const auto cloud = renderEvaluationView(renderer, settings, sequence_index, candidate,
                                                camera_from_object, anchors, radius);
        // Rendered from the true pose; the estimator gets the pose the robot believes.
        const ViewUpdate update = estimator.update(
            cloud, believedWorldFromCamera(world_from_object * camera_from_object.inverse(),
                                           settings.camera_pose_error, settings.seed,
                                           sequence_index, candidate));
        out.stage_ms += update.timing;
        if (!update.updated) ++out.skipped;
        const auto map_start = std::chrono::steady_clock::now();
        const Eigen::Vector4d map = estimator.mapOrientation();
        out.map_ms += millisecondsSince(map_start);
        out.errors.push_back(rotationErrorDeg(map, sequence.world_from_object));
        out.views_fused.push_back(estimator.viewsFused());
        out.cone90_deg.push_back(estimator.spread().cone90 * 180.0 / M_PI);
        // The object sits at the world origin.
        const std::optional<Eigen::Vector3d> position = estimator.positionEstimate();
        out.position_errors_mm.push_back(position ? 1000.0 * position->norm()
                                                  : std::numeric_limits<double>::quiet_NaN());
        out.position_mahalanobis.push_back(
            position ? mahalanobisDistance(*position, estimator.positionCovariance())
                     : std::numeric_limits<double>::quiet_NaN());
#pragma omp critical(vdc_evaluation_progress)
        reportProgress(progress, stage, ++done_views, total_views);
      }
    } catch (const std::exception& error) {
#pragma omp critical(vdc_evaluation_failure)
      if (failure.empty()) failure = error.what();
    }
  }
  if (!failure.empty()) throw Error("the evaluation failed: " + failure);

  EvaluationResult result;
  result.planner = evaluationPlannerName(planner);
  double planning_ms = 0, map_ms = 0;
  int planned = 0;
  for (int k = 0; k < settings_count; ++k) {
    SettingErrors setting;
    setting.radius = radii[static_cast<std::size_t>(k)];
    setting.visible_fraction = fractions[static_cast<std::size_t>(k)];
    setting.errors_deg.resize(settings.sequences, settings.views);
    setting.views_fused.resize(settings.sequences, settings.views);
    setting.cone90_deg.resize(settings.sequences, settings.views);
    setting.position_errors_mm.resize(settings.sequences, settings.views);
    setting.position_mahalanobis.resize(settings.sequences, settings.views);
    for (int s = 0; s < settings.sequences; ++s) {
      const RunOutput& out = outputs[static_cast<std::size_t>(s * settings_count + k)];
      for (int v = 0; v < settings.views; ++v) {
        const auto view = static_cast<std::size_t>(v);
        setting.errors_deg(s, v) = out.errors[view];
        setting.views_fused(s, v) = out.views_fused[view];
        setting.cone90_deg(s, v) = out.cone90_deg[view];
        setting.position_errors_mm(s, v) = out.position_errors_mm[view];
        setting.position_mahalanobis(s, v) = out.position_mahalanobis[view];
      }
      setting.skipped_views += out.skipped;
      planning_ms += out.planning_ms;
      map_ms += out.map_ms;
      result.mean_stage_ms += out.stage_ms;
      planned += out.planned;
    }
    result.settings.push_back(std::move(setting));
  }
  const double views_done = static_cast<double>(total_views);
  result.mean_stage_ms /= views_done;
  result.mean_update_ms = result.mean_stage_ms.total;
  result.mean_map_ms = map_ms / views_done;
  result.mean_planning_ms = planned > 0 ? planning_ms / planned : 0.0;
  return result;
}

EvaluationResult evaluateSingleView(const SingleViewMethod& method, const std::string& name,
                                    const TriangleMesh& mesh, const CameraIntrinsics& intrinsics,
                                    const std::vector<Eigen::Vector3d>& anchors,
                                    const EvaluationSettings& settings,
                                    const ProgressCallback& progress) {
  checkEvaluationSettings(settings);
  checkVisibilityAnchors(anchors, settings);
  if (!method) throw Error("the single-view evaluation needs a method");
  // A single-view method estimates T_CO in the camera frame: the camera pose error does not
  // reach it, the perturbed mesh does.
  const DepthRenderer renderer(renderedObjectMesh(mesh, settings), intrinsics);
  const std::vector<double> radii = visibilityRadii(settings);
  const std::vector<double> fractions = visibleFractions(mesh, anchors, settings);
  const std::size_t total_views = radii.size() * settings.sequences * settings.views;
  const std::string stage = "evaluating " + name;
  reportProgress(progress, stage, 0, total_views);

  EvaluationResult result;
  result.planner = name;
  for (std::size_t k = 0; k < radii.size(); ++k) {
    SettingErrors setting;
    setting.radius = radii[k];
    setting.visible_fraction = fractions[k];
    setting.errors_deg.resize(settings.sequences, settings.views);
    setting.position_errors_mm.setConstant(settings.sequences, settings.views,
                                           std::numeric_limits<double>::quiet_NaN());
    result.settings.push_back(std::move(setting));
  }
  double method_ms = 0;
  std::size_t done = 0;
  for (int s = 0; s < settings.sequences; ++s) {
    const EvaluationSequence sequence = makeEvaluationSequence(settings, s);
    for (int v = 0; v < settings.views; ++v) {
      const Eigen::Isometry3d& camera_from_object =
          sequence.camera_from_object[static_cast<std::size_t>(v)];
      for (std::size_t k = 0; k < radii.size(); ++k) {
        SettingErrors& setting = result.settings[k];
        const auto cloud =
            renderEvaluationView(renderer, settings, s, v, camera_from_object, anchors, radii[k]);
        const auto start = std::chrono::steady_clock::now();
        const std::optional<Eigen::Isometry3d> estimate = method(cloud);
        method_ms += millisecondsSince(start);
        double error = 180.0;
        if (estimate && estimate->matrix().allFinite()) {
          // R_CO estimated, R_CO true: compare them in the camera frame (the same angle as
          // between R_WC R_CO and q_WO, R_WC being known exactly).
          error = rotationErrorDeg(quaternionFromRotationMatrix(estimate->linear()),
                                   quaternionFromRotationMatrix(camera_from_object.linear()));
          setting.position_errors_mm(s, v) =
              1000.0 * (estimate->translation() - camera_from_object.translation()).norm();
        } else {
          ++setting.skipped_views;
        }
        setting.errors_deg(s, v) = error;
        reportProgress(progress, stage, ++done, total_views);
      }
    }
  }
  result.mean_update_ms = method_ms / static_cast<double>(total_views);
  return result;
}

}  // namespace vdc
