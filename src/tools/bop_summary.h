#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/bop/bop_scoring.h"

namespace vdc::tools {

// One way of running the estimator on a BOP dataset, scored: "single" (each image alone) or
// "fused" (each scene's images as a view sequence).
struct BopRun {
  std::string name;
  BopScores scores;
  double mean_image_seconds = 0.0;  // the estimator's time per image
  int images = 0;
};

// `vdc evaluate-bop`'s summary.json: per run, the VSD, MSSD and MSPD average recall per object
// and overall, their mean (BOP's AR; of MSSD and MSPD where VSD was not scored, ar_vsd null),
// the estimates and targets, the time per image.
nlohmann::json bopSummaryJson(const std::vector<BopRun>& runs);

// The same as a table on stdout: one line per object and run, then the overall lines.
void printBopSummary(const std::vector<BopRun>& runs);

}  // namespace vdc::tools
