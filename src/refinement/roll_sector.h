#pragma once

// How far a kept pose can be turned about the model's axis of near symmetry before verification
// tells the turn apart (private to refinement; doc/method.md, "Refinement"). A spool of thread,
// a mug seen from behind its handle: ICP settles on one turn of many that explain the points
// equally well, and fusing that one turn as a sharp pose would make the belief sure of a roll no
// measurement fixed.

#include <Eigen/Geometry>

#include "view_direction_classification/refinement/model_surface.h"
#include "view_direction_classification/refinement/pose_refiner.h"
#include "view_direction_classification/refinement/pose_verification.h"

namespace vdc {

// [deg] The largest multiple of step_deg (up to 180) such that the pose turned by every multiple
// up to it, on one side or the other, scores within `margin` of the pose's own score; 0 when
// neither turn by step_deg does.
double verifiedRollSectorDeg(const ModelSurface& surface, const PoseVerifier& verifier,
                             const RefinedPose& pose, double step_deg, double margin);

// True when `other`'s orientation lies on `pose`'s roll sector: a turn of at most
// pose.roll_sector_deg about pose.sector_axis, give or take tolerance_deg.
bool onRollSector(const RefinedPose& pose, const RefinedPose& other, double tolerance_deg);

}  // namespace vdc
