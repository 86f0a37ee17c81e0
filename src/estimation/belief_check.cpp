#include "view_direction_classification/estimation/belief_check.h"

#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/refinement/pose_verification.h"

namespace vdc {

void checkBeliefCheckParameters(const BeliefCheckParameters& p) {
  if (!(p.search_below_score >= 0.0 && p.search_below_score <= 1.0)) {
    throw Error("search_below_score must lie in [0, 1], got " +
                std::to_string(p.search_below_score));
  }
  if (!(p.rebuild_margin >= 0.0 && p.rebuild_margin <= 1.0)) {
    throw Error("rebuild_margin must lie in [0, 1], got " + std::to_string(p.rebuild_margin));
  }
  if (p.check_views < 1) {
    throw Error("check_views must be at least 1, got " + std::to_string(p.check_views));
  }
  if (!(p.search_girdle_step_deg > 0.0 && p.search_girdle_step_deg <= 180.0)) {
    throw Error("search_girdle_step_deg must lie in (0, 180], got " +
                std::to_string(p.search_girdle_step_deg));
  }
  if (p.search_max_refined < 1) {
    throw Error("search_max_refined must be at least 1, got " +
                std::to_string(p.search_max_refined));
  }
}

RefinementParameters searchRefinementParameters(const RefinementParameters& base, int directions,
                                                const BeliefCheckParameters& parameters) {
  RefinementParameters search = base;
  search.hypotheses.max_components = directions;
  search.hypotheses.min_relative_weight = 0.0;
  search.hypotheses.girdle_step_deg = parameters.search_girdle_step_deg;
  search.max_refined = parameters.search_max_refined;
  search.screen_per_component = false;
  return search;
}

double verifiedScore(const PoseRefiner& refiner, const std::vector<RefinementView>& views,
                     const Eigen::Isometry3d& pose) {
  return PoseVerifier(refiner.sharedSurface(), views, refiner.parameters().verification)
      .score(pose)
      .score();
}

BeliefVerdict judgeBelief(const PoseRefiner& refiner, const std::vector<RefinementView>& views,
                          const Eigen::Isometry3d& belief_pose,
                          const Eigen::Isometry3d& search_pose,
                          const BeliefCheckParameters& parameters) {
  const PoseVerifier verifier(refiner.sharedSurface(), views, refiner.parameters().verification);
  BeliefVerdict verdict;
  verdict.belief_score = verifier.score(belief_pose).score();
  verdict.search_score = verifier.score(search_pose).score();
  verdict.contradicted = verdict.search_score > verdict.belief_score + parameters.rebuild_margin;
  return verdict;
}

}  // namespace vdc
