#pragma once

#include <ostream>
#include <vector>

#include "evaluation_report.h"
#include "view_direction_classification/evaluation/evaluation.h"
#include "view_direction_classification/evaluation/stream_evaluation.h"

namespace vdc::tools {

// errors.csv: a header of column names
// ("planner,visibility,sequence,view,map_error_deg,event,time_s,views_fused,cone90_deg,
// inside_cone90"), then one row per result, setting, sequence (0-based) and view (1-based: the
// number of views seen so far; event "view"), then the streams' rows: per setting and sequence
// one after every fused frame (event "fused") and one at the end of every view's dwell (event
// "dwell_end"), view being the path's view the camera is at or last left. A cell without a value
// (the one-cloud rows' time, a single-view method's trust signals) is empty. The columns are
// declared once, in evaluation_csv.cpp.
void writeErrorsCsv(std::ostream& out, const std::vector<EvaluationResult>& results,
                    const std::vector<StreamEvaluationResult>& streams = {});
// A run's errors.csv: the planners' rows, the baselines' (PPF, then PPF followed by ICP), the
// streams'.
void writeErrorsCsv(std::ostream& out, const EvaluationReport& report);

}  // namespace vdc::tools
