#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vdc {

// Pinhole intrinsics of the simulated depth camera (doc/method.md section 2). Pixel (u, v) samples
// the ray through image coordinates (u, v): u = fx x / z + cx, v = fy y / z + cy in the optical
// frame (z forward, x right, y down).
struct CameraIntrinsics {
  int width = 640, height = 480;
  double fx = 525, fy = 525, cx = 319.5, cy = 239.5;
};

// Throws vdc::Error unless the image size is positive and the focal lengths positive and finite.
void checkIntrinsics(const CameraIntrinsics& intrinsics);

// Pose of a camera (camera_from_object = T_CO, mapping object coordinates into the optical
// frame) that sees the object origin on its optical axis at `distance` from the unit viewing
// direction `view_direction` (object frame, object -> camera), so R_CO d = (0, 0, -1).
// Roll convention: at roll = 0 the object's +z axis projects "up" in the image (towards -y);
// if d is (anti)parallel to z, the object's +y axis projects up instead. A positive `roll`
// [rad] turns the camera about its own optical (+z) axis, so the image content turns by -roll.
// A non-unit direction is normalised. Throws vdc::Error for a zero or non-finite direction, a
// non-positive distance or a non-finite roll.
Eigen::Isometry3d cameraFromObject(const Eigen::Vector3d& view_direction, double distance,
                                   double roll);

// Unit vector from the object origin to the camera centre, in the object frame. Throws
// vdc::Error if the camera centre coincides with the object origin.
Eigen::Vector3d viewDirectionOf(const Eigen::Isometry3d& camera_from_object);

}  // namespace vdc
