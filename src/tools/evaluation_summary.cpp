#include "evaluation_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "evaluation_labels.h"

namespace vdc::tools {

namespace {

std::vector<double> toVector(const Eigen::VectorXd& values) {
  return std::vector<double>(values.data(), values.data() + values.size());
}

// A value, or null for NaN (JSON has no NaN).
nlohmann::json numberOrNull(double value) {
  return std::isnan(value) ? nlohmann::json(nullptr) : nlohmann::json(value);
}

// The medians after views 1, 5, 10, 20 and the last, keyed by the view count.
nlohmann::json afterViews(const Eigen::VectorXd& medians, int views) {
  nlohmann::json after = nlohmann::json::object();
  for (const int v : {1, 5, 10, 20}) {
    if (v <= views) after[std::to_string(v)] = numberOrNull(medians(v - 1));
  }
  after[std::to_string(views)] = numberOrNull(medians(views - 1));  // and after the last view
  return after;
}

nlohmann::json settingSummary(const SettingErrors& setting, int views) {
  const Eigen::VectorXd medians = setting.medianPerView();
  const nlohmann::json after = afterViews(medians, views);
  nlohmann::json position_medians = nlohmann::json::array();
  nlohmann::json position_after = nullptr;
  if (setting.position_errors_mm.cols() == views) {
    const Eigen::VectorXd positions = setting.medianPositionPerView();
    for (Eigen::Index v = 0; v < positions.size(); ++v) {
      position_medians.push_back(numberOrNull(positions(v)));
    }
    position_after = afterViews(positions, views);
  }
  const std::optional<int> converged = viewsUntilMedianStaysBelow(medians, kConvergedDeg);
  return {
      {"visibility", visibilityLabel(setting.radius)},
      {"visible_fraction", setting.visible_fraction},
      {"skipped_views", setting.skipped_views},
      {"median_error_deg", std::vector<double>(medians.data(), medians.data() + medians.size())},
      {"median_error_after_views", after},
      {"median_position_error_mm", position_medians},
      {"median_position_error_mm_after_views", position_after},
      {"views_until_median_below_5deg", converged ? nlohmann::json(*converged) : nlohmann::json()},
      {"inside_cone90_fraction", toVector(setting.insideCone90PerView())},
      {"confidently_wrong_fraction", toVector(setting.confidentlyWrongPerView())},
      {"position_inside_ellipsoid90_fraction",
       toVector(setting.positionInsideEllipsoid90PerView())}};
}

double medianOf(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// A stream setting's figures at the end of the stream (its last view's dwell) and over it.
nlohmann::json streamSettingSummary(const StreamSettingResult& setting) {
  std::vector<double> final_error, final_cone, views_fused, featurised_per_s;
  int frames = 0, featurised = 0, fused = 0, not_novel = 0, skipped = 0, inside = 0;
  for (const StreamSequenceResult& sequence : setting.sequences) {
    frames += sequence.frames;
    featurised += sequence.featurised;
    fused += sequence.fused;
    not_novel += sequence.not_novel;
    skipped += sequence.skipped;
    featurised_per_s.push_back(sequence.featurisedPerSecond());
    if (sequence.view_ends.empty()) continue;
    const StreamSample& last = sequence.view_ends.back();
    final_error.push_back(last.map_error_deg);
    final_cone.push_back(last.cone90_deg);
    views_fused.push_back(last.views_fused);
    inside += last.insideCone90();
  }
  const double sequences = static_cast<double>(setting.sequences.size());
  return {{"visibility", visibilityLabel(setting.radius)},
          {"median_error_deg_at_view_ends", toVector(setting.medianAtViewEnds())},
          {"inside_cone90_fraction_at_view_ends", toVector(setting.insideCone90AtViewEnds())},
          {"final_median_error_deg", medianOf(final_error)},
          {"final_median_cone90_deg", medianOf(final_cone)},
          {"final_inside_cone90_fraction", sequences > 0 ? inside / sequences : 0.0},
          {"final_median_views_fused", medianOf(views_fused)},
          {"frames", frames},
          {"frames_featurised", featurised},
          {"featurised_fraction", frames > 0 ? static_cast<double>(featurised) / frames : 0.0},
          {"median_featurised_per_s", medianOf(featurised_per_s)},
          {"frames_fused", fused},
          {"frames_not_novel", not_novel},
          {"frames_skipped", skipped}};
}

nlohmann::json streamSummary(const StreamEvaluationResult& stream, const EvaluationSettings& used) {
  nlohmann::json settings = nlohmann::json::array();
  for (const auto& setting : stream.settings) settings.push_back(streamSettingSummary(setting));
  return {{"name", stream.name},
          {"rate_hz", stream.rate_hz},
          {"dwell_s", used.stream_dwell_s},
          {"render_ms_per_frame", stream.mean_render_ms},
          {"update_ms_per_unfeaturised_frame", stream.mean_unfeaturised_update_ms},
          {"update_ms_per_featurised_frame", stream.mean_featurised_update_ms},
          {"settings", settings}};
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
            {"fusion", stage.fusion},
            {"refinement", stage.refinement}}},
          {"settings", settings}};
}

nlohmann::json baselineSummary(const BaselineResult& baseline) {
  nlohmann::json settings = nlohmann::json::array();
  for (const auto& setting : baseline.result.settings) {
    const double position_mm = setting.position_errors_mm.size() > 0
                                   ? medianIgnoringNaN(setting.position_errors_mm.data(),
                                                       setting.position_errors_mm.size())
                                   : std::numeric_limits<double>::quiet_NaN();
    settings.push_back({{"visibility", visibilityLabel(setting.radius)},
                        {"median_error_deg", medianOverAllViews(setting)},
                        {"median_position_error_mm", numberOrNull(position_mm)},
                        {"views_without_pose", setting.skipped_views}});
  }
  return {{"name", baseline.result.planner},
          {"ms_per_view", baseline.result.mean_update_ms},
          {"training_seconds", baseline.training_seconds},
          {"parameters", baseline.parameters},
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
  summary["baseline_icp"] =
      report.baseline_icp ? baselineSummary(*report.baseline_icp) : nlohmann::json(nullptr);
  nlohmann::json streams = nlohmann::json::array();
  for (const auto& stream : report.streams) {
    streams.push_back(streamSummary(stream, report.settings));
  }
  summary["streams"] = streams;
  return summary;
}

}  // namespace vdc::tools
