#pragma once

// Cheap screening of refinement starts before ICP (private to refinement; doc/method.md,
// "Refinement"): ICP costs milliseconds per start, a look-up of a few hundred points in the
// model's k-d tree a fraction of one, so every start is scored first and only the best are
// aligned.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

#include "view_direction_classification/refinement/model_surface.h"

namespace vdc {

// About `count` of the points, evenly spread through the cloud (every k-th: the voxel-filtered
// points are in grid order, so this keeps their spatial spread). All of them when count <= 0 or
// the cloud is not larger.
pcl::PointCloud<pcl::PointXYZ>::Ptr evenSubsample(const pcl::PointCloud<pcl::PointXYZ>& points,
                                                  int count);

// The mean distance [m] of the points (fixed frame) to the model's nearest surface sample with
// the model at world_from_object, each distance truncated at `truncation` [m] (a point ICP would
// not match counts as that far, whatever its distance). Lower is a better start.
double meanTruncatedDistance(const ModelSurface& surface,
                             const pcl::PointCloud<pcl::PointXYZ>& points_world,
                             const Eigen::Isometry3d& world_from_object, double truncation);

// Indices of the `count` smallest distances among the starts of each belief component
// (components[i] is start i's), smallest first per component (ties in index order); every
// index when count <= 0. Per component: a wrong viewing direction's girdle can hold starts that
// fit the object's symmetric body better than the right girdle's nearly right ones, which
// verification, not screening, tells apart.
std::vector<std::size_t> bestStarts(const std::vector<double>& distances,
                                    const std::vector<int>& components, int count);

}  // namespace vdc
