#include "view_direction_classification/evaluation/stream_evaluation.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <random>
#include <string>

#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/visibility_crop.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc {
namespace {

// Tags that keep the stream's generators apart from the protocol's for the same seed.
constexpr std::uint32_t kStreamPathTag = 0x5a7bu;
constexpr std::uint32_t kStreamNoiseTag = 0x5a7cu;

using Clock = std::chrono::steady_clock;

std::mt19937 generatorOf(std::uint32_t seed, std::uint32_t tag, int sequence) {
  std::seed_seq seeds{seed, tag, static_cast<std::uint32_t>(sequence)};
  return std::mt19937(seeds);
}

// The camera path of one sequence through the random planner's views.
std::vector<StreamFrame> sequencePath(const EvaluationSettings& settings, int sequence) {
  const EvaluationSequence views = makeEvaluationSequence(settings, sequence);
  const std::vector<Eigen::Isometry3d> path_views(
      views.camera_from_object.begin(),
      views.camera_from_object.begin() + static_cast<std::ptrdiff_t>(settings.views));
  StreamPathSettings path;
  path.rate_hz = settings.stream_rate_hz;
  path.dwell_s = settings.stream_dwell_s;
  std::mt19937 draw = generatorOf(settings.seed, kStreamPathTag, sequence);
  return streamPath(path_views, path, draw());
}

// Whether frame k is the last one at its view's dwell (the moment the protocol's one cloud per
// view is compared with).
bool endsADwell(const std::vector<StreamFrame>& frames, std::size_t k) {
  if (!frames[k].dwelling) return false;
  return k + 1 == frames.size() || !frames[k + 1].dwelling || frames[k + 1].view != frames[k].view;
}

StreamSample sampleOf(const OrientationEstimator& estimator, const Eigen::Vector4d& truth,
                      const StreamFrame& frame) {
  StreamSample sample;
  sample.time_s = frame.time;
  sample.view = frame.view + 1;
  sample.views_fused = estimator.viewsFused();
  sample.map_error_deg = rotationErrorDeg(estimator.mapOrientation(), truth);
  sample.cone90_deg = estimator.spread().cone90 * 180.0 / M_PI;
  return sample;
}

// Sums of one run's costs [ms].
struct StreamCosts {
  double render = 0.0, unfeaturised = 0.0, featurised = 0.0;
};

// Counts one frame's outcome into the sequence's figures and costs.
void countFrame(const ViewUpdate& update, StreamSequenceResult* out, StreamCosts* costs) {
  ++out->frames;
  // The features stage ran: the frame passed the selection and its segmentation.
  const bool featurised = update.timing.features > 0.0;
  out->featurised += featurised;
  (featurised ? costs->featurised : costs->unfeaturised) += update.timing.total;
  switch (update.outcome) {
    case FrameOutcome::kFused:
      ++out->fused;
      break;
    case FrameOutcome::kNotNovel:
      ++out->not_novel;
      break;
    case FrameOutcome::kSkipped:
      ++out->skipped;
      break;
  }
}

// One (sequence, setting) stream, frame by frame through a fresh estimator.
StreamSequenceResult runStream(const std::shared_ptr<const ModelBundle>& model,
                               const DepthRenderer& renderer,
                               const std::vector<Eigen::Vector3d>& anchors, double radius,
                               const EvaluationSettings& settings, int sequence_index,
                               const std::vector<StreamFrame>& frames, StreamCosts* costs,
                               const std::function<void()>& frame_done) {
  const EvaluationSequence sequence = makeEvaluationSequence(settings, sequence_index);
  const Eigen::Isometry3d world_from_object = sequence.worldFromObject();
  OrientationEstimator estimator(model, settings.estimator);
  std::mt19937 noise_rng = generatorOf(settings.seed, kStreamNoiseTag, sequence_index);
  const DepthNoiseModel noise{settings.noise, sensorModel(settings.sensor)};
  StreamSequenceResult out;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const StreamFrame& frame = frames[k];
    const Clock::time_point render_start = Clock::now();
    pcl::PointCloud<pcl::PointXYZ> cloud =
        renderer.render(frame.camera_from_object, noise, &noise_rng);
    if (radius != kAllVisible) {
      cloud = cropToAnchors(cloud, frame.camera_from_object, anchors, radius);
    }
    costs->render += millisecondsSince(render_start);
    // Rendered from the true pose; the estimator gets the pose the robot believes, with the
    // noise of the view the frame belongs to (the robot's error changes as it moves on).
    const ViewUpdate update =
        estimator.update(cloud,
                         believedWorldFromCamera(
                             world_from_object * frame.camera_from_object.inverse(),
                             settings.camera_pose_error, settings.seed, sequence_index, frame.view),
                         frame.time);
    countFrame(update, &out, costs);
    if (update.updated) {
      out.fusions.push_back(sampleOf(estimator, sequence.world_from_object, frame));
    }
    if (endsADwell(frames, k)) {
      out.view_ends.push_back(sampleOf(estimator, sequence.world_from_object, frame));
    }
    frame_done();
  }
  out.duration_s = frames.empty() ? 0.0 : frames.back().time;
  return out;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The number of view ends every sequence has (they all have `views`; 0 without sequences).
std::size_t viewEndCount(const std::vector<StreamSequenceResult>& sequences) {
  if (sequences.empty()) return 0;
  std::size_t count = sequences.front().view_ends.size();
  for (const auto& sequence : sequences) count = std::min(count, sequence.view_ends.size());
  return count;
}

}  // namespace

Eigen::VectorXd StreamSettingResult::medianAtViewEnds() const {
  const std::size_t views = viewEndCount(sequences);
  Eigen::VectorXd medians(static_cast<Eigen::Index>(views));
  for (std::size_t v = 0; v < views; ++v) {
    std::vector<double> errors;
    for (const auto& sequence : sequences) errors.push_back(sequence.view_ends[v].map_error_deg);
    medians(static_cast<Eigen::Index>(v)) = median(errors);
  }
  return medians;
}

Eigen::VectorXd StreamSettingResult::insideCone90AtViewEnds() const {
  const std::size_t views = viewEndCount(sequences);
  Eigen::VectorXd fractions = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(views));
  for (std::size_t v = 0; v < views; ++v) {
    for (const auto& sequence : sequences) {
      fractions(static_cast<Eigen::Index>(v)) += sequence.view_ends[v].insideCone90();
    }
  }
  return sequences.empty() ? fractions : fractions / static_cast<double>(sequences.size());
}

std::string streamEvaluationName(double rate_hz) {
  char text[48];
  std::snprintf(text, sizeof(text), "stream_%.6ghz", rate_hz);
  return text;
}

StreamEvaluationResult evaluateStream(std::shared_ptr<const ModelBundle> model,
                                      const TriangleMesh& mesh,
                                      const std::vector<Eigen::Vector3d>& anchors,
                                      const EvaluationSettings& settings,
                                      const ProgressCallback& progress) {
  checkEvaluationSettings(settings);
  checkVisibilityAnchors(anchors, settings);
  if (!(settings.stream_rate_hz > 0.0)) {
    throw Error("the stream evaluation needs a stream rate above 0 Hz");
  }
  if (!model) throw Error("the stream evaluation needs a model bundle");
  { const OrientationEstimator check(model, settings.estimator); }  // bad parameters fail here
  const DepthRenderer renderer(renderedObjectMesh(mesh, settings), intrinsicsOf(model->parameters));
  const std::vector<double> radii = visibilityRadii(settings);
  const int settings_count = static_cast<int>(radii.size());
  std::vector<std::vector<StreamFrame>> paths;
  std::size_t total_frames = 0;
  for (int s = 0; s < settings.sequences; ++s) {
    paths.push_back(sequencePath(settings, s));
    total_frames += paths.back().size() * radii.size();
  }

  StreamEvaluationResult result;
  result.rate_hz = settings.stream_rate_hz;
  result.name = streamEvaluationName(settings.stream_rate_hz);
  const int runs = settings.sequences * settings_count;
  std::vector<StreamSequenceResult> outputs(static_cast<std::size_t>(runs));
  std::vector<StreamCosts> costs(static_cast<std::size_t>(runs));
  std::size_t done_frames = 0;
  std::string failure;
  const std::string stage = "evaluating " + result.name;
  reportProgress(progress, stage, 0, total_frames);
  const auto frame_done = [&]() {
#pragma omp critical(vdc_stream_progress)
    reportProgress(progress, stage, ++done_frames, total_frames);
  };

  const int threads = settings.threads > 0 ? settings.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int run = 0; run < runs; ++run) {
    const int sequence = run / settings_count;
    const auto index = static_cast<std::size_t>(run);
    try {
      outputs[index] = runStream(
          model, renderer, anchors, radii[static_cast<std::size_t>(run % settings_count)], settings,
          sequence, paths[static_cast<std::size_t>(sequence)], &costs[index], frame_done);
    } catch (const std::exception& error) {
#pragma omp critical(vdc_stream_failure)
      if (failure.empty()) failure = error.what();
    }
  }
  if (!failure.empty()) throw Error("the stream evaluation failed: " + failure);

  int frames = 0, featurised = 0;
  StreamCosts sums;
  for (int k = 0; k < settings_count; ++k) {
    StreamSettingResult setting;
    setting.radius = radii[static_cast<std::size_t>(k)];
    for (int s = 0; s < settings.sequences; ++s) {
      const auto index = static_cast<std::size_t>(s * settings_count + k);
      frames += outputs[index].frames;
      featurised += outputs[index].featurised;
      sums.render += costs[index].render;
      sums.unfeaturised += costs[index].unfeaturised;
      sums.featurised += costs[index].featurised;
      setting.sequences.push_back(std::move(outputs[index]));
    }
    result.settings.push_back(std::move(setting));
  }
  result.mean_render_ms = frames > 0 ? sums.render / frames : 0.0;
  result.mean_unfeaturised_update_ms =
      frames > featurised ? sums.unfeaturised / (frames - featurised) : 0.0;
  result.mean_featurised_update_ms = featurised > 0 ? sums.featurised / featurised : 0.0;
  return result;
}

}  // namespace vdc
