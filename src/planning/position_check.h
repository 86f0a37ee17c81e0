#pragma once

#include <Eigen/Core>

#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

// Throws vdc::Error "The <what> is not finite." for a position with a NaN or infinite coordinate;
// shared by the planning module's sources (not installed).
inline void checkFinitePosition(const Eigen::Vector3d& p, const char* what) {
  if (!p.allFinite()) throw Error(std::string("The ") + what + " is not finite.");
}

}  // namespace vdc
