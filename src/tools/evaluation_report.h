#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/evaluation/evaluation.h"
#include "view_direction_classification/evaluation/stream_evaluation.h"

namespace vdc::tools {

// A single-view baseline's results, the time its model took to build and its settings as used
// (summary.json).
struct BaselineResult {
  EvaluationResult result;
  double training_seconds = 0;
  nlohmann::json parameters = nlohmann::json::object();
};

// Everything one `vdc evaluate` run reports, in summary.json and on the terminal.
struct EvaluationReport {
  std::string model_path, mesh_path;
  EvaluationSettings settings;                  // as used
  nlohmann::json recorded_settings;             // recordedSettings of the options
  std::vector<EvaluationResult> results;        // one per planner
  std::optional<BaselineResult> baseline;       // --baseline: PCL's PPF
  std::optional<BaselineResult> baseline_icp;   // --baseline: PPF followed by ICP
  std::vector<StreamEvaluationResult> streams;  // --stream-rate: the random views as a stream
  double seconds_total = 0;
};

// The planner question: after how many views the median error gets under 5 degrees and
// stays there for the rest of the sequence (a dip that comes back up does not count).
constexpr double kConvergedDeg = 5.0;

}  // namespace vdc::tools
