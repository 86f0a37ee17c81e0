#pragma once

#include <nlohmann/json.hpp>

#include "evaluation_report.h"

namespace vdc::tools {

// summary.json: the recorded settings, then per planner its timings and per setting the median
// error after each view, the medians after 1, 5, 10, 20 and the last view and the views until the
// median stays under kConvergedDeg, and the calibration figure (the fraction of sequences whose
// true orientation lies within cone90 of the MAP) after each view; the baselines' single-view
// medians and settings, "baseline" (PPF) and "baseline_icp" (PPF then ICP), or null; the streams'
// figures (an empty list without --stream-rate).
nlohmann::json evaluationSummary(const EvaluationReport& report);

// The median of every view's error in a setting: the baseline judges each view alone.
double medianOverAllViews(const SettingErrors& setting);

}  // namespace vdc::tools
