// `vdc evaluate --model B.h5 --mesh M --out DIR`: the paper's figure-4 protocol (doc/method.md
// section 11) with the online estimator, per planner and visibility setting, optionally beside the
// single-view PPF baseline on the same views. Writes DIR/errors.csv, DIR/summary.json and, through
// scripts/plot_evaluation.py, one PNG per planner (and one comparing planners).
#include <pcl/console/print.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "progress_bar.h"
#include "python_script.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/evaluation.h"
#include "view_direction_classification/evaluation/ppf_baseline.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc::tools {

namespace {

namespace fs = std::filesystem;

// The paper's settings: all visible and r_vis = 8 .. 3 cm.
constexpr const char* kDefaultVisibility = "all,0.08,0.07,0.06,0.05,0.04,0.03";
constexpr const char* kBaselineName = "ppf_baseline";

struct EvaluateOptions {
  std::string model_path, mesh_path, out_dir;
  std::string visibility = kDefaultVisibility;
  std::string planners = "random";
  std::string anchors;  // empty: the built-in mug's two handle points
  bool baseline = false;
  bool no_noise = false;
  bool no_figure = false;
  EvaluationSettings settings;
};

std::vector<std::string> splitList(const std::string& text, char separator) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, separator);) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

// "x,y,z;x,y,z" in metres, object frame.
std::vector<Eigen::Vector3d> parseAnchors(const std::string& text) {
  std::vector<Eigen::Vector3d> anchors;
  for (const std::string& point : splitList(text, ';')) {
    const std::vector<std::string> coordinates = splitList(point, ',');
    Eigen::Vector3d anchor;
    bool valid = coordinates.size() == 3;
    for (std::size_t k = 0; valid && k < 3; ++k) {
      char* end = nullptr;
      anchor(static_cast<Eigen::Index>(k)) = std::strtod(coordinates[k].c_str(), &end);
      valid = end == coordinates[k].c_str() + coordinates[k].size() && std::isfinite(anchor(k));
    }
    if (!valid) {
      throw Error("--anchors: '" + point +
                  "' is not a point x,y,z in metres (points separated by ;)");
    }
    anchors.push_back(anchor);
  }
  if (anchors.empty()) throw Error("--anchors: no anchor point given");
  return anchors;
}

// The planner question: after how many views the median error gets under 5 degrees and
// stays there for the rest of the sequence (a dip that comes back up does not count).
constexpr double kConvergedDeg = 5.0;

nlohmann::json settingSummary(const SettingErrors& setting, int views) {
  const Eigen::VectorXd medians = setting.medianPerView();
  nlohmann::json after = nlohmann::json::object();
  for (const int v : {1, 5, 10, 20}) {
    if (v <= views) after[std::to_string(v)] = medians(v - 1);
  }
  after[std::to_string(views)] = medians(views - 1);  // and after the last view
  const std::optional<int> converged = viewsUntilMedianStaysBelow(medians, kConvergedDeg);
  return {
      {"visibility", visibilityLabel(setting.radius)},
      {"visible_fraction", setting.visible_fraction},
      {"skipped_views", setting.skipped_views},
      {"median_error_deg", std::vector<double>(medians.data(), medians.data() + medians.size())},
      {"median_error_after_views", after},
      {"views_until_median_below_5deg", converged ? nlohmann::json(*converged) : nlohmann::json()}};
}

// The baseline judges each view alone: one median over all its views per setting.
nlohmann::json baselineSummary(const EvaluationResult& baseline, double training_seconds) {
  nlohmann::json settings = nlohmann::json::array();
  for (const auto& setting : baseline.settings) {
    std::vector<double> all(setting.errors_deg.data(),
                            setting.errors_deg.data() + setting.errors_deg.size());
    std::sort(all.begin(), all.end());
    const std::size_t n = all.size();
    const double median = n % 2 ? all[n / 2] : 0.5 * (all[n / 2 - 1] + all[n / 2]);
    settings.push_back({{"visibility", visibilityLabel(setting.radius)},
                        {"median_error_deg", median},
                        {"views_without_pose", setting.skipped_views}});
  }
  return {{"name", baseline.planner},
          {"ms_per_view", baseline.mean_update_ms},
          {"training_seconds", training_seconds},
          {"settings", settings}};
}

void runEvaluate(EvaluateOptions options, const CLI::App& command) {
  const auto start = std::chrono::steady_clock::now();
  EvaluationSettings settings = options.settings;
  settings.visibility_radii.clear();
  for (const std::string& label : splitList(options.visibility, ',')) {
    settings.visibility_radii.push_back(parseVisibility(label));
  }
  if (settings.visibility_radii.empty()) throw Error("--visibility: no setting given");
  std::vector<EvaluationPlanner> planners;
  for (const std::string& name : splitList(options.planners, ',')) {
    planners.push_back(parseEvaluationPlanner(name));
  }
  if (planners.empty()) throw Error("--planner: no planner given");
  const std::vector<Eigen::Vector3d> anchors =
      options.anchors.empty() ? mugHandleAnchors() : parseAnchors(options.anchors);

  const auto model = std::make_shared<const ModelBundle>(loadModelBundle(options.model_path));
  const TriangleMesh mesh = loadMesh(options.mesh_path);
  // Evaluate at the distance the model was trained for unless told otherwise.
  if (command.count("--distance") == 0) settings.distance = model->parameters.distance;
  settings.noise = !options.no_noise;
  checkEvaluationSettings(settings);

  std::error_code error;
  fs::create_directories(options.out_dir, error);
  if (error) {
    throw Error("cannot create output directory " + options.out_dir + ": " + error.message());
  }
  std::fprintf(stderr,
               "evaluating %s on %s: %d sequences x %d views, %zu visibility settings, seed %u, "
               "noise %s\n",
               options.model_path.c_str(), options.mesh_path.c_str(), settings.sequences,
               settings.views, settings.visibility_radii.size(), settings.seed,
               settings.noise ? "on" : "off");

  ProgressBar progress;
  const ProgressCallback report = [&progress](const std::string& stage, std::size_t done,
                                              std::size_t total) { progress(stage, done, total); };
  std::vector<EvaluationResult> results;
  for (const EvaluationPlanner planner : planners) {
    results.push_back(evaluateEstimator(model, mesh, anchors, planner, settings, report));
  }
  std::optional<EvaluationResult> baseline;
  double baseline_training_seconds = 0;
  if (options.baseline) {
    // PCL's registration logs every match at INFO level; keep the terminal to the progress bar.
    pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
    const auto training_start = std::chrono::steady_clock::now();
    PpfBaseline ppf(mesh);
    baseline_training_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - training_start).count();
    const SingleViewMethod method =
        [&ppf](const pcl::PointCloud<pcl::PointXYZ>& cloud) -> std::optional<Eigen::Isometry3d> {
      const PpfMatch match = ppf.match(cloud);
      if (!match.found) return std::nullopt;
      return match.camera_from_object;
    };
    baseline = evaluateSingleView(method, kBaselineName, mesh, intrinsicsOf(model->parameters),
                                  anchors, settings, report);
  }

  const fs::path csv_path = fs::path(options.out_dir) / "errors.csv";
  {
    std::ofstream csv(csv_path);
    std::vector<EvaluationResult> rows = results;
    if (baseline) rows.push_back(*baseline);
    writeErrorsCsv(csv, rows);
    if (!csv) throw Error("cannot write " + csv_path.string());
  }

  nlohmann::json planner_summaries = nlohmann::json::array();
  for (const auto& result : results) {
    nlohmann::json setting_summaries = nlohmann::json::array();
    for (const auto& setting : result.settings) {
      setting_summaries.push_back(settingSummary(setting, settings.views));
    }
    planner_summaries.push_back({{"planner", result.planner},
                                 {"ms_per_view", result.mean_update_ms},
                                 {"planning_ms_per_view", result.mean_planning_ms},
                                 {"map_ms_per_view", result.mean_map_ms},
                                 {"stage_ms_per_view",
                                  {{"segmentation", result.mean_stage_ms.segmentation},
                                   {"features", result.mean_stage_ms.features},
                                   {"classification", result.mean_stage_ms.classification},
                                   {"measurement", result.mean_stage_ms.measurement},
                                   {"fusion", result.mean_stage_ms.fusion}}},
                                 {"settings", setting_summaries}});
  }
  const double total_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json summary = {
      {"model", options.model_path},
      {"mesh", options.mesh_path},
      {"sequences", settings.sequences},
      {"views", settings.views},
      {"candidates", settings.candidates},
      {"seed", settings.seed},
      {"distance_m", settings.distance},
      {"noise", settings.noise},
      {"estimator",
       {{"n_feat", settings.estimator.n_feat},
        {"kappa", settings.estimator.kappa},
        {"max_components", settings.estimator.max_components},
        {"min_weight", settings.estimator.min_weight},
        {"belief_weight_floor", settings.estimator.belief_weight_floor}}},
      {"seconds_total", total_seconds},
      {"planners", planner_summaries},
      {"baseline",
       baseline ? baselineSummary(*baseline, baseline_training_seconds) : nlohmann::json(nullptr)}};
  const fs::path summary_path = fs::path(options.out_dir) / "summary.json";
  std::ofstream(summary_path) << summary.dump(2) << "\n";

  // The numbers the README quotes, on the terminal too.
  for (const auto& result : results) {
    std::printf("%s: %.1f ms/view estimator update", result.planner.c_str(), result.mean_update_ms);
    if (result.mean_planning_ms > 0) {
      std::printf(", %.1f ms/view planning", result.mean_planning_ms);
    }
    std::printf("\n");
    const UpdateTiming& t = result.mean_stage_ms;
    std::printf(
        "  stages: features %.1f, classification %.1f, measurement %.1f, fusion %.1f; MAP %.1f "
        "ms/view\n",
        t.features, t.classification, t.measurement, t.fusion, result.mean_map_ms);
    for (const auto& setting : result.settings) {
      const Eigen::VectorXd medians = setting.medianPerView();
      std::printf("  %-5s (%5.1f %% visible): median error",
                  visibilityLabel(setting.radius).c_str(), 100.0 * setting.visible_fraction);
      for (const int v : {1, 5, 10, 20}) {
        if (v <= settings.views) std::printf("  %2d: %6.1f", v, medians(v - 1));
      }
      const int last = settings.views;
      if (last != 1 && last != 5 && last != 10 && last != 20) {
        std::printf("  %2d: %6.1f", last, medians(last - 1));
      }
      const std::optional<int> converged = viewsUntilMedianStaysBelow(medians, kConvergedDeg);
      if (converged) {
        std::printf(" deg; < %.0f deg from view %d on\n", kConvergedDeg, *converged);
      } else {
        std::printf(" deg; never < %.0f deg to the end\n", kConvergedDeg);
      }
    }
  }
  if (baseline) {
    const nlohmann::json b = baselineSummary(*baseline, baseline_training_seconds);
    std::printf("%s: %.1f ms/view, trained in %.1f s\n", kBaselineName, baseline->mean_update_ms,
                baseline_training_seconds);
    for (const auto& s : b["settings"]) {
      std::printf("  %-5s single-view median error %6.1f deg (%d views without a pose)\n",
                  s["visibility"].get<std::string>().c_str(), s["median_error_deg"].get<double>(),
                  s["views_without_pose"].get<int>());
    }
  }
  std::printf("wrote %s and %s (%.0f s)\n", csv_path.c_str(), summary_path.c_str(), total_seconds);

  if (options.no_figure) return;
  runPythonScript("plot_evaluation.py", {summary_path.string(), options.out_dir}, "plotting",
                  "errors.csv and summary.json are in " + options.out_dir);
}

// CLI validators, so a malformed list is a usage error (exit code 2) reported before any work.
std::string checkVisibilityList(const std::string& text) {
  try {
    for (const std::string& label : splitList(text, ',')) parseVisibility(label);
  } catch (const Error& error) {
    return error.what();
  }
  return splitList(text, ',').empty() ? "no visibility setting given" : "";
}

std::string checkPlannerList(const std::string& text) {
  try {
    for (const std::string& name : splitList(text, ',')) parseEvaluationPlanner(name);
  } catch (const Error& error) {
    return error.what();
  }
  return splitList(text, ',').empty() ? "no planner given" : "";
}

}  // namespace

void addEvaluateCommand(CLI::App& app) {
  auto options = std::make_shared<EvaluateOptions>();
  EvaluationSettings& s = options->settings;
  auto* evaluate = app.add_subcommand(
      "evaluate",
      "the paper's figure-4 protocol: median MAP error after each view of random view sequences, "
      "per visibility setting and planner, optionally beside a single-view PPF baseline");
  evaluate->add_option("--model", options->model_path, "model bundle (HDF5)")->required();
  evaluate->add_option("--mesh", options->mesh_path, "the object's mesh (the model's object)")
      ->required();
  evaluate->add_option("--out", options->out_dir, "output directory")->required();
  evaluate->add_option("--sequences", s.sequences, "random view sequences")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  evaluate->add_option("--views", s.views, "views per sequence")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  evaluate
      ->add_option("--visibility", options->visibility,
                   "comma-separated settings: 'all' or a radius [m] around the anchors")
      ->capture_default_str()
      ->check(CLI::Validator(checkVisibilityList, "LIST"));
  evaluate
      ->add_option("--planner", options->planners,
                   "comma-separated: random, informativeness, information_gain")
      ->capture_default_str()
      ->check(CLI::Validator(checkPlannerList, "LIST"));
  evaluate
      ->add_option("--candidates", s.candidates,
                   "random candidate views per sequence the planners choose from")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  evaluate->add_option("--anchors", options->anchors,
                       "visibility anchors 'x,y,z;x,y,z' [m, object frame]; default: the mug's "
                       "two handle points");
  evaluate->add_option("--seed", s.seed, "seed of sequences, orientations and noise")
      ->capture_default_str();
  evaluate->add_option("--distance", s.distance, "camera distance [m]; default: the model's");
  evaluate->add_option("--threads", s.threads, "OpenMP threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  // The estimator's tuning knobs (every default was tuned with this evaluation: doc/method.md, "Defaults").
  evaluate
      ->add_option("--n-feat", s.estimator.n_feat,
                   "most certain features summed per view; 0: the model's value")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  evaluate
      ->add_option("--kappa", s.estimator.kappa,
                   "girdle concentration; 0: the default for the model's view spacing")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  evaluate->add_option("--max-components", s.estimator.max_components, "K_max of the belief")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  evaluate
      ->add_option("--min-weight", s.estimator.min_weight,
                   "measurement components below this p_sum are dropped")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.5));
  evaluate
      ->add_option("--belief-weight-floor", s.estimator.belief_weight_floor,
                   "belief components below this fraction of the heaviest are dropped")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.5));
  evaluate->add_flag("--baseline", options->baseline,
                     "also run the single-view PPF baseline (PCL) on the random planner's views");
  evaluate->add_flag("--no-noise", options->no_noise, "render the views without sensor noise");
  evaluate->add_flag("--no-figure", options->no_figure, "no plots (no matplotlib needed)");
  evaluate->callback([options, evaluate] { runEvaluate(*options, *evaluate); });
}

}  // namespace vdc::tools
