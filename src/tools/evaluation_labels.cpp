#include "evaluation_labels.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "view_direction_classification/common/error.h"

namespace vdc::tools {

std::string visibilityLabel(double radius) {
  if (radius == kAllVisible) return "all";
  char text[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, radius);
    if (std::strtod(text, nullptr) == radius) break;
  }
  return text;
}

double parseVisibility(const std::string& label) {
  if (label == "all") return kAllVisible;
  char* end = nullptr;
  const double radius = std::strtod(label.c_str(), &end);
  if (label.empty() || end != label.c_str() + label.size() || !(radius > 0.0) ||
      !std::isfinite(radius)) {
    throw Error("visibility '" + label + "' is neither 'all' nor a positive radius in metres");
  }
  return radius;
}

EvaluationPlanner parseEvaluationPlanner(const std::string& name) {
  for (const EvaluationPlanner planner :
       {EvaluationPlanner::kRandom, EvaluationPlanner::kInformativeness,
        EvaluationPlanner::kInformationGain}) {
    if (name == evaluationPlannerName(planner)) return planner;
  }
  throw Error("unknown planner '" + name +
              "'; expected random, informativeness or information_gain");
}

}  // namespace vdc::tools
