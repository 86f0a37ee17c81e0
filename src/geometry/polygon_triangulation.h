#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vdc {

// Appends triangles that cover the polygon whose corners, in order, are `corners[0..count)`
// (indices into `vertices`, count >= 3, all valid), each wound as the polygon is, so outward
// faces stay outward. A convex polygon becomes a fan; a concave one is cut into ears in the plane
// that fits it best (as assimp's triangulation does). A polygon that is no simple polygon in that
// plane (self-intersecting, or collapsed to a line or a point) still yields count - 2 triangles,
// and the work stays within a constant times count^2 whatever the corners are.
void triangulatePolygon(const std::vector<Eigen::Vector3f>& vertices, const std::int32_t* corners,
                        std::size_t count, std::vector<Eigen::Vector3i>* triangles);

}  // namespace vdc
