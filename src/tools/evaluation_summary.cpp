#include "evaluation_summary.h"

#include <algorithm>
#include <string>
#include <vector>

#include "evaluation_labels.h"

namespace vdc::tools {

namespace {

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

nlohmann::json plannerSummary(const EvaluationResult& result, int views) {
  nlohmann::json settings = nlohmann::json::array();
  for (const auto& setting : result.settings) settings.push_back(settingSummary(setting, views));
  const UpdateTiming& stage = result.mean_stage_ms;
  return {{"planner", result.planner},
          {"ms_per_view", result.mean_update_ms},
          {"planning_ms_per_view", result.mean_planning_ms},
          {"map_ms_per_view", result.mean_map_ms},
          {"stage_ms_per_view",
           {{"segmentation", stage.segmentation},
            {"features", stage.features},
            {"classification", stage.classification},
            {"measurement", stage.measurement},
            {"fusion", stage.fusion}}},
          {"settings", settings}};
}

nlohmann::json baselineSummary(const BaselineResult& baseline) {
  nlohmann::json settings = nlohmann::json::array();
  for (const auto& setting : baseline.result.settings) {
    settings.push_back({{"visibility", visibilityLabel(setting.radius)},
                        {"median_error_deg", medianOverAllViews(setting)},
                        {"views_without_pose", setting.skipped_views}});
  }
  return {{"name", baseline.result.planner},
          {"ms_per_view", baseline.result.mean_update_ms},
          {"training_seconds", baseline.training_seconds},
          {"settings", settings}};
}

}  // namespace

double medianOverAllViews(const SettingErrors& setting) {
  std::vector<double> all(setting.errors_deg.data(),
                          setting.errors_deg.data() + setting.errors_deg.size());
  std::sort(all.begin(), all.end());
  const std::size_t n = all.size();
  return n % 2 ? all[n / 2] : 0.5 * (all[n / 2 - 1] + all[n / 2]);
}

nlohmann::json evaluationSummary(const EvaluationReport& report) {
  nlohmann::json planners = nlohmann::json::array();
  for (const auto& result : report.results) {
    planners.push_back(plannerSummary(result, report.settings.views));
  }
  nlohmann::json summary = report.recorded_settings;
  summary["model"] = report.model_path;
  summary["mesh"] = report.mesh_path;
  summary["seconds_total"] = report.seconds_total;
  summary["planners"] = planners;
  summary["baseline"] =
      report.baseline ? baselineSummary(*report.baseline) : nlohmann::json(nullptr);
  return summary;
}

}  // namespace vdc::tools
