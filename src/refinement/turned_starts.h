#pragma once

// Restarts from a converged pose (private to refinement; doc/method.md, "Refinement"): a nearly
// symmetric object (a mug's body, a box) fits its points almost as well turned about one of its
// axes of near symmetry, and ICP that converged there stays in that local minimum (the mug's
// handle on the wrong side). The same pose turned about each axis is a start ICP can reach the
// right turn from.

#include <Eigen/Geometry>

#include <vector>

#include "view_direction_classification/refinement/model_surface.h"

namespace vdc {

// world_from_object turned about `axis` (object frame) by `angle` [rad]: x -> c + R (x - c) for
// the axis' origin c.
Eigen::Isometry3d turnedAbout(const Eigen::Isometry3d& world_from_object,
                              const Eigen::ParametrizedLine<double, 3>& axis, double angle);

// world_from_object turned about the model's best symmetry axis (model_surface.h) by every
// multiple of step_deg short of a full turn (round(360 / step_deg) - 1 turns), and a half turn
// about each of the other two (the flips that leave a box or a mirror-symmetric object's
// silhouette in place).
std::vector<Eigen::Isometry3d> turnedStarts(const ModelSurface& surface,
                                            const Eigen::Isometry3d& world_from_object,
                                            double step_deg);

// The last two of those: world_from_object turned half a turn about each of the model's half
// turn axes (half_turn_axes.h).
std::vector<Eigen::Isometry3d> halfTurnStarts(const ModelSurface& surface,
                                              const Eigen::Isometry3d& world_from_object);

}  // namespace vdc
