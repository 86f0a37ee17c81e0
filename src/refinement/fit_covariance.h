#pragma once

// How well a point-to-plane fit pins down the translation and the orientation (private to
// refinement; doc/method.md, "Refinement").

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "view_direction_classification/refinement/model_surface.h"

namespace vdc {

// Principal standard deviations the covariances are clamped to.
struct CovarianceBounds {
  double min_shift_sigma, max_shift_sigma;  // [m]
  double min_turn_sigma, max_turn_sigma;    // [rad]
};

// The covariances of a fitted pose, from one point-to-plane matching of the points (fixed frame)
// to the model's nearest samples (points further than max_distance are not matched).
struct FitCovariance {
  // [m^2, fixed frame] The translation's: the residual variance of the matches times the inverse
  // of sum n n^T over them (n: the model's normal at each observed point's nearest sample), the
  // Gauss-Newton covariance of the linearised fit. Along a direction the matched normals do not
  // constrain (a cylinder seen side-on slides along its axis) it is large, as it should be.
  Eigen::Matrix3d translation;
  // [rad^2, object frame] The orientation's, as a small turn t applied in the object frame
  // (world_from_object * exp(t)): the turn's block of the linearised six-degree-of-freedom fit's
  // covariance, residual variance times the inverse information. About an axis the matched
  // surface does not constrain (a surface of revolution's) it is large.
  Eigen::Matrix3d rotation;
};

// The matches are not independent (neighbours share the surface's error, and the model is
// sampled every few millimetres), so each principal standard deviation is clamped: the
// translation's to [min_shift_sigma, max_shift_sigma], the turn's to [floor, max_turn_sigma]
// with the floor the larger of min_turn_sigma and min_shift_sigma over the root mean square
// distance of the matched points from their centroid (a 1 mm floor turns a 5 cm patch by about 4
// degrees, a whole mug view by about 1.5). Fewer than 7 matches give the maxima on every axis.
FitCovariance fitCovariance(const ModelSurface& surface,
                            const pcl::PointCloud<pcl::PointXYZ>& points_world,
                            const Eigen::Isometry3d& world_from_object, double max_distance,
                            const CovarianceBounds& bounds);

}  // namespace vdc
