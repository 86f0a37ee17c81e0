// `vdc train --mesh M --out B.h5`: the whole offline pipeline into one model bundle.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <vector>

#include "commands.h"
#include "progress_bar.h"
#include "sensor_option.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/view_sphere.h"
#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc::tools {

namespace {

struct TrainOptions {
  std::string mesh_path;
  std::string out_path;
  bool quick = false;
  bool no_noise = false;
  std::string sensor;                  // --sensor; empty: not given
  std::vector<double> distance_range;  // [min, max] camera distances [m], when given
  TrainingParameters parameters;
};

// The bundle keeps a centre distance and a relative jitter: [min, max] is centre (1 +- jitter).
void applyDistanceRange(const std::vector<double>& range, TrainingParameters* parameters) {
  if (range.size() != 2 || !(range[0] > 0.0) || !(range[1] >= range[0]) ||
      !std::isfinite(range[1])) {
    throw CLI::ValidationError("--distance-range",
                               "needs MIN MAX with 0 < MIN <= MAX (metres), finite");
  }
  parameters->distance = 0.5 * (range[0] + range[1]);
  parameters->distance_jitter = (range[1] - range[0]) / (range[0] + range[1]);
}

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

void runTrain(TrainOptions options, const CLI::App& command) {
  const auto start = std::chrono::steady_clock::now();
  TrainingParameters parameters = options.parameters;
  if (options.quick) {
    const TrainingParameters quick = quickTrainingParameters(parameters);
    // Explicit --views / --clouds-per-view still win over --quick's small defaults.
    if (command.count("--views") == 0) parameters.views = quick.views;
    if (command.count("--clouds-per-view") == 0) {
      parameters.clouds_per_view = quick.clouds_per_view;
    }
    parameters.surface_spacing = quick.surface_spacing;
  }
  if (!options.distance_range.empty()) applyDistanceRange(options.distance_range, &parameters);
  const SensorSelection sensor = selectSensor(options.sensor, options.no_noise);
  parameters.noise = sensor.noise;
  parameters.sensor = sensor.sensor;
  parameters.mesh_name = options.mesh_path;
  const TriangleMesh mesh = loadMesh(options.mesh_path);

  std::fprintf(stderr, "training on %s: %d views x %d clouds at %.2f-%.2f m, seed %u, sensor %s\n",
               options.mesh_path.c_str(), parameters.views, parameters.clouds_per_view,
               parameters.distance * (1.0 - parameters.distance_jitter),
               parameters.distance * (1.0 + parameters.distance_jitter), parameters.seed,
               selectionName(parameters.noise, parameters.sensor).c_str());
  ProgressBar progress;
  TrainingReport report;
  const ModelBundle bundle =
      trainModel(mesh, parameters, &report,
                 [&progress](const std::string& stage, std::size_t done, std::size_t total) {
                   progress(stage, done, total);
                 });
  for (const auto& warning : report.warnings) std::cerr << "warning: " << warning << "\n";
  saveModelBundle(bundle, options.out_path);

  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto& v = bundle.view_informativeness;
  double view_sum = 0.0;
  int view_count = 0;
  for (Eigen::Index m = 0; m < v.view_scores.size(); ++m) {
    if (v.view_scores(m) >= 0.0) view_sum += v.view_scores(m), ++view_count;
  }
  double global_sum = 0.0;
  int global_count = 0;
  for (Eigen::Index i = 0; i < bundle.global_scores.size(); ++i) {
    if (bundle.global_scores(i) >= 0.0f) global_sum += bundle.global_scores(i), ++global_count;
  }
  std::printf("wrote %s\n", options.out_path.c_str());
  std::printf("features: %zu training, %zu held-out\n", report.training_features,
              report.held_out_features);
  std::printf("held-out: accuracy %.3f (chance %.3f), log-loss %.3f\n", bundle.held_out.accuracy,
              1.0 / parameters.views, bundle.held_out.log_loss);
  std::printf("mean view score %.3f; mean global score %.3f over %d observable surface points\n",
              view_count ? view_sum / view_count : -1.0,
              global_count ? global_sum / global_count : -1.0, global_count);
  std::printf(
      "time: %.1f s (render+features %.1f s, classifier %.1f s, scoring %.1f s); "
      "peak memory %.0f MiB\n",
      total, report.seconds_rendering, report.seconds_training, report.seconds_scoring,
      peakMemoryMiB());
}

}  // namespace

void addTrainCommand(CLI::App& app) {
  auto options = std::make_shared<TrainOptions>();
  auto* train = app.add_subcommand("train",
                                   "render views, train the classifier, score "
                                   "informativeness, write a model bundle");
  TrainingParameters& p = options->parameters;
  train->add_option("--mesh", options->mesh_path, "object mesh (PLY/STL/OBJ/OFF, metres)")
      ->required();
  train->add_option("--out", options->out_path, "model bundle to write (HDF5)")->required();
  train->add_option("--views", p.views, "number of viewing directions")
      ->capture_default_str()
      ->check(CLI::Range(2, 5000));
  train->add_option("--clouds-per-view", p.clouds_per_view, "training clouds per direction")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  train->add_option("--seed", p.seed, "seed of every random choice")->capture_default_str();
  train->add_flag("--quick", options->quick, "a small model in seconds (tests, CI)");
  train->add_option("--clusters", p.clusters, "K-means clusters, one classifier each")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  train->add_option("--n-feat", p.n_feat, "most certain features summed per view")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  train->add_option("--l2", p.l2, "L2 regularisation of the classifier")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 100.0));
  train->add_option("--keypoint-voxel", p.keypoint_voxel, "voxel edge of the keypoints [m]")
      ->capture_default_str()
      ->check(CLI::Range(0.0005, 0.1));
  train
      ->add_option("--support-voxel", p.support_voxel,
                   "voxel edge of the FPFH search surface [m]; 0: the full cloud")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.1));
  train
      ->add_option("--distance-range", options->distance_range,
                   "camera distances of the training clouds [m], MIN MAX, drawn uniformly "
                   "(default 0.54 0.66: 0.6 m +- 10 %)")
      ->expected(2);
  train->add_flag("--no-noise", options->no_noise, "render training clouds without noise");
  addSensorOption(*train, &options->sensor);
  train->callback([options, train] { runTrain(*options, *train); });
}

}  // namespace vdc::tools
