#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <vector>

#include "view_direction_classification/scene/scene_segmentation.h"

namespace vdc {

// Segmentation cuts some objects into candidates none of which a model explains alone: the split
// at concave edges cuts a spool at its flanges and an animal at its legs, and a depth jump where
// the object hides a part of itself (a spool lying on its side: the near flange's face against
// the core behind it) even puts its parts in different clusters. Such parts lie side by side in
// the image. Returns the pairs of candidates beside each other in the image (some of their rays
// closer than the angle touch_distance [m] spans at the points' range, in front or behind) and,
// for a pair from two clusters, each with the other's cluster and the two clusters together
// (their candidates among these): each group once, as positions into candidates. The groups that
// span clusters come first: the scene layer has tried each cluster whole and its pieces alone
// before the groups, so an object the depth jump put into two clusters is still untried, while a
// pair within a cluster is a part of what was tried. Within each kind fewest points first (an
// object's pieces are small; a large union of several objects fails, and costs more). The cloud
// is in the camera frame (rays from the origin).
std::vector<std::vector<std::size_t>> adjacentCandidateGroups(
    const pcl::PointCloud<pcl::PointXYZ>& cloud,
    const std::vector<const SceneCandidate*>& candidates, double touch_distance);

}  // namespace vdc
