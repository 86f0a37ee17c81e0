#pragma once

#include <Eigen/Geometry>

#include <vector>

#include "view_direction_classification/refinement/pose_refiner.h"

namespace vdc {

// When a view's geometry contradicts the belief (doc/method.md, "Refinement", "A belief the
// geometry contradicts"). Refinement only tries the belief's own hypotheses and accepts only
// poses inside its credible region, so a belief made sure of a wrong pose by an earlier view (a
// mug upside down, whose side views fit either way, at 1.5 m) would stay sure of it whatever
// later views show. Where the belief's best pose fits a view poorly, a search that ignores the
// belief looks for a better one; where that pose also fits the latest views clearly better, the
// belief is rebuilt from this view.
struct BeliefCheckParameters {
  // The search runs when refinement's best pose verifies below this on the view, or it kept none
  // and the belief's MAP (at the position estimate) verifies below this (a right pose of a whole
  // view verifies at 0.98-1.00; refinement keeps none when ICP cannot improve on a belief that
  // is already right); 0: never. Once a search finds nothing clearly better, later views search
  // only below the score the belief's pose reached on that view minus rebuild_margin (the
  // estimator's confirmed fit: what a noisier camera lets a right pose reach).
  double search_below_score = 0.95;
  // The search's best pose rebuilds the belief when its verification over the latest check_views
  // views (this one included) beats the belief's best pose's by more than this.
  double rebuild_margin = 0.03;
  int check_views = 4;
  // The search's starts: every training direction's girdle along this view's line of sight,
  // a start every search_girdle_step_deg of roll, the search_max_refined best-screened of them
  // all aligned (then restarted and polished as any refinement).
  double search_girdle_step_deg = 30.0;
  int search_max_refined = 6;
};

// Throws vdc::Error naming the first bad value: a score or margin outside [0, 1], fewer than 1
// check view, a step outside (0, 180], fewer than 1 search start.
void checkBeliefCheckParameters(const BeliefCheckParameters& parameters);

// The search's refinement settings: `base` with hypotheses from each of `directions` equally
// weighted girdles and the search's steps and number of aligned starts, screened over all
// girdles together.
RefinementParameters searchRefinementParameters(const RefinementParameters& base, int directions,
                                                const BeliefCheckParameters& parameters);

// The verification score (pose_verification.h) of `pose` over `views` together, against the
// refiner's surface with its verification settings.
double verifiedScore(const PoseRefiner& refiner, const std::vector<RefinementView>& views,
                     const Eigen::Isometry3d& pose);

// Verification of the belief's and the search's best poses over the same views.
struct BeliefVerdict {
  double belief_score = 0.0, search_score = 0.0;  // over every view together
  bool contradicted = false;                      // search_score > belief_score + rebuild_margin
};
BeliefVerdict judgeBelief(const PoseRefiner& refiner, const std::vector<RefinementView>& views,
                          const Eigen::Isometry3d& belief_pose,
                          const Eigen::Isometry3d& search_pose,
                          const BeliefCheckParameters& parameters);

}  // namespace vdc
