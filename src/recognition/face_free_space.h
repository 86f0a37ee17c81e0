#pragma once

#include <Eigen/Core>

#include <vector>

#include "view_direction_classification/refinement/pose_verification.h"

namespace vdc {

// Private to recognition: how the simple-shape alternative's box faces are judged.

// What a box whose upright face has the points `face_points` (its normal `normal`, made square
// to `up`; the plane through their median) predicts beyond the points that lie on it: the whole
// rectangle those points span across the face and, along `up`, from their lowest to their highest,
// with no hole. Sampled on a grid of at most max_samples cells, each cell's centre is judged
// against the scene's depth (seenThrough at `free_space_tolerance` [m]). `face_points` are in the
// camera frame scaled by `scale` (the shape fit's units, per metre); `normal` and `up` unit
// vectors. Returns {samples, seen through}: a box's face is seen wherever it is predicted, a disc
// seen face-on (a spool's flange) leaves its bounding square's corners, where the camera saw the
// table behind. {0, 0} for fewer than 3 points or an empty scene.
struct FaceJudgement {
  int samples = 0;
  int seen_through = 0;
};
FaceJudgement judgeFaceRectangle(const std::vector<Eigen::Vector3f>& face_points,
                                 const Eigen::Vector3f& normal, const Eigen::Vector3f& up,
                                 float scale, const SceneDepth& scene, double free_space_tolerance,
                                 int max_samples = 400);

}  // namespace vdc
