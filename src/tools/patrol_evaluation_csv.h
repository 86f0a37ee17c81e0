#pragma once

#include <ostream>
#include <string>

#include "view_direction_classification/evaluation/patrol_evaluation.h"

namespace vdc::tools {

// A change as "KIND:MODEL#ID" ("distractor_moved:#INDEX" for a distractor).
std::string patrolChangeLabel(const PatrolChange& change);

// patrol.csv: a header of column names, then one row per pass. The change columns hold one
// value per change made before the pass, ';'-separated and in the same order across them; a
// change the memory never took in has "-" for its views. The columns are declared once, in
// patrol_evaluation_csv.cpp.
void writePatrolCsv(std::ostream& out, const PatrolResult& result);

}  // namespace vdc::tools
