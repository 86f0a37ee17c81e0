#pragma once

// The half turns after which a nearly symmetric object looks nearly the same (private to
// refinement; doc/method.md, "Refinement"): a mug seen only around its handle looks the same
// upside down, turned half a turn about the line from the body's middle through the handle.
// Restarts (turned_starts.h) try these half turns; one about another line leaves the turned
// start tens of degrees from the equivalent pose, too far for the restart's short ICP, and the
// refinement then finds one of two poses that explain the points equally well. Fused as one
// sharp pose, that makes the belief sure of a side no measurement fixed.

#include <Eigen/Geometry>

#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "view_direction_classification/refinement/nearest_points.h"

namespace vdc {

// Two lines orthogonal to main_axis, through its point in the middle of the samples' extent
// along it: first the one about which the samples turned by half a turn lie nearest the surface
// (`nearest`, the samples' own index; mean squared distance truncated at a tenth of the samples'
// extent, over azimuths every 3 degrees, then every 0.25 degrees around the best), then the one
// orthogonal to it and to main_axis. Ties (a surface of revolution, where every azimuth is as
// good) keep the azimuth nearest `first_guess` (projected onto the plane orthogonal to
// main_axis). Deterministic; at most max_samples samples are turned.
std::vector<Eigen::ParametrizedLine<double, 3>> halfTurnAxes(
    const pcl::PointCloud<pcl::PointNormal>& samples, const NearestPoints& nearest,
    const Eigen::ParametrizedLine<double, 3>& main_axis, const Eigen::Vector3d& first_guess,
    int max_samples = 300);

}  // namespace vdc
