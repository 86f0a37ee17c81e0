#pragma once

// How well a point-to-plane fit pins down the translation and the orientation (private to
// refinement; doc/method.md, "Refinement").

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "view_direction_classification/refinement/model_surface.h"

namespace vdc {

// The covariance [m^2, fixed frame] of the translation of a fitted pose: the residual variance
// of the point-to-plane matches times the inverse of sum n n^T over them (n: the model's normal
// at each observed point's nearest sample; points further than max_distance are not matched),
// the Gauss-Newton covariance of the linearised fit. Along a direction the matched normals do
// not constrain (a cylinder seen side-on slides along its axis) it is large, as it should be.
// The matches are not independent (neighbours share the surface's error, and the model is
// sampled every few millimetres), so each principal variance is clamped to
// [min_sigma^2, max_sigma^2]; fewer than 7 matches give max_sigma^2 on every axis.
Eigen::Matrix3d translationCovariance(const ModelSurface& surface,
                                      const pcl::PointCloud<pcl::PointXYZ>& points_world,
                                      const Eigen::Isometry3d& world_from_object,
                                      double max_distance, double min_sigma, double max_sigma);

// The covariance [rad^2, object frame] of the orientation of a fitted pose, as a small turn t
// applied in the object frame (world_from_object * exp(t)): the turn's block of the linearised
// six-degree-of-freedom fit's covariance, residual variance times the inverse information. About
// an axis the matched surface does not constrain (a surface of revolution's) it is large. Each
// principal standard deviation is clamped to [floor, max_sigma] [rad] for the reason above, the
// floor being the larger of min_sigma and min_shift_sigma [m] over the root mean square distance
// of the matched points from their centroid (a 1 mm floor turns a 5 cm patch by about 4 degrees,
// a whole mug view by about 1.5); fewer than 7 matches give max_sigma^2 on every axis.
Eigen::Matrix3d rotationCovariance(const ModelSurface& surface,
                                   const pcl::PointCloud<pcl::PointXYZ>& points_world,
                                   const Eigen::Isometry3d& world_from_object, double max_distance,
                                   double min_sigma, double max_sigma, double min_shift_sigma);

}  // namespace vdc
