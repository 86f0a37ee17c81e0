#include "counted_voxels.h"

#include <pcl/filters/voxel_grid.h>

#include <algorithm>
#include <cmath>

namespace vdc {

namespace {

bool finite(const pcl::PointXYZ& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// PCL's grid skips non-finite points only in a cloud that says it is not dense (it trusts
// is_dense, and a NaN point then indexes outside the grid).
pcl::PointCloud<pcl::PointXYZ>::ConstPtr markedNotDense(
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& points) {
  if (!points->is_dense || std::all_of(points->begin(), points->end(), finite)) return points;
  auto copy = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(*points);
  copy->is_dense = false;
  return copy;
}

}  // namespace

CountedVoxels countedVoxels(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& points, double voxel) {
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(markedNotDense(points));
  const float leaf = static_cast<float>(voxel);
  grid.setLeafSize(leaf, leaf, leaf);
  // The layout maps a voxel to its centroid's index, so each point can be counted in its voxel.
  grid.setSaveLeafLayout(true);
  CountedVoxels result;
  grid.filter(*result.centroids);
  result.counts.assign(result.centroids->size(), 0.0f);
  for (const pcl::PointXYZ& p : points->points) {
    if (!finite(p)) continue;
    // Bounds-checked: -1 outside the grid, or where PCL kept no layout (a grid too fine for
    // its integer indices, when it passes the points through unthinned).
    const int index = grid.getCentroidIndexAt(grid.getGridCoordinates(p.x, p.y, p.z));
    if (index >= 0 && static_cast<std::size_t>(index) < result.counts.size()) {
      result.counts[static_cast<std::size_t>(index)] += 1.0f;
    }
  }
  // A centroid no point was counted in (PCL passed the cloud through) stands for itself.
  for (float& count : result.counts) {
    if (count == 0.0f) count = 1.0f;
  }
  return result;
}

}  // namespace vdc
