#pragma once

// Voxel-grid thinning that remembers how many points each centroid stands for (private to
// refinement).

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

namespace vdc {

struct CountedVoxels {
  pcl::PointCloud<pcl::PointXYZ>::Ptr centroids{new pcl::PointCloud<pcl::PointXYZ>};
  std::vector<float> counts;  // the finite input points in each centroid's voxel
};

// PCL's voxel grid of the finite points at `voxel` [m], each centroid with its point count: a
// least-squares fit that weights each centroid by its count weighs the surface as all the points
// would, at the thinned cloud's cost. The centroids are those of voxelFiltered (pose_refiner.cpp)
// at the same voxel.
CountedVoxels countedVoxels(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& points, double voxel);

}  // namespace vdc
