#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

#include "view_direction_classification/scene/scene_segmentation.h"

namespace vdc::scene {

// Support planes of an organised cloud (integral-image normals, organised multi-plane
// segmentation), largest first. The cloud must be organised and at least kMinOrganisedSide wide
// and high.
std::vector<SupportPlane> findOrganisedSupportPlanes(
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
    const SceneSegmentationParameters& parameters);

// Support planes among the points at `finite` (iterative RANSAC), largest first.
std::vector<SupportPlane> findRansacSupportPlanes(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                  const std::vector<int>& finite,
                                                  const SceneSegmentationParameters& parameters);

// Smaller organised clouds are segmented as unorganised ones: the normals' integral-image window
// (10 pixels) and the plane regions need room.
constexpr int kMinOrganisedSide = 32;

// What each point of the cloud stands on: kNotStanding for points that are no object (not
// finite, on a plane, below every plane or too high above it), kNoSupport for every finite point
// when there is no plane, else the index of the nearest plane below it.
constexpr int kNotStanding = -2;
constexpr int kNoSupport = -1;
std::vector<int> standingOn(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                            const std::vector<int>& finite, const std::vector<SupportPlane>& planes,
                            const SceneSegmentationParameters& parameters);

// The support most of the candidate's points stand on (standingOn's planes), -1: none.
int supportOf(const std::vector<int>& indices, const std::vector<int>& standing);

}  // namespace vdc::scene
