#pragma once

#include <string>

#include "view_direction_classification/evaluation/evaluation.h"

namespace vdc::tools {

// The text forms of the evaluation's settings in `vdc evaluate`'s options and output files.

// "all" for kAllVisible, otherwise the radius in metres as the shortest exact decimal ("0.08").
std::string visibilityLabel(double radius);
// Inverse of visibilityLabel; throws vdc::Error for anything but "all" or a positive number.
double parseVisibility(const std::string& label);

// The planner whose evaluationPlannerName is `name`; throws vdc::Error naming the accepted ones.
EvaluationPlanner parseEvaluationPlanner(const std::string& name);

}  // namespace vdc::tools
