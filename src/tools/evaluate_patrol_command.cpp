// `vdc evaluate-patrol --model NAME=BUNDLE.h5:MESH ... --out DIR`: the object memory over time
// (evaluation/patrol_evaluation.h, issue 30 item 6). A seeded table of evaluate-scenes' kind is
// patrolled: per pass, the camera's arc fed to one scene estimator, a look away, then random
// changes on the table (objects moved, taken away, put back or new). Writes DIR/patrol.csv
// (patrol_evaluation_csv.cpp) and prints the per-pass figures against the targets
// (patrol_evaluation_summary.cpp).
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
#include "patrol_evaluation_csv.h"
#include "patrol_evaluation_summary.h"
#include "progress_bar.h"
#include "scene_evaluation_options.h"
#include "view_direction_classification/common/error.h"

namespace vdc::tools {

namespace {

namespace fs = std::filesystem;

struct EvaluatePatrolOptions {
  std::vector<std::string> models;
  std::vector<std::string> distractors;
  std::string out_dir;
  bool no_noise = false;
  PatrolSettings settings;
};

fs::path writePatrolCsvFile(const PatrolResult& result, const std::string& out_dir) {
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) throw Error("cannot create output directory " + out_dir + ": " + error.message());
  const fs::path path = fs::path(out_dir) / "patrol.csv";
  std::ofstream csv(path);
  writePatrolCsv(csv, result);
  if (!csv) throw Error("cannot write " + path.string());
  return path;
}

void runEvaluatePatrol(EvaluatePatrolOptions options) {
  const auto start = std::chrono::steady_clock::now();
  // Refinement's registration logs at INFO level; keep the terminal to the progress bar.
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const std::vector<SceneEvaluationModel> models = loadSceneModels(options.models);
  const std::vector<TriangleMesh> distractors = loadDistractorMeshes(options.distractors);
  options.settings.noise = !options.no_noise;
  checkPatrolSettings(options.settings);
  const PatrolSettings& s = options.settings;
  std::fprintf(stderr,
               "%d passes x %d views, %d changes between passes, %d known + %d distractors, "
               "%zu models, seed %u\n",
               s.passes, s.generation.views, s.changes.changes, s.generation.known_objects,
               s.generation.distractors, models.size(), s.seed);
  ProgressBar progress;
  const PatrolResult result = evaluatePatrol(
      models, distractors, s, [&progress](int done, int total) { progress("views", done, total); });
  const fs::path csv_path = writePatrolCsvFile(result, options.out_dir);
  printPatrolSummary(result);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s (%.0f s)\n", csv_path.c_str(), seconds);
}

// The patrol's defaults: a smaller table than evaluate-scenes' clutter, so that one arc sees
// most of it, and no occluders placed for the first view (the arc comes back every pass).
PatrolSettings patrolDefaults() {
  PatrolSettings settings;
  settings.generation.views = 3;
  settings.generation.known_objects = 3;
  settings.generation.distractors = 2;
  settings.generation.occluder_fraction = 0.0;
  settings.generation.scatter_radius = 0.2;
  return settings;
}

void addSceneOptions(CLI::App* command, EvaluatePatrolOptions* options) {
  command
      ->add_option("--model", options->models,
                   "a library model as NAME=BUNDLE.h5:MESH (repeat; the mesh the bundle was "
                   "trained on, placed on the table)")
      ->required();
  command->add_option("--distractor", options->distractors,
                      "an unknown object: box:X,Y,Z, cylinder:R,H or carton:X,Y,Z,GABLE[,FIN] "
                      "[m], or a mesh file (repeat; default: three boxes and two cylinders)");
  command->add_option("--out", options->out_dir, "directory for patrol.csv")->required();
  SceneGenerationSettings& g = options->settings.generation;
  command->add_option("--known", g.known_objects, "known objects on the table at the start")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  command->add_option("--distractors", g.distractors, "distractors on the table")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  command->add_option("--seed", options->settings.seed, "the table, its noise and its changes")
      ->capture_default_str();
  command->add_flag("--no-noise", options->no_noise, "render the views without depth noise");
}

}  // namespace

void addEvaluatePatrolCommand(CLI::App& app) {
  auto options = std::make_shared<EvaluatePatrolOptions>();
  options->settings = patrolDefaults();
  PatrolSettings& s = options->settings;
  auto* command = app.add_subcommand(
      "evaluate-patrol",
      "patrol a seeded table that changes between passes with the scene estimator: instances "
      "right, duplicates, stale instances, views to notice each change, memory size");
  addSceneOptions(command, options.get());
  command->add_option("--passes", s.passes, "passes of the camera over the table")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  command->add_option("--views-per-pass", s.generation.views, "views per pass, on the arc")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  command
      ->add_option("--changes-per-pass", s.changes.changes,
                   "random changes on the table between two passes")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  command->add_option("--max-move", s.changes.max_move, "[m] farthest a moved object goes")
      ->capture_default_str()
      ->check(CLI::Range(0.03, 1.0));
  addIdentityOptions(*command, &s.estimator.identification);
  command->callback([options] { runEvaluatePatrol(*options); });
}

}  // namespace vdc::tools
