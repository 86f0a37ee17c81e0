#pragma once

// Which of a refinement's verified poses a view keeps, and which others still enter its
// measurement (private to refinement; doc/method.md, "Refinement").

#include <vector>

#include "view_direction_classification/refinement/pose_refiner.h"

namespace vdc {

// Within duplicate_angle_deg and duplicate_distance of each other: one pose.
bool samePose(const RefinedPose& a, const RefinedPose& b, const RefinementParameters& parameters);

// The distinct accepted poses of `tried` within keep_score_margin of the best, best first.
std::vector<RefinedPose> keptPoses(const std::vector<RefinedPose>& tried,
                                   const RefinementParameters& parameters);

// Whether `pose` lies on the roll sector of one of `poses` (roll_sector.h), within
// duplicate_angle_deg: that pose again, turned.
bool onARollSectorOf(const RefinedPose& pose, const std::vector<RefinedPose>& poses,
                     const RefinementParameters& parameters);

// Up to max_alternatives distinct poses of `tried`, best first, screened in and converged
// (accepted or not), that score within measurement_score_margin of kept.front() and are neither
// one of `kept` nor on a kept pose's roll sector. Empty when nothing is kept.
std::vector<RefinedPose> verifiedAlternatives(const std::vector<RefinedPose>& tried,
                                              const std::vector<RefinedPose>& kept,
                                              const RefinementParameters& parameters);

}  // namespace vdc
