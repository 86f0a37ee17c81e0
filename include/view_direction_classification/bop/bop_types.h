#pragma once

#include <Eigen/Core>

#include <map>
#include <optional>
#include <vector>

#include "view_direction_classification/geometry/camera.h"

namespace vdc {

// The records of a BOP dataset (bop_toolkit's docs/bop_datasets_format.md) in the units the
// format stores them in: millimetres for translations and model sizes, pixels for intrinsics.
// Keeping the format's units makes a written dataset read back exactly; bop_units.h converts to
// the package's metres.

// A rigid transformation as BOP writes it: x' = R x + t, t [mm].
struct BopPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

// One image's camera (scene_camera.json): intrinsics, the depth PNG's scale (a pixel value times
// depth_scale is the depth in mm) and, where the dataset gives it, the camera's pose
// (cam_R_w2c, cam_t_w2c: world to camera).
struct BopCamera {
  CameraIntrinsics intrinsics;
  double depth_scale = 1.0;
  std::optional<BopPose> camera_from_world;
};

// One annotated object instance of an image (scene_gt.json).
struct BopGtObject {
  int obj_id = 0;
  BopPose camera_from_model;  // cam_R_m2c, cam_t_m2c
};

// A continuous rotational symmetry: any angle about `axis` through `offset` [mm].
struct BopContinuousSymmetry {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

// One model's entry of models_info.json: its diameter [mm] (the largest distance between two of
// its vertices) and its symmetries; the bounding box fields are not needed here.
struct BopModelInfo {
  double diameter = 0.0;
  std::vector<BopPose> symmetries_discrete;  // the 4x4 matrices, t [mm]
  std::vector<BopContinuousSymmetry> symmetries_continuous;
};

// One entry of test_targets_bop19.json: estimate inst_count instances of obj_id in the image.
struct BopTarget {
  int scene_id = 0;
  int im_id = 0;
  int obj_id = 0;
  int inst_count = 0;
};

// A scene folder's annotation files, keyed by im_id.
struct BopSceneFiles {
  std::map<int, BopCamera> cameras;
  std::map<int, std::vector<BopGtObject>> ground_truth;
};

}  // namespace vdc
