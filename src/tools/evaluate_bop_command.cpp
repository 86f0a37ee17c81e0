// `vdc evaluate-bop --dataset DIR --bop-model OBJ_ID=BUNDLE.h5 ... --out OUT`: the scene
// estimator on a BOP dataset's depth images (bop_estimation.h), each target image alone and,
// where the scenes give camera poses, each scene's images fused as a view sequence. Writes BOP
// results files (OUT/vdc-single_NAME-SPLIT.csv, OUT/vdc-fused_NAME-SPLIT.csv), scores them with
// BOP's VSD, MSSD and MSPD recall (bop/bop_scoring.h) into OUT/summary.json and prints the table.
// A subcommand of its own, as evaluate-scenes: it shares none of `evaluate`'s options.
#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "bop_estimation.h"
#include "bop_options.h"
#include "bop_summary.h"
#include "commands.h"
#include "identity_options.h"
#include "progress_bar.h"
#include "view_direction_classification/bop/bop_units.h"
#include "view_direction_classification/common/error.h"

namespace vdc::tools {
namespace {

namespace fs = std::filesystem;

struct EvaluateBopOptions {
  std::string dataset, split = "test", out_dir;
  std::vector<std::string> models;
  int max_images = 0;
  bool no_fusion = false;
  SceneEstimatorParameters estimator;
};

// The targets by scene and image, the first max_images images only (0: all).
std::map<int, std::map<int, std::vector<BopTarget>>> targetsByScene(
    const std::vector<BopTarget>& targets, int max_images, std::vector<BopTarget>* kept) {
  std::map<int, std::map<int, std::vector<BopTarget>>> grouped;
  int images = 0;
  for (const BopTarget& target : targets) {
    auto& scene = grouped[target.scene_id];
    const bool new_image = scene.count(target.im_id) == 0;
    if (new_image && max_images > 0 && images >= max_images) {
      if (scene.empty()) grouped.erase(target.scene_id);
      continue;
    }
    images += new_image ? 1 : 0;
    scene[target.im_id].push_back(target);
    kept->push_back(target);
  }
  return grouped;
}

std::map<int, BopScoringModel> scoringModels(const BopDatasetReader& dataset,
                                             const std::vector<BopTarget>& targets) {
  std::map<int, BopScoringModel> models;
  for (const BopTarget& target : targets) {
    if (models.count(target.obj_id) != 0) continue;
    const auto info = dataset.modelsInfo().find(target.obj_id);
    if (info == dataset.modelsInfo().end()) {
      throw Error("models_info.json has no entry for target object " +
                  std::to_string(target.obj_id));
    }
    TriangleMesh mesh = dataset.modelMesh(target.obj_id);
    std::vector<Eigen::Vector3d> vertices = verticesInMillimetres(mesh);
    models[target.obj_id] = {info->second, std::move(vertices), std::move(mesh)};
  }
  return models;
}

std::string datasetName(const std::string& dataset) {
  // BOP's file name is METHOD_DATASET-SPLIT.csv: no '_' inside the parts.
  std::string name = fs::path(dataset).lexically_normal().filename().string();
  if (name.empty()) name = fs::path(dataset).lexically_normal().parent_path().filename().string();
  std::replace(name.begin(), name.end(), '_', '-');
  return name.empty() ? "dataset" : name;
}

void writeResults(const fs::path& path, const std::vector<BopEstimate>& estimates) {
  std::ofstream csv(path);
  writeBopResultsCsv(csv, estimates);
  if (!csv) throw Error("cannot write " + path.string());
}

double mean(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

BopRun scoredRun(const std::string& name, const BopEstimation& estimation,
                 const std::vector<BopTarget>& targets, const BopScoringTruth& truth,
                 const std::map<int, BopScoringModel>& models) {
  return {name, scoreBopEstimates(estimation.estimates, targets, truth, models),
          mean(estimation.image_seconds), static_cast<int>(estimation.image_seconds.size())};
}

void runEvaluateBop(const EvaluateBopOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  // Refinement's registration logs at INFO level; keep the terminal to the progress bar.
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const BopDatasetReader dataset(options.dataset, options.split);
  const ModelLibrary library = bopModelLibrary(parseObjectPaths(options.models, "--bop-model"));
  std::vector<BopTarget> targets;
  const auto grouped = targetsByScene(dataset.targets(), options.max_images, &targets);
  const auto models = scoringModels(dataset, targets);
  BopScoringTruth truth;
  BopEstimation single, fused;
  ProgressBar progress;
  int done = 0;
  for (const auto& [scene_id, images] : grouped) {
    BopEstimationInput input{&dataset, scene_id, dataset.scene(scene_id), images};
    truth.scenes[scene_id] = input.files;
    // VSD compares with the image's depth (read again: a few hundred kB per image).
    for (const auto& [im_id, image_targets] : images) {
      if (input.files.cameras.count(im_id) != 0) {
        truth.depths[{scene_id, im_id}] = dataset.depth(scene_id, im_id);
      }
    }
    const BopEstimation scene_single = estimateSingleViews(input, library, options.estimator);
    single.estimates.insert(single.estimates.end(), scene_single.estimates.begin(),
                            scene_single.estimates.end());
    single.image_seconds.insert(single.image_seconds.end(), scene_single.image_seconds.begin(),
                                scene_single.image_seconds.end());
    if (!options.no_fusion) {
      const BopEstimation scene_fused = estimateViewSequence(input, library, options.estimator);
      fused.estimates.insert(fused.estimates.end(), scene_fused.estimates.begin(),
                             scene_fused.estimates.end());
      fused.image_seconds.insert(fused.image_seconds.end(), scene_fused.image_seconds.begin(),
                                 scene_fused.image_seconds.end());
    }
    progress("scenes", ++done, static_cast<int>(grouped.size()));
  }
  std::error_code error;
  fs::create_directories(options.out_dir, error);
  if (error) throw Error("cannot create output directory " + options.out_dir);
  const std::string suffix = "_" + datasetName(options.dataset) + "-" + options.split + ".csv";
  std::vector<BopRun> runs{scoredRun("single", single, targets, truth, models)};
  writeResults(fs::path(options.out_dir) / ("vdc-single" + suffix), single.estimates);
  if (!fused.image_seconds.empty()) {
    runs.push_back(scoredRun("fused", fused, targets, truth, models));
    writeResults(fs::path(options.out_dir) / ("vdc-fused" + suffix), fused.estimates);
  }
  const fs::path summary_path = fs::path(options.out_dir) / "summary.json";
  std::ofstream(summary_path) << bopSummaryJson(runs).dump(2) << "\n";
  printBopSummary(runs);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s and the results files (%.0f s)\n", summary_path.c_str(), seconds);
}

}  // namespace

void addEvaluateBopCommand(CLI::App& app) {
  auto options = std::make_shared<EvaluateBopOptions>();
  auto* command = app.add_subcommand(
      "evaluate-bop",
      "the scene estimator on a BOP dataset's depth images (each target image alone, and each "
      "scene's images fused where it gives camera poses): BOP results files and VSD/MSSD/MSPD "
      "recall");
  command->add_option("--dataset", options->dataset, "the BOP dataset's folder")->required();
  command->add_option("--split", options->split, "the split's folder")->capture_default_str();
  command
      ->add_option("--bop-model", options->models,
                   "a trained bundle per object as OBJ_ID=BUNDLE.h5 (repeat; trained on the "
                   "object's mesh in metres)")
      ->required();
  command->add_option("--out", options->out_dir, "directory for the results and summary.json")
      ->required();
  command
      ->add_option("--max-images", options->max_images,
                   "evaluate the first N target images only (0: all)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000000));
  command->add_flag("--no-fusion", options->no_fusion,
                    "skip the view sequences (single images only)");
  addIdentityOptions(*command, &options->estimator.identification);
  command->callback([options] { runEvaluateBop(*options); });
}

}  // namespace vdc::tools
