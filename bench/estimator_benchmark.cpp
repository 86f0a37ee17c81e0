// Per-view latency of the online estimator (issue 5, "Benchmarks"): one cloud in, one fused
// estimate out, split by stage, for the default mug view (without and with refinement) and for
// clouds of ~1k to ~300k object points, plus the process's peak memory; and the refinement alone
// (issue 13), by number of hypotheses and by cloud size.
//
// Model: the bundle named by the environment variable VDC_BENCH_MODEL, else a quick mug model
// (quickTrainingParameters(), ~35 s) trained once at start-up; the context block of the output
// says which. Classification cost grows with the number of views, so figures for the default
// model (42 views) are the ones to quote.
//
// Cloud sizes: a depth camera sees the mug at 0.6 m with ~5000 points (fx = fy = 525). The
// number of object pixels grows with the square of the focal length, so the size cases scale
// fx, fy by s = sqrt(target / points at s = 1), measured on the same view and refined once. The
// image is cropped to a square window around the principal point that still holds the whole
// mug (side 0.3 f pixels: the mug's largest extent, ~0.15 m, seen from >= 0.5 m), so a 300k-point
// view does not allocate a 20-megapixel organised cloud. Only the object's density changes; the
// camera distance, noise model and view stay those of the default case.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/estimation/view_measurement.h"
#include "view_direction_classification/features/fpfh_features.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/learning/feature_selection.h"
#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/training/model_training.h"

namespace {

constexpr double kDistance = 0.6;  // the default (training) distance [m]

// The model every case uses, loaded or trained on first use.
std::shared_ptr<const vdc::ModelBundle> benchModel() {
  static const std::shared_ptr<const vdc::ModelBundle> model = [] {
    const char* path = std::getenv("VDC_BENCH_MODEL");
    if (path != nullptr && *path != '\0') {
      benchmark::AddCustomContext("model", std::string("loaded from VDC_BENCH_MODEL=") + path);
      return std::make_shared<const vdc::ModelBundle>(vdc::loadModelBundle(path));
    }
    std::cerr << "VDC_BENCH_MODEL not set: training a quick mug model (~35 s)..." << std::endl;
    vdc::TrainingParameters parameters = vdc::quickTrainingParameters();
    parameters.mesh_name = "mug";
    benchmark::AddCustomContext("model",
                                "quick mug model trained at start-up (12 views; set "
                                "VDC_BENCH_MODEL to a bundle for the default model's figures)");
    return std::make_shared<const vdc::ModelBundle>(vdc::trainModel(vdc::makeMug(), parameters));
  }();
  return model;
}

// Peak resident set size of this process [MiB] (VmHWM), or -1 if /proc is unavailable.
double peakResidentMiB() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kib = 0;
      status >> kib;
      return kib / 1024.0;
    }
    status.ignore(1 << 12, '\n');
  }
  return -1.0;
}

// The mug stands at a fixed, non-trivial pose in the world; the camera moves around it.
Eigen::Isometry3d worldFromObject() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.4, -0.2, 0.8);
  return pose;
}

struct View {
  pcl::PointCloud<pcl::PointXYZ> cloud;  // camera frame, organised, noisy
  Eigen::Isometry3d world_from_camera;
};

// A fixed sequence of viewing directions around the mug (side, handle, top, oblique, below, ...):
// what a camera moving around the object sees, so fusion works on a realistic belief.
std::vector<Eigen::Vector3d> sequenceDirections() {
  return {{1, 0, 0.2},   {0, 1, 0.3},    {0.3, 0.2, 1}, {-1, 0.5, -0.3},  {1, 1, 1},
          {-0.4, -1, 0}, {0.2, 0.1, -1}, {-1, -1, 0.5}, {0.6, -0.8, 0.4}, {-0.2, 0.9, -0.6}};
}

View renderView(const vdc::DepthRenderer& renderer, const Eigen::Vector3d& direction, double roll,
                std::uint32_t seed) {
  const Eigen::Isometry3d camera_from_object = vdc::cameraFromObject(direction, kDistance, roll);
  std::mt19937 rng(seed);
  return {renderer.render(camera_from_object, vdc::DepthNoiseModel{true}, &rng),
          worldFromObject() * camera_from_object.inverse()};
}

// What the node publishes after every fused view, the "estimate out" of the latency: the MAP
// orientation, the belief's entropy, the orientation covariance and the position. Returns the
// time it took [ms].
double computeEstimate(const vdc::OrientationEstimator& estimator) {
  const auto start = std::chrono::steady_clock::now();
  benchmark::DoNotOptimize(estimator.mapOrientation());
  benchmark::DoNotOptimize(estimator.entropy());
  benchmark::DoNotOptimize(estimator.orientationCovariance());
  benchmark::DoNotOptimize(estimator.positionEstimate());
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// Averages the stages of every update of a run into per-update counters.
struct StageTotals {
  vdc::UpdateTiming sum;
  double estimate = 0;  // what the node publishes after the update [ms]
  double features = 0, object_points = 0;
  int updates = 0;

  void add(const vdc::ViewUpdate& update, double estimate_ms) {
    sum += update.timing;
    estimate += estimate_ms;
    features += update.features;
    object_points += update.object_points;
    ++updates;
  }
  void report(benchmark::State& state) const {
    const double n = updates > 0 ? updates : 1;
    state.counters["features_ms"] = sum.features / n;
    state.counters["classification_ms"] = sum.classification / n;
    state.counters["measurement_ms"] = sum.measurement / n;
    state.counters["fusion_ms"] = sum.fusion / n;
    state.counters["refinement_ms"] = sum.refinement / n;
    state.counters["estimate_ms"] = estimate / n;
    state.counters["total_ms"] = (sum.total + estimate) / n;
    state.counters["features"] = features / n;
    state.counters["points"] = object_points / n;
    state.counters["peak_MiB"] = peakResidentMiB();
  }
};

// The estimator's settings with the refinement of the benchmark's argument (0: none, 1: icp).
vdc::EstimatorParameters withRefinement(std::int64_t icp) {
  vdc::EstimatorParameters parameters;
  parameters.refinement = icp != 0 ? vdc::RefinementMode::kIcp : vdc::RefinementMode::kNone;
  return parameters;
}

// (a) The default mug view: a sequence of updates from the directions above (the filter starts
// again from the uniform prior after each sequence, outside the timed region); argument:
// refinement none (0) or icp (1).
void BM_MugViewSequence(benchmark::State& state) {
  const auto model = benchModel();
  const vdc::DepthRenderer renderer(vdc::makeMug(), vdc::intrinsicsOf(model->parameters));
  std::vector<View> views;
  const std::vector<Eigen::Vector3d> directions = sequenceDirections();
  for (std::size_t i = 0; i < directions.size(); ++i) {
    views.push_back(renderView(renderer, directions[i], 0.4 * static_cast<double>(i),
                               static_cast<std::uint32_t>(100 + i)));
  }
  vdc::OrientationEstimator estimator(model, withRefinement(state.range(0)));
  StageTotals totals, first_views;  // every update; the first of each sequence alone
  double refined_poses = 0;
  std::size_t next = 0;
  for (auto _ : state) {
    if (next == views.size()) {
      state.PauseTiming();
      estimator.reset();
      next = 0;
      state.ResumeTiming();
    }
    const bool first = next == 0;
    const View& view = views[next++];
    const vdc::ViewUpdate update = estimator.update(view.cloud, view.world_from_camera);
    if (!update.updated) state.SkipWithError(update.skip_reason.c_str());
    const double estimate_ms = computeEstimate(estimator);
    totals.add(update, estimate_ms);
    if (first) first_views.add(update, estimate_ms);
    refined_poses += update.refined_poses;
  }
  totals.report(state);
  // The first view costs most: its belief is two girdles, every start of them is aligned.
  const double firsts = std::max(1, first_views.updates);
  state.counters["first_view_total_ms"] = (first_views.sum.total + first_views.estimate) / firsts;
  state.counters["first_view_refinement_ms"] = first_views.sum.refinement / firsts;
  state.counters["belief_components"] = static_cast<double>(estimator.belief().size());
  state.counters["refined_poses"] = refined_poses / std::max<double>(1, totals.updates);
}
BENCHMARK(BM_MugViewSequence)
    ->ArgName("icp")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->MinTime(5.0);

// Intrinsics whose focal length is `scale` times the model's, cropped around the mug (see the
// file comment).
vdc::CameraIntrinsics scaledIntrinsics(const vdc::CameraIntrinsics& base, double scale) {
  vdc::CameraIntrinsics scaled;
  scaled.fx = base.fx * scale;
  scaled.fy = base.fy * scale;
  const int side = static_cast<int>(std::ceil(0.3 * std::max(scaled.fx, scaled.fy)));
  scaled.width = scaled.height = side;
  scaled.cx = scaled.cy = 0.5 * (side - 1);
  return scaled;
}

// A view of the mug (one oblique direction, handle visible) with about `target` object points.
View viewWithPoints(const vdc::ModelBundle& model, double target) {
  const Eigen::Vector3d direction(1, 1, 1);
  const vdc::CameraIntrinsics base = vdc::intrinsicsOf(model.parameters);
  double scale = 1.0;
  View view;
  for (int refinement = 0; refinement < 3; ++refinement) {
    const vdc::DepthRenderer renderer(vdc::makeMug(), scaledIntrinsics(base, scale));
    view = renderView(renderer, direction, 0.3, 7);
    const double points = static_cast<double>(vdc::countValidPoints(view.cloud));
    scale *= std::sqrt(target / points);
  }
  return view;
}

// The cloud sizes of both size benchmarks, timed alike: wall time and the process's CPU time.
void cloudSizeCases(benchmark::internal::Benchmark* cases) {
  for (const int points : {1000, 10000, 100000, 300000}) cases->Arg(points);
  cases->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
}

// (b) Features + classification only (what the cloud's size changes), at ~state.range(0) object
// points.
void BM_FeaturesAndClassificationByCloudSize(benchmark::State& state) {
  const auto model = benchModel();
  const View view = viewWithPoints(*model, static_cast<double>(state.range(0)));
  const vdc::FeatureParameters parameters = vdc::featureParametersOf(model->parameters);
  double features_ms = 0, classification_ms = 0, features = 0;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    const vdc::FeatureSet set = vdc::computeFeatures(view.cloud, parameters);
    const Clock::time_point described = Clock::now();
    const Eigen::MatrixXf probabilities = model->classifier.predict(set.descriptors);
    const Eigen::VectorXd p_sum = vdc::summedDistribution(probabilities, model->parameters.n_feat);
    benchmark::DoNotOptimize(p_sum.data());
    const Clock::time_point classified = Clock::now();
    features_ms += std::chrono::duration<double, std::milli>(described - start).count();
    classification_ms += std::chrono::duration<double, std::milli>(classified - described).count();
    features += static_cast<double>(set.size());
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["features_ms"] = features_ms / n;
  state.counters["classification_ms"] = classification_ms / n;
  state.counters["features"] = features / n;
  state.counters["points"] = static_cast<double>(vdc::countValidPoints(view.cloud));
  state.counters["peak_MiB"] = peakResidentMiB();
}
BENCHMARK(BM_FeaturesAndClassificationByCloudSize)->Apply(cloudSizeCases);

// (b) The full update at ~state.range(0) object points, from the uniform prior each time (the
// reset is outside the timed region), so every size fuses into the same belief.
void BM_FullUpdateByCloudSize(benchmark::State& state) {
  const auto model = benchModel();
  const View view = viewWithPoints(*model, static_cast<double>(state.range(0)));
  vdc::OrientationEstimator estimator(model, vdc::EstimatorParameters{});
  StageTotals totals;
  for (auto _ : state) {
    state.PauseTiming();
    estimator.reset();
    state.ResumeTiming();
    const vdc::ViewUpdate update = estimator.update(view.cloud, view.world_from_camera);
    if (!update.updated) state.SkipWithError(update.skip_reason.c_str());
    totals.add(update, computeEstimate(estimator));
  }
  totals.report(state);
}
BENCHMARK(BM_FullUpdateByCloudSize)->Apply(cloudSizeCases);

// The refiner the estimator builds, with `step` degrees between girdle starts and `max_refined`
// starts aligned.
vdc::PoseRefiner estimatorRefiner(const vdc::ModelBundle& model, double step, int max_refined) {
  vdc::RefinementParameters parameters = vdc::EstimatorParameters{}.refinement_parameters;
  if (step > 0) parameters.hypotheses.girdle_step_deg = step;
  if (max_refined >= 0) parameters.max_refined = max_refined;
  return vdc::PoseRefiner(model, parameters);
}

// What one view's measurement leaves of the roll: the girdle of the true viewing direction (the
// camera's line of sight through the object origin), in the fixed frame.
vdc::BinghamMixture trueGirdle(const View& view) {
  const Eigen::Isometry3d object_from_camera = worldFromObject().inverse() * view.world_from_camera;
  const Eigen::Vector3d direction = object_from_camera.translation().normalized();
  const vdc::BinghamMixture camera_frame({1.0}, {vdc::viewGirdle(direction, 18.0)});
  return vdc::cameraToFixedFrame(
      camera_frame, vdc::fromEigenQuaternion(Eigen::Quaterniond(view.world_from_camera.linear())));
}

// CPU time of the calling thread [ms].
double threadCpuMilliseconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

// Times refine() on one view and reports its starts, ICPs and the best kept pose's errors.
void timeRefinement(benchmark::State& state, const vdc::PoseRefiner& refiner, const View& view) {
  const vdc::BinghamMixture belief = trueGirdle(view);
  const Eigen::Vector3d position = worldFromObject().translation();
  // The rendered mug alone: no scene beside it.
  vdc::RefinementView input{pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(view.cloud),
                            view.world_from_camera, vdc::SceneDepth{}};
  vdc::RefinementResult result;
  // refine() runs on this thread alone: its own CPU time is what it costs, whatever else the
  // machine runs (the wall time on a shared machine is not).
  double thread_cpu_ms = 0;
  for (auto _ : state) {
    const double before = threadCpuMilliseconds();
    result = refiner.refine(belief, position, {input});
    thread_cpu_ms += threadCpuMilliseconds() - before;
  }
  state.counters["refine_cpu_ms"] = thread_cpu_ms / static_cast<double>(state.iterations());
  int refined = 0, iterations = 0;
  for (const vdc::RefinedPose& pose : result.tried) {
    refined += pose.screened_in ? 1 : 0;
    iterations += pose.icp_iterations;
  }
  state.counters["icp_iterations"] = refined > 0 ? static_cast<double>(iterations) / refined : 0;
  state.counters["starts"] = static_cast<double>(result.tried.size());
  state.counters["icps"] = refined;
  state.counters["kept"] = static_cast<double>(result.kept.size());
  state.counters["points"] = static_cast<double>(vdc::countValidPoints(view.cloud));
  if (result.kept.empty()) return;
  const Eigen::Isometry3d& best = result.kept.front().world_from_object;
  state.counters["error_deg"] = vdc::rotationErrorDeg(
      result.kept.front().orientation,
      vdc::fromEigenQuaternion(Eigen::Quaterniond(worldFromObject().linear())));
  state.counters["position_error_mm"] =
      1000.0 * (best.translation() - worldFromObject().translation()).norm();
}

// (d) The refinement of one view's girdle (the handle seen from the side and above, ~6.8k points)
// by number of hypotheses: arguments girdle step [deg] (360 / step starts) and starts aligned by
// ICP (0: all).
void BM_RefinementByHypotheses(benchmark::State& state) {
  const auto model = benchModel();
  const vdc::DepthRenderer renderer(vdc::makeMug(), vdc::intrinsicsOf(model->parameters));
  const View view = renderView(renderer, Eigen::Vector3d(0.3, 1.0, 0.4).normalized(), 1.3, 11);
  timeRefinement(state,
                 estimatorRefiner(*model, static_cast<double>(state.range(0)),
                                  static_cast<int>(state.range(1))),
                 view);
}
BENCHMARK(BM_RefinementByHypotheses)
    ->ArgNames({"step_deg", "max_refined"})
    ->Args({30, 3})
    ->Args({10, 1})
    ->Args({10, 3})
    ->Args({10, 6})
    ->Args({5, 3})
    ->Args({30, 0})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// (d) The same refinement (the estimator's settings) at ~state.range(0) object points.
void BM_RefinementByCloudSize(benchmark::State& state) {
  const auto model = benchModel();
  const View view = viewWithPoints(*model, static_cast<double>(state.range(0)));
  timeRefinement(state, estimatorRefiner(*model, -1, -1), view);
}
BENCHMARK(BM_RefinementByCloudSize)->Apply(cloudSizeCases);

// (c) Peak memory of everything above (runs last: benchmarks run in registration order).
void BM_PeakMemory(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(peakResidentMiB());
  state.counters["peak_MiB"] = peakResidentMiB();
}
BENCHMARK(BM_PeakMemory)->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  try {
    benchModel();  // before the run, so that the context block names the model
  } catch (const std::exception& error) {
    std::cerr << error.what() << std::endl;
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
