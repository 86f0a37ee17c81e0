#pragma once

// A table-top scene around the built-in mug, shared by the segmentation, tracking and estimator
// tests: the upright mug on a table with distractors that do not fit its size.

#include <Eigen/Geometry>

#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/geometry/scene.h"

namespace vdc::test {

inline const Eigen::Vector3d kMugPosition(0.4, -0.1, 0.7);
constexpr double kMugYaw = 0.7;
// The upright mug's bottom, 9.5 / 2 cm below its origin.
inline double tableTop() { return kMugPosition.z() - 0.0475; }

inline Eigen::Isometry3d placed(const Eigen::Vector3d& position, double yaw = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = position;
  return pose;
}

inline Eigen::Isometry3d worldFromMug() { return placed(kMugPosition, kMugYaw); }

// The mug at worldFromMug(), optionally on a 1.4 x 1 m table and beside three distractors that
// do not fit its size: a flat 30 x 20 x 5 cm box, a 25 cm tall cylinder and a 4 cm cube, each at
// least 15 cm from the mug.
inline Scene mugScene(bool table, bool distractors) {
  Scene scene;
  scene.object = {makeMug(), worldFromMug()};
  if (table) scene.table_size = Eigen::Vector2d(1.4, 1.0);
  if (distractors) {
    const double z = tableTop();
    scene.distractors.push_back(
        {makeBoxMesh(Eigen::Vector3d(0.3, 0.2, 0.05)), placed(Eigen::Vector3d(0.4, 0.22, z), 0.3)});
    scene.distractors.push_back(
        {makeCylinderMesh(0.03, 0.25), placed(Eigen::Vector3d(0.2, -0.25, z))});
    scene.distractors.push_back(
        {makeBoxMesh(Eigen::Vector3d(0.04, 0.04, 0.04)), placed(Eigen::Vector3d(0.55, -0.25, z))});
  }
  return scene;
}

// A camera looking at `target` from the fixed-frame direction `direction` at `distance`, the
// fixed frame's +z up in the image.
inline Eigen::Isometry3d cameraFromWorld(const Eigen::Vector3d& direction, double distance,
                                         const Eigen::Vector3d& target = kMugPosition) {
  Eigen::Isometry3d world_from_target = Eigen::Isometry3d::Identity();
  world_from_target.translation() = target;
  return cameraFromObject(direction, distance, 0.0) * world_from_target.inverse();
}

}  // namespace vdc::test
