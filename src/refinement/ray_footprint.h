#pragma once

// Where a view observed the object, as seen from its camera (private to refinement): the convex
// hull of the observed points' rays (x/z, y/z). A model sample predicted outside it where nothing
// was observed may be occluded or cropped away rather than absent; inside it, the camera saw
// the object's surroundings through where the sample would be.

#include <Eigen/Core>

#include <vector>

namespace vdc {

// The convex hull of the points, counter-clockwise, without collinear points (Andrew's monotone
// chain); fewer than 3 points for fewer than 3 distinct non-collinear inputs.
std::vector<Eigen::Vector2f> convexHull(std::vector<Eigen::Vector2f> points);

// True when p lies inside the counter-clockwise convex polygon or on its boundary (within
// `tolerance`, in the points' units, outside it); false for a polygon of fewer than 3 vertices.
bool insideConvexPolygon(const std::vector<Eigen::Vector2f>& polygon, const Eigen::Vector2f& p,
                         float tolerance);

}  // namespace vdc
