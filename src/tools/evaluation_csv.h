#pragma once

#include <ostream>
#include <vector>

#include "view_direction_classification/evaluation/evaluation.h"

namespace vdc::tools {

// errors.csv: a header of column names ("planner,visibility,sequence,view,map_error_deg"), then
// one row per result, setting, sequence (0-based) and view (1-based: the number of views seen so
// far). The columns are declared once, in evaluation_csv.cpp.
void writeErrorsCsv(std::ostream& out, const std::vector<EvaluationResult>& results);

}  // namespace vdc::tools
