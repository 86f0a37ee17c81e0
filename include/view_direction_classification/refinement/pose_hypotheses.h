#pragma once

#include <Eigen/Core>

#include <vector>

#include "view_direction_classification/bingham/bingham_mixture.h"

namespace vdc {

// Which orientations of a belief are worth refining against the geometry (doc/method.md,
// "Refinement").
struct HypothesisParameters {
  int max_components = 4;  // the heaviest components of the belief are used ...
  // ... unless lighter than this fraction of the heaviest.
  double min_relative_weight = 1e-3;
  // A component whose loosest concentration is weaker (closer to 0) than -girdle_concentration
  // is a girdle: its roll is still free, so points along its circle are tried instead of its
  // arbitrary mode.
  double girdle_concentration = 2.0;
  double girdle_step_deg = 15.0;  // rotation angle between neighbouring points of a girdle
};

struct OrientationStart {
  Eigen::Vector4d orientation;  // q_WO (w, x, y, z), unit
  int component = 0;            // which belief component it came from
};

// The modes of the heaviest components and, for girdles, the orientations every girdle_step_deg
// along their circle cos(t) mode + sin(t) v3 (t in [0, pi), i.e. rotations by 2t about the
// circle's axis, which for a view's girdle is the roll about the line of sight). Throws
// vdc::Error for invalid parameters (max_components < 1, a weight fraction outside [0, 1), a
// negative concentration threshold, a step outside (0, 180]).
std::vector<OrientationStart> orientationHypotheses(const BinghamMixture& belief,
                                                    const HypothesisParameters& parameters);

}  // namespace vdc
