#include "evaluation_console.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "evaluation_labels.h"
#include "evaluation_summary.h"

namespace vdc::tools {

namespace {

void printTimings(const EvaluationResult& result) {
  std::printf("%s: %.1f ms/view estimator update", result.planner.c_str(), result.mean_update_ms);
  if (result.mean_planning_ms > 0) std::printf(", %.1f ms/view planning", result.mean_planning_ms);
  std::printf("\n");
  const UpdateTiming& t = result.mean_stage_ms;
  std::printf(
      "  stages: features %.1f, classification %.1f, measurement %.1f, fusion %.1f; MAP %.1f "
      "ms/view\n",
      t.features, t.classification, t.measurement, t.fusion, result.mean_map_ms);
}

// The median after views 1, 5, 10, 20 and the last, and when it stays under kConvergedDeg.
void printInsideCone90(const Eigen::VectorXd& fractions);
void printConfidentlyWrong(const Eigen::VectorXd& fractions);
void printPositionInsideEllipsoid90(const Eigen::VectorXd& fractions);

void printSettingMedians(const SettingErrors& setting, int views) {
  const Eigen::VectorXd medians = setting.medianPerView();
  std::printf("  %-5s (%5.1f %% visible): median error", visibilityLabel(setting.radius).c_str(),
              100.0 * setting.visible_fraction);
  for (const int v : {1, 5, 10, 20}) {
    if (v <= views) std::printf("  %2d: %6.1f", v, medians(v - 1));
  }
  if (views != 1 && views != 5 && views != 10 && views != 20) {
    std::printf("  %2d: %6.1f", views, medians(views - 1));
  }
  const std::optional<int> converged = viewsUntilMedianStaysBelow(medians, kConvergedDeg);
  if (converged) {
    std::printf(" deg; < %.0f deg from view %d on\n", kConvergedDeg, *converged);
  } else {
    std::printf(" deg; never < %.0f deg to the end\n", kConvergedDeg);
  }
  printInsideCone90(setting.insideCone90PerView());
  printConfidentlyWrong(setting.confidentlyWrongPerView());
  printPositionInsideEllipsoid90(setting.positionInsideEllipsoid90PerView());
}

// The calibration figure after each view (or at each view's end of a stream).
void printInsideCone90(const Eigen::VectorXd& fractions) {
  if (fractions.size() == 0) return;
  std::printf("        truth inside cone90 after view 1..%d:", static_cast<int>(fractions.size()));
  for (Eigen::Index v = 0; v < fractions.size(); ++v) std::printf(" %.2f", fractions(v));
  std::printf("\n");
}

// The position's calibration figure after each view ("-" where no sequence had a covariance).
void printPositionInsideEllipsoid90(const Eigen::VectorXd& fractions) {
  if (fractions.size() == 0) return;
  std::printf("        true position inside its covariance's 90 %% ellipsoid after view 1..%d:",
              static_cast<int>(fractions.size()));
  for (Eigen::Index v = 0; v < fractions.size(); ++v) {
    if (std::isnan(fractions(v))) {
      std::printf(" -");
    } else {
      std::printf(" %.2f", fractions(v));
    }
  }
  std::printf("\n");
}

// Printed only where it happened: on the renders it is nearly always none.
void printConfidentlyWrong(const Eigen::VectorXd& fractions) {
  if (fractions.size() == 0 || fractions.maxCoeff() == 0.0) return;
  std::printf("        confidently wrong (error > 2 x cone90 and > %.0f deg) after view 1..%d:",
              SettingErrors::kConfidentlyWrongMinDeg, static_cast<int>(fractions.size()));
  for (Eigen::Index v = 0; v < fractions.size(); ++v) std::printf(" %.2f", fractions(v));
  std::printf("\n");
}

void printStream(const StreamEvaluationResult& stream) {
  std::printf(
      "%s: render %.1f ms/frame; update %.2f ms per frame not featurised, %.1f ms per featurised "
      "frame\n",
      stream.name.c_str(), stream.mean_render_ms, stream.mean_unfeaturised_update_ms,
      stream.mean_featurised_update_ms);
  for (const auto& setting : stream.settings) {
    int frames = 0, featurised = 0, inside = 0;
    double seconds = 0.0;
    for (const auto& sequence : setting.sequences) {
      frames += sequence.frames;
      featurised += sequence.featurised;
      seconds += sequence.duration_s;
      inside += !sequence.view_ends.empty() && sequence.view_ends.back().insideCone90();
    }
    const Eigen::VectorXd medians = setting.medianAtViewEnds();
    std::printf("  %-5s %d frames, %d featurised (%.1f %%, %.2f per s of stream); median error",
                visibilityLabel(setting.radius).c_str(), frames, featurised,
                frames > 0 ? 100.0 * featurised / frames : 0.0,
                seconds > 0 ? featurised / seconds : 0.0);
    for (Eigen::Index v = 0; v < medians.size(); ++v) std::printf(" %.1f", medians(v));
    std::printf(" deg at view ends; truth inside cone90 at the end: %d of %zu\n", inside,
                setting.sequences.size());
    printInsideCone90(setting.insideCone90AtViewEnds());
  }
}

void printBaseline(const BaselineResult& baseline) {
  std::printf("%s: %.1f ms/view, trained in %.1f s\n", baseline.result.planner.c_str(),
              baseline.result.mean_update_ms, baseline.training_seconds);
  for (const auto& setting : baseline.result.settings) {
    std::printf("  %-5s single-view median error %6.1f deg (%d views without a pose)\n",
                visibilityLabel(setting.radius).c_str(), medianOverAllViews(setting),
                setting.skipped_views);
  }
}

}  // namespace

void printEvaluationStart(const std::string& model_path, const std::string& mesh_path,
                          const EvaluationSettings& settings) {
  std::fprintf(stderr,
               "evaluating %s on %s: %d sequences x %d views, %zu visibility settings, seed %u, "
               "noise %s",
               model_path.c_str(), mesh_path.c_str(), settings.sequences, settings.views,
               settings.visibility_radii.size(), settings.seed, settings.noise ? "on" : "off");
  if (settings.stream_rate_hz > 0.0) {
    std::fprintf(stderr, ", and as %g Hz streams (%g s at each view)", settings.stream_rate_hz,
                 settings.stream_dwell_s);
  }
  std::fprintf(stderr, "\n");
}

void printEvaluationReport(const EvaluationReport& report) {
  for (const auto& result : report.results) {
    printTimings(result);
    for (const auto& setting : result.settings) printSettingMedians(setting, report.settings.views);
  }
  if (report.baseline) printBaseline(*report.baseline);
  if (report.baseline_icp) printBaseline(*report.baseline_icp);
  for (const auto& stream : report.streams) printStream(stream);
}

}  // namespace vdc::tools
