// `vdc evaluate --model B.h5 --mesh M --out DIR`: the paper's figure-4 protocol (doc/method.md
// section 11) with the online estimator, per planner and visibility setting, optionally beside the
// single-view PPF baseline on the same views, and with --stream-rate the random views as camera
// streams (evaluation/stream_evaluation.h). Writes DIR/errors.csv, DIR/summary.json and, through
// scripts/plot_evaluation.py, one PNG per planner (and one comparing planners).
// The options are declared in evaluation_options.cpp, the files written by evaluation_csv.cpp
// and evaluation_summary.cpp, the terminal lines by evaluation_console.cpp.
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
#include "view_direction_classification/evaluation/evaluation.h"
#include "view_direction_classification/evaluation/ppf_baseline.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc::tools {

namespace {

namespace fs = std::filesystem;

constexpr const char* kBaselineName = "ppf_baseline";

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void createOutputDirectory(const std::string& out_dir) {
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) throw Error("cannot create output directory " + out_dir + ": " + error.message());
}

// The single-view PPF baseline on the random planner's views.
BaselineResult runPpfBaseline(const TriangleMesh& mesh, const ModelBundle& model,
                              const EvaluationRequest& request, const EvaluationSettings& settings,
                              const ProgressCallback& report) {
  // PCL's registration logs every match at INFO level; keep the terminal to the progress bar.
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  BaselineResult baseline;
  const auto training_start = std::chrono::steady_clock::now();
  PpfBaseline ppf(mesh);
  baseline.training_seconds = secondsSince(training_start);
  const SingleViewMethod method =
      [&ppf](const pcl::PointCloud<pcl::PointXYZ>& cloud) -> std::optional<Eigen::Isometry3d> {
    const PpfMatch match = ppf.match(cloud);
    if (!match.found) return std::nullopt;
    return match.camera_from_object;
  };
  baseline.result = evaluateSingleView(method, kBaselineName, mesh, intrinsicsOf(model.parameters),
                                       request.anchors, settings, report);
  return baseline;
}

fs::path writeErrorsCsvFile(const EvaluationReport& report, const std::string& out_dir) {
  const fs::path path = fs::path(out_dir) / "errors.csv";
  std::ofstream csv(path);
  std::vector<EvaluationResult> rows = report.results;
  if (report.baseline) rows.push_back(report.baseline->result);
  writeErrorsCsv(csv, rows, report.streams);
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
    report.baseline = runPpfBaseline(mesh, *model, request, report.settings, report_progress);
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
      "per visibility setting and planner, optionally beside a single-view PPF baseline and as "
      "camera streams");
  addEvaluateOptions(*evaluate, *options);
  evaluate->callback([options] { runEvaluate(*options); });
}

}  // namespace vdc::tools
