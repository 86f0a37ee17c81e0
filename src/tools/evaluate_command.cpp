// `vdc evaluate --model B.h5 --mesh M --out DIR`: the paper's figure-4 protocol (doc/method.md
// section 11) with the online estimator, per planner and visibility setting, optionally beside the
// single-view baselines (PPF, and PPF followed by ICP) on the same views, and with --stream-rate
// the random views as camera streams (evaluation/stream_evaluation.h). Writes DIR/errors.csv,
// DIR/summary.json and, through scripts/plot_evaluation.py, one PNG per planner (and one comparing
// planners). The options are declared in evaluation_options.cpp, the files written by
// evaluation_csv.cpp and evaluation_summary.cpp, the terminal lines by evaluation_console.cpp.
#include <pcl/console/print.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "evaluation_console.h"
#include "evaluation_csv.h"
#include "evaluation_options.h"
#include "evaluation_summary.h"
#include "progress_bar.h"
#include "python_script.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/baseline_icp.h"
#include "view_direction_classification/evaluation/evaluation.h"
#include "view_direction_classification/evaluation/ppf_baseline.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc::tools {

namespace {

namespace fs = std::filesystem;

constexpr const char* kBaselineName = "ppf_baseline";
constexpr const char* kIcpBaselineName = "ppf_icp_baseline";

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void createOutputDirectory(const std::string& out_dir) {
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) throw Error("cannot create output directory " + out_dir + ": " + error.message());
}

nlohmann::json ppfParameters(const PpfBaseline& ppf) {
  return {{"angle_step_deg", ppf.angleStepDeg()},
          {"requested_angle_step_deg", ppf.parameters().angle_step_deg},
          {"distance_step_m", ppf.parameters().distance_step},
          {"model_spacing_m", ppf.parameters().model_spacing},
          {"model_points", ppf.modelPoints()}};
}

nlohmann::json icpParameters(const BaselineIcp& icp) {
  return {{"icp", "point_to_plane"},
          {"icp_model_spacing_m", icp.parameters().model_spacing},
          {"icp_max_correspondence_distance_m", icp.parameters().max_correspondence_distance},
          {"icp_max_iterations", icp.parameters().max_iterations}};
}

// The single-view baselines on the random planner's views: PCL's PPF alone, then PPF followed by
// ICP (each view matched again, so each row's ms/view is its whole method's).
void runBaselines(const TriangleMesh& mesh, const ModelBundle& model,
                  const EvaluationRequest& request, EvaluationReport& report,
                  const ProgressCallback& progress) {
  // PCL's registration logs every match at INFO level; keep the terminal to the progress bar.
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const auto training_start = std::chrono::steady_clock::now();
  PpfBaseline ppf(mesh);
  const double ppf_seconds = secondsSince(training_start);
  const BaselineIcp icp(mesh);
  const double icp_seconds = secondsSince(training_start);
  const CameraIntrinsics intrinsics = intrinsicsOf(model.parameters);

  const SingleViewMethod ppf_method =
      [&ppf](const pcl::PointCloud<pcl::PointXYZ>& cloud) -> std::optional<Eigen::Isometry3d> {
    const PpfMatch match = ppf.match(cloud);
    if (!match.found) return std::nullopt;
    return match.camera_from_object;
  };
  report.baseline = BaselineResult{evaluateSingleView(ppf_method, kBaselineName, mesh, intrinsics,
                                                      request.anchors, report.settings, progress),
                                   ppf_seconds, ppfParameters(ppf)};

  const SingleViewMethod icp_method = [&ppf, &icp](const pcl::PointCloud<pcl::PointXYZ>& cloud) {
    return matchPpfIcp(ppf, icp, cloud).pose();
  };
  nlohmann::json parameters = ppfParameters(ppf);
  parameters.update(icpParameters(icp));
  report.baseline_icp =
      BaselineResult{evaluateSingleView(icp_method, kIcpBaselineName, mesh, intrinsics,
                                        request.anchors, report.settings, progress),
                     icp_seconds, parameters};
}

fs::path writeErrorsCsvFile(const EvaluationReport& report, const std::string& out_dir) {
  const fs::path path = fs::path(out_dir) / "errors.csv";
  std::ofstream csv(path);
  writeErrorsCsv(csv, report);
  if (!csv) throw Error("cannot write " + path.string());
  return path;
}

fs::path writeSummaryFile(const EvaluationReport& report, const std::string& out_dir) {
  const fs::path path = fs::path(out_dir) / "summary.json";
  std::ofstream(path) << evaluationSummary(report).dump(2) << "\n";
  return path;
}

void runEvaluate(const EvaluateOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const EvaluationRequest request = parseEvaluateOptions(options);
  const auto model = std::make_shared<const ModelBundle>(loadModelBundle(options.model_path));
  const TriangleMesh mesh = loadMesh(options.mesh_path);
  EvaluationReport report;
  report.model_path = options.model_path;
  report.mesh_path = options.mesh_path;
  report.settings = resolveSettings(request.settings, options, *model);
  report.recorded_settings = recordedSettings(options, report.settings);
  createOutputDirectory(options.out_dir);
  printEvaluationStart(options.model_path, options.mesh_path, report.settings);

  ProgressBar progress;
  const ProgressCallback report_progress = [&progress](const std::string& stage, std::size_t done,
                                                       std::size_t total) {
    progress(stage, done, total);
  };
  for (const EvaluationPlanner planner : request.planners) {
    report.results.push_back(
        evaluateEstimator(model, mesh, request.anchors, planner, report.settings, report_progress));
  }
  if (options.baseline) {
    runBaselines(mesh, *model, request, report, report_progress);
  }
  if (report.settings.stream_rate_hz > 0.0) {
    report.streams.push_back(
        evaluateStream(model, mesh, request.anchors, report.settings, report_progress));
  }

  const fs::path csv_path = writeErrorsCsvFile(report, options.out_dir);
  report.seconds_total = secondsSince(start);
  const fs::path summary_path = writeSummaryFile(report, options.out_dir);
  printEvaluationReport(report);
  std::printf("wrote %s and %s (%.0f s)\n", csv_path.c_str(), summary_path.c_str(),
              report.seconds_total);

  if (options.no_figure) return;
  runPythonScript("plot_evaluation.py", {summary_path.string(), options.out_dir}, "plotting",
                  "errors.csv and summary.json are in " + options.out_dir);
}

}  // namespace

void addEvaluateCommand(CLI::App& app) {
  auto options = std::make_shared<EvaluateOptions>();
  auto* evaluate = app.add_subcommand(
      "evaluate",
      "the paper's figure-4 protocol: median MAP error after each view of random view sequences, "
      "per visibility setting and planner, optionally beside single-view baselines (PPF, and PPF "
      "then ICP) and as camera streams");
  addEvaluateOptions(*evaluate, *options);
  evaluate->callback([options] { runEvaluate(*options); });
}

}  // namespace vdc::tools
