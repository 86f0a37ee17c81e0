#pragma once

#include <Eigen/Core>

#include "view_direction_classification/refinement/pose_verification.h"

namespace vdc {

// Whether the camera saw through `point` (camera frame) (private to recognition): the nearest
// scene point on its ray (the occluders' and the supports' ray indices of `scene`, indexRays;
// within 4 mm of the ray at the point's depth) lies more than `tolerance` [m] beyond it. False
// when a scene surface on the ray lies in front of it or within the tolerance (hidden, or
// something there), when no scene point is on its ray (outside the image, or no depth), and
// for a point behind the camera.
bool seenThrough(const SceneDepth& scene, const Eigen::Vector3f& point, double tolerance);

}  // namespace vdc
