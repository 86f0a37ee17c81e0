// `vdc evaluate-scenes --model NAME=BUNDLE.h5:MESH ... --out DIR`: recognising every known object
// of seeded cluttered table scenes (evaluation/scene_evaluation.h): per scene, its views on the
// camera arc fed in order to one scene estimator with the node's defaults, scored after each
// view. Writes DIR/scenes.csv (scene_evaluation_csv.cpp) and prints the figures per view index
// (scene_evaluation_summary.cpp). A subcommand of its own rather than `evaluate --scene`: it
// shares none of `evaluate`'s single-object options.
#include <pcl/console/print.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "identity_options.h"
#include "progress_bar.h"
#include "scene_evaluation_csv.h"
#include "scene_evaluation_options.h"
#include "scene_evaluation_summary.h"
#include "sensor_option.h"
#include "view_direction_classification/common/error.h"

namespace vdc::tools {

namespace {

namespace fs = std::filesystem;

struct EvaluateScenesOptions {
  std::vector<std::string> models;
  std::vector<std::string> distractors;
  std::string out_dir;
  bool no_noise = false;
  std::string sensor;  // --sensor; empty: not given
  SceneEvaluationSettings settings;
};

fs::path writeCsvFile(const std::vector<SceneViewRecord>& records, const std::string& out_dir) {
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) throw Error("cannot create output directory " + out_dir + ": " + error.message());
  const fs::path path = fs::path(out_dir) / "scenes.csv";
  std::ofstream csv(path);
  writeScenesCsv(csv, records);
  if (!csv) throw Error("cannot write " + path.string());
  return path;
}

void runEvaluateScenes(EvaluateScenesOptions options) {
  const auto start = std::chrono::steady_clock::now();
  // Refinement's registration logs at INFO level; keep the terminal to the progress bar.
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const std::vector<SceneEvaluationModel> models = loadSceneModels(options.models);
  const std::vector<TriangleMesh> distractors = loadDistractorMeshes(options.distractors);
  const SensorSelection sensor = selectSensor(options.sensor, options.no_noise);
  options.settings.noise = sensor.noise;
  options.settings.sensor = sensor.sensor;
  checkSceneEvaluationSettings(options.settings);
  std::fprintf(stderr,
               "%d scenes x %d views, %d known + %d distractors each, %zu models, seed %u\n",
               options.settings.scenes, options.settings.generation.views,
               options.settings.generation.known_objects, options.settings.generation.distractors,
               models.size(), options.settings.seed);
  ProgressBar progress;
  const auto records =
      evaluateScenes(models, distractors, options.settings,
                     [&progress](int done, int total) { progress("scenes", done, total); });
  const fs::path csv_path = writeCsvFile(records, options.out_dir);
  printSceneEvaluationSummary(records);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s (%.0f s)\n", csv_path.c_str(), seconds);
}

}  // namespace

void addEvaluateScenesCommand(CLI::App& app) {
  auto options = std::make_shared<EvaluateScenesOptions>();
  SceneEvaluationSettings& s = options->settings;
  auto* command = app.add_subcommand(
      "evaluate-scenes",
      "recognise every known object of seeded cluttered table scenes with the scene estimator: "
      "identified, false identifications and pose errors after each view");
  command
      ->add_option("--model", options->models,
                   "a library model as NAME=BUNDLE.h5:MESH (repeat; the mesh the bundle was "
                   "trained on, placed in the scenes)")
      ->required();
  command->add_option("--distractor", options->distractors,
                      "an unknown object: box:X,Y,Z, cylinder:R,H or carton:X,Y,Z,GABLE[,FIN] "
                      "[m], or a mesh file (repeat; default: three boxes and two cylinders)");
  command->add_option("--out", options->out_dir, "directory for scenes.csv")->required();
  command->add_option("--scenes", s.scenes, "number of scenes")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  command->add_option("--views", s.generation.views, "views per scene, on the camera arc")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  command->add_option("--seed", s.seed, "scene s uses seed + s")->capture_default_str();
  command->add_option("--known", s.generation.known_objects, "known objects per scene")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  command->add_option("--distractors", s.generation.distractors, "distractors per scene")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  command->add_flag("--no-noise", options->no_noise, "render the views without depth noise");
  addSensorOption(*command, &options->sensor);
  // The scene estimator's identity settings and the instances' refinement views: the node's
  // identity_* parameters and refinement_views.
  addIdentityOptions(*command, &s.estimator.identification);
  command
      ->add_option("--refinement-views", s.estimator.instance.refinement_views,
                   "views each instance's refinement aligns and verifies together")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  command->callback([options] { runEvaluateScenes(*options); });
}

}  // namespace vdc::tools
