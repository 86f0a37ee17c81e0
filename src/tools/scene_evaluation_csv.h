#pragma once

#include <ostream>
#include <vector>

#include "view_direction_classification/evaluation/scene_evaluation.h"

namespace vdc::tools {

// scenes.csv: a header of column names, then one row per scene and view (1-based), in the
// order fed. The per-instance columns hold one value per identified instance (or per missed
// visible object, or per false identification), separated by ';' and in the same order across
// the columns of a group. The columns are declared once, in scene_evaluation_csv.cpp.
void writeScenesCsv(std::ostream& out, const std::vector<SceneViewRecord>& records);

}  // namespace vdc::tools
