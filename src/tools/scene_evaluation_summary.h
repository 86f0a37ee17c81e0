#pragma once

#include <vector>

#include "view_direction_classification/evaluation/scene_evaluation.h"

namespace vdc::tools {

// The figures of `vdc evaluate-scenes` for one view index (1-based) over every scene.
struct SceneViewSummary {
  int view = 1;
  int views = 0;  // scenes that had this view
  int visible_known = 0, identified = 0, false_identifications = 0, estimates = 0;
  int false_on_distractor = 0, false_wrong_model = 0, false_duplicate = 0, false_elsewhere = 0;
  double median_rotation_deg = 0.0, median_position_mm = 0.0;  // over identified instances
  double inside_cone90 = 0.0;                                  // fraction of identified
  double mean_time_ms = 0.0, median_time_ms = 0.0;
  // Means over the segmented views only (a frame not segmented has no stages).
  int segmented = 0;
  double mean_segmentation_ms = 0.0;
  SceneStageTimes mean_stage_ms;
  double identifiedFraction() const;        // of visible known
  double falsePerView() const;              // false identifications per view
  double falseFractionOfEstimates() const;  // of every confirmed estimate
};

// Time per view against the number of candidates: the views with candidates in [low, high].
struct CandidateTimeBin {
  int low = 0, high = 0;
  int views = 0;
  double mean_time_ms = 0.0, median_time_ms = 0.0, mean_candidates = 0.0;
};

std::vector<SceneViewSummary> summariseByView(const std::vector<SceneViewRecord>& records);
// Bins of `width` candidates over the segmented views (a view skipped costs nothing).
std::vector<CandidateTimeBin> timeByCandidates(const std::vector<SceneViewRecord>& records,
                                               int width = 4);
// The tables on stdout.
void printSceneEvaluationSummary(const std::vector<SceneViewRecord>& records);

}  // namespace vdc::tools
