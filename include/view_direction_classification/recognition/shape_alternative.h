#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <vector>

#include "view_direction_classification/recognition/model_library.h"
#include "view_direction_classification/refinement/pose_verification.h"

namespace vdc {

// "Unknown" is not a fixed score. Most unknown things on a kitchen table are boxes and cans, and
// a box's face or a can's side is explained by a mug's side within a depth camera's tolerance
// about as well as by the box or the can. So a candidate's unknown alternative scores what the
// best simple shape standing on the support explains of it (method.md section 13): a model that
// does not explain it better is no evidence. Models that are themselves simple shapes (a carton,
// a can: isSimpleShape) are exempt, their size is their evidence.

// Of `points` (any frame), the share explained within `tolerance` [m] (weighted as the verifier
// weighs a model's inliers: 1 within half the tolerance, 1/2 up to it) by the better of two
// simple shapes standing upright on a support whose unit normal (same frame) is `up`: a box (up to
// two perpendicular upright faces and a horizontal top) or an upright cylinder (its side and a
// horizontal top). PCL's RANSAC (fixed seed: deterministic) on at most 2000 evenly strided points;
// 0 for fewer than 30 points or a non-finite `up`. Given the scene's depth (ray-indexed, camera
// frame, as `points`), a box is also a prediction: less the share of its upright faces' rectangles
// where the camera saw more than `free_space_tolerance` [m] beyond them (a disc's face is no
// box's), as a model's score is less its contradicted samples. So the result is in [-1, 1].
double simpleShapeFraction(const pcl::PointCloud<pcl::PointXYZ>& points, const Eigen::Vector3f& up,
                           double tolerance, const SceneDepth& scene = SceneDepth(),
                           double free_space_tolerance = 0.0);

// Whether a model's surface samples (object frame) are a simple shape: at least `min_fraction`
// within `tolerance` [m] of the faces of their axis-aligned bounding box, or of an upright
// cylinder (side and end caps) about one of the object frame's axes through the box's centre.
bool isSimpleShape(const std::vector<Eigen::Vector3f>& surface_points, double tolerance = 0.003,
                   double min_fraction = 0.9);

// The simple-shape alternative of one library, applied as a penalty on each model's score: with
// s_m lowered by max(0, a - unknown_score), where a is simpleShapeFraction at verification's
// tolerances at the candidate's median depth, "s_m against unknown_score" is "s_m against
// the better of unknown_score and a". Models that are simple shapes get none.
class ShapeAlternative {
 public:
  ShapeAlternative(const ModelLibrary& library, VerificationParameters verification,
                   double unknown_score);

  // Per library model, the amount to subtract from its score on a candidate of `points` (camera
  // frame) standing on a support with unit normal `up` (camera frame; zero: no support found,
  // no penalty), in a frame whose depth is `scene` (ray-indexed: indexRays; empty: the box's
  // faces are not judged).
  std::vector<double> penalties(const pcl::PointCloud<pcl::PointXYZ>& points,
                                const Eigen::Vector3f& up,
                                const SceneDepth& scene = SceneDepth()) const;
  // The alternative itself: simpleShapeFraction at verification's tolerances at the points'
  // median depth (0 without a support or points).
  double fraction(const pcl::PointCloud<pcl::PointXYZ>& points, const Eigen::Vector3f& up,
                  const SceneDepth& scene = SceneDepth()) const;

 private:
  std::vector<bool> simple_;  // per model: isSimpleShape
  VerificationParameters verification_;
  double unknown_score_;
};

}  // namespace vdc
