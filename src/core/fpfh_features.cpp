#include "view_direction_classification/core/fpfh_features.h"

#include <pcl/features/fpfh_omp.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/search/kdtree.h>

#include <cmath>
#include <string>

#include "view_direction_classification/core/error.h"

namespace vdc {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

void checkParameters(const FeatureParameters& p) {
  auto positive = [](double value, const char* name) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw Error(std::string("feature parameter ") + name + " must be a positive length, got " +
                  std::to_string(value));
    }
  };
  positive(p.keypoint_voxel, "keypoint_voxel");
  positive(p.normal_radius, "normal_radius");
  positive(p.fpfh_radius, "fpfh_radius");
  if (!(p.support_voxel >= 0.0) || !std::isfinite(p.support_voxel)) {
    throw Error("feature parameter support_voxel must be 0 (off) or a positive length, got " +
                std::to_string(p.support_voxel));
  }
  if (p.min_neighbours < 1) {
    throw Error("feature parameter min_neighbours must be at least 1, got " +
                std::to_string(p.min_neighbours));
  }
}

// The finite points only: PCL's estimators and the voxel grid handle NaN inconsistently across
// versions, and an organised cloud from a depth camera is mostly NaN.
Cloud::Ptr finitePoints(const Cloud& cloud) {
  auto out = pcl::make_shared<Cloud>();
  out->reserve(cloud.size());
  for (const auto& p : cloud) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) out->push_back(p);
  }
  out->width = static_cast<std::uint32_t>(out->size());
  out->height = 1;
  out->is_dense = true;
  return out;
}

bool finiteNormal(const pcl::Normal& n) {
  return std::isfinite(n.normal_x) && std::isfinite(n.normal_y) && std::isfinite(n.normal_z);
}

}  // namespace

FeatureSet computeFeatures(const Cloud& cloud, const FeatureParameters& parameters,
                           const Eigen::Vector3f& viewpoint) {
  checkParameters(parameters);
  FeatureSet result;
  result.descriptors.resize(0, kFpfhBins);

  const Cloud::Ptr surface = finitePoints(cloud);
  // Fewer points than a descriptor needs support cannot yield a single valid feature.
  if (surface->size() < static_cast<std::size_t>(std::max(parameters.min_neighbours, 3))) {
    return result;
  }

  auto tree = pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>>();
  tree->setInputCloud(surface);

  // Normals on the full cloud, so that keypoint descriptors see every neighbour's normal.
  auto normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>>();
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> normal_estimation;
  normal_estimation.setInputCloud(surface);
  normal_estimation.setSearchMethod(tree);
  normal_estimation.setRadiusSearch(parameters.normal_radius);
  normal_estimation.setViewPoint(viewpoint.x(), viewpoint.y(), viewpoint.z());
  normal_estimation.compute(*normals);

  // FPFH's pair features use every support point's normal; a NaN normal (too few neighbours
  // within normal_radius) would poison the histogram, so such points leave the search surface.
  pcl::PointCloud<pcl::PointNormal> oriented;
  oriented.reserve(surface->size());
  for (std::size_t i = 0; i < surface->size(); ++i) {
    if (!finiteNormal((*normals)[i])) continue;
    pcl::PointNormal p;
    p.getVector3fMap() = (*surface)[i].getVector3fMap();
    p.getNormalVector3fMap() = (*normals)[i].getNormalVector3fMap();
    p.curvature = (*normals)[i].curvature;
    oriented.push_back(p);
  }
  if (parameters.support_voxel > 0.0 && !oriented.empty()) {
    // Voxel centroids with averaged (then renormalised) normals: the normals still come from the
    // full-resolution cloud, only the FPFH pair statistics are computed on fewer points.
    pcl::PointCloud<pcl::PointNormal> reduced;
    pcl::VoxelGrid<pcl::PointNormal> reduce;
    reduce.setInputCloud(oriented.makeShared());
    const auto edge = static_cast<float>(parameters.support_voxel);
    reduce.setLeafSize(edge, edge, edge);
    reduce.filter(reduced);
    oriented.swap(reduced);
  }
  auto support = pcl::make_shared<Cloud>();
  auto support_normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>>();
  support->reserve(oriented.size());
  support_normals->reserve(oriented.size());
  for (const auto& p : oriented) {
    const Eigen::Vector3f n = p.getNormalVector3fMap();
    if (!(n.norm() > 1e-6f)) continue;  // opposite normals averaged away: no usable direction
    support->push_back(pcl::PointXYZ(p.x, p.y, p.z));
    const Eigen::Vector3f unit = n.normalized();
    support_normals->push_back(pcl::Normal(unit.x(), unit.y(), unit.z()));
  }
  if (support->size() < static_cast<std::size_t>(parameters.min_neighbours)) return result;
  tree->setInputCloud(support);

  auto keypoints = pcl::make_shared<Cloud>();
  pcl::VoxelGrid<pcl::PointXYZ> voxel_grid;
  voxel_grid.setInputCloud(support);
  const auto leaf = static_cast<float>(parameters.keypoint_voxel);
  voxel_grid.setLeafSize(leaf, leaf, leaf);
  voxel_grid.filter(*keypoints);
  if (keypoints->empty()) return result;

  pcl::PointCloud<pcl::FPFHSignature33> descriptors;
  pcl::FPFHEstimationOMP<pcl::PointXYZ, pcl::Normal, pcl::FPFHSignature33> fpfh;
  fpfh.setInputCloud(keypoints);
  fpfh.setSearchSurface(support);
  fpfh.setInputNormals(support_normals);
  fpfh.setSearchMethod(tree);
  fpfh.setRadiusSearch(parameters.fpfh_radius);
  fpfh.compute(descriptors);

  // Keep keypoints with enough support and a finite, non-empty histogram.
  std::vector<int> neighbour_indices;
  std::vector<float> neighbour_distances;
  result.keypoints.reserve(keypoints->size());
  std::vector<std::size_t> kept;
  kept.reserve(keypoints->size());
  for (std::size_t i = 0; i < keypoints->size(); ++i) {
    const auto& histogram = descriptors[i].histogram;
    bool finite = true;
    float total = 0.0f;
    for (int b = 0; b < kFpfhBins; ++b) {
      finite = finite && std::isfinite(histogram[b]);
      total += histogram[b];
    }
    if (!finite || !(total > 0.0f)) continue;
    const int support_count = tree->radiusSearch((*keypoints)[i], parameters.fpfh_radius,
                                                 neighbour_indices, neighbour_distances);
    if (support_count < parameters.min_neighbours) continue;
    kept.push_back(i);
  }
  result.descriptors.resize(static_cast<Eigen::Index>(kept.size()), kFpfhBins);
  for (std::size_t row = 0; row < kept.size(); ++row) {
    const auto& point = (*keypoints)[kept[row]];
    result.keypoints.emplace_back(point.x, point.y, point.z);
    for (int b = 0; b < kFpfhBins; ++b) {
      result.descriptors(static_cast<Eigen::Index>(row), b) = descriptors[kept[row]].histogram[b];
    }
  }
  return result;
}

}  // namespace vdc
