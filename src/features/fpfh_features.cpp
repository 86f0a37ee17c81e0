#include "view_direction_classification/features/fpfh_features.h"

#include <pcl/features/normal_3d.h>
#include <pcl/features/pfh_tools.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/parallel_for.h"

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

// Centroids of the occupied voxels of edge `edge` [m].
Cloud::Ptr voxelCentroids(const Cloud::ConstPtr& cloud, double edge) {
  auto centroids = pcl::make_shared<Cloud>();
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(cloud);
  const auto leaf = static_cast<float>(edge);
  grid.setLeafSize(leaf, leaf, leaf);
  grid.filter(*centroids);
  return centroids;
}

bool finiteNormal(const pcl::Normal& n) {
  return std::isfinite(n.normal_x) && std::isfinite(n.normal_y) && std::isfinite(n.normal_z);
}

// FPFH's three sub-histograms of 11 bins each (PCL's FPFHSignature33 layout).
constexpr int kSubBins = kFpfhBins / 3;
using Spfh = std::array<float, kFpfhBins>;

// The bins of one point pair's (theta, alpha, phi) angles, as PCL's FPFHEstimation bins them.
struct PairBins {
  std::uint8_t f1, f2, f3;
};

int binOf(double scaled) {
  const int index = static_cast<int>(std::floor(scaled));
  return std::clamp(index, 0, kSubBins - 1);
}

// PCL's normals of `points` from their neighbours in `surface` within `radius` (searched with
// `tree`, already on `surface`), turned towards `viewpoint`: pcl::NormalEstimation on blocks of
// points on `workers` threads, the same normals as NormalEstimationOMP's without OpenMP.
pcl::PointCloud<pcl::Normal>::Ptr normalsAt(const Cloud::Ptr& points, const Cloud::Ptr& surface,
                                            const pcl::search::KdTree<pcl::PointXYZ>::Ptr& tree,
                                            double radius, const Eigen::Vector3f& viewpoint,
                                            int workers) {
  constexpr std::size_t kBlock = 256;
  auto normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>>();
  normals->resize(points->size());
  const std::size_t blocks = (points->size() + kBlock - 1) / kBlock;
  parallelFor(blocks, workers, [&](int, std::size_t block) {
    auto indices = pcl::make_shared<pcl::Indices>();
    for (std::size_t i = block * kBlock; i < std::min(points->size(), (block + 1) * kBlock); ++i) {
      indices->push_back(static_cast<pcl::index_t>(i));
    }
    pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
    estimation.setInputCloud(points);
    estimation.setIndices(indices);
    estimation.setSearchSurface(surface);
    estimation.setSearchMethod(tree);
    estimation.setRadiusSearch(radius);
    estimation.setViewPoint(viewpoint.x(), viewpoint.y(), viewpoint.z());
    pcl::PointCloud<pcl::Normal> block_normals;
    estimation.compute(block_normals);
    for (std::size_t k = 0; k < indices->size(); ++k) {
      (*normals)[static_cast<std::size_t>((*indices)[k])] = block_normals[k];
    }
  });
  return normals;
}

// Simplified point feature histograms (SPFH) of the support points marked `needed`, each over
// its support neighbours within `radius`: the same histograms as pcl::FPFHEstimation's, at half
// the cost. PCL orders each pair's points canonically (pcl::computePairFeatures picks the point
// whose normal is closer to the connecting line as source), so a pair's features are the same
// from either end and are computed once here for both of its points. Rows of points not needed
// stay zero.
std::vector<Spfh> computeSpfh(const Cloud& support, const pcl::PointCloud<pcl::Normal>& normals,
                              const pcl::search::KdTree<pcl::PointXYZ>& tree,
                              const std::vector<char>& needed, float radius, int workers) {
  std::vector<int> neighbour_count(support.size(), 0);
  // pairs[i]: the pairs point i computes, with the other point's index.
  std::vector<std::vector<std::pair<int, PairBins>>> pairs(support.size());
  const float inverse_two_pi = 1.0f / (2.0f * static_cast<float>(M_PI));  // PCL's d_pi_
  parallelFor(support.size(), workers, [&](int, std::size_t index) {
    const auto i = static_cast<std::ptrdiff_t>(index);
    if (!needed[index]) return;
    pcl::Indices indices;
    std::vector<float> distances;
    tree.radiusSearch(support[static_cast<std::size_t>(i)], radius, indices, distances);
    neighbour_count[static_cast<std::size_t>(i)] = static_cast<int>(indices.size());
    auto& own = pairs[static_cast<std::size_t>(i)];
    own.reserve(indices.size());
    const Eigen::Vector4f p1 = support[static_cast<std::size_t>(i)].getVector4fMap();
    const Eigen::Vector4f n1 = normals[static_cast<std::size_t>(i)].getNormalVector4fMap();
    for (const auto j : indices) {
      // A pair with a needed point of lower index is computed by that point.
      if (j == i || (j < i && needed[static_cast<std::size_t>(j)])) continue;
      float f1, f2, f3, f4;
      if (!pcl::computePairFeatures(p1, n1, support[static_cast<std::size_t>(j)].getVector4fMap(),
                                    normals[static_cast<std::size_t>(j)].getNormalVector4fMap(), f1,
                                    f2, f3, f4)) {
        continue;
      }
      // PCL's expressions, so that values on a bin edge fall into the same bin.
      own.emplace_back(
          static_cast<int>(j),
          PairBins{static_cast<std::uint8_t>(binOf(kSubBins * ((f1 + M_PI) * inverse_two_pi))),
                   static_cast<std::uint8_t>(binOf(kSubBins * ((f2 + 1.0) * 0.5))),
                   static_cast<std::uint8_t>(binOf(kSubBins * ((f3 + 1.0) * 0.5)))});
    }
  });
  // Counts first, then one scale per row: PCL adds 100 / (neighbours - 1) per pair instead,
  // which differs by float rounding only.
  std::vector<Spfh> histograms(support.size());
  for (auto& row : histograms) row.fill(0.0f);
  for (std::size_t i = 0; i < support.size(); ++i) {
    for (const auto& [j, bins] : pairs[i]) {
      for (Spfh* row : {&histograms[i], needed[static_cast<std::size_t>(j)]
                                            ? &histograms[static_cast<std::size_t>(j)]
                                            : nullptr}) {
        if (row == nullptr) continue;
        (*row)[bins.f1] += 1.0f;
        (*row)[kSubBins + bins.f2] += 1.0f;
        (*row)[2 * kSubBins + bins.f3] += 1.0f;
      }
    }
  }
  for (std::size_t i = 0; i < support.size(); ++i) {
    if (neighbour_count[i] < 2) continue;  // no pair: the row stays zero (PCL's too)
    const float increment = 100.0f / static_cast<float>(neighbour_count[i] - 1);
    for (float& value : histograms[i]) value *= increment;
  }
  return histograms;
}

// FPFH of a keypoint: its support neighbours' SPFH weighted by inverse squared distance, each
// sub-histogram normalised to sum 100 (pcl::FPFHEstimation::weightPointSPFHSignature; a
// keypoint is a voxel centroid, not a support point, so it has no SPFH of its own). False if
// the result is not finite or empty.
bool weightedHistogram(const std::vector<Spfh>& spfh, const pcl::Indices& indices,
                       const std::vector<float>& squared_distances,
                       std::array<float, kFpfhBins>* histogram) {
  histogram->fill(0.0f);
  std::array<double, 3> sums = {0.0, 0.0, 0.0};
  for (std::size_t n = 0; n < indices.size(); ++n) {
    if (squared_distances[n] == 0.0f) continue;  // PCL skips the query point itself
    const float weight = 1.0f / squared_distances[n];
    const Spfh& row = spfh[static_cast<std::size_t>(indices[n])];
    for (int b = 0; b < kFpfhBins; ++b) {
      const float value = row[b] * weight;
      sums[b / kSubBins] += value;
      (*histogram)[b] += value;
    }
  }
  float total = 0.0f;
  bool finite = true;
  for (int b = 0; b < kFpfhBins; ++b) {
    const double sum = sums[b / kSubBins];
    const double scale = sum != 0.0 ? 100.0 / sum : sum;
    (*histogram)[b] = static_cast<float>((*histogram)[b] * scale);
    finite = finite && std::isfinite((*histogram)[b]);
    total += (*histogram)[b];
  }
  return finite && total > 0.0f;
}

}  // namespace

bool operator==(const FeatureParameters& a, const FeatureParameters& b) {
  return a.keypoint_voxel == b.keypoint_voxel && a.normal_radius == b.normal_radius &&
         a.fpfh_radius == b.fpfh_radius && a.support_voxel == b.support_voxel &&
         a.min_neighbours == b.min_neighbours;
}

FeatureSet computeFeatures(const Cloud& cloud, const FeatureParameters& parameters,
                           const Eigen::Vector3f& viewpoint, int threads) {
  const int workers = threads > 0 ? threads : hardwareThreads();
  checkParameters(parameters);
  FeatureSet result;
  result.descriptors.resize(0, kFpfhBins);

  const Cloud::Ptr surface = finitePoints(cloud);
  // Fewer points than a descriptor needs support cannot yield a single valid feature.
  if (surface->size() < static_cast<std::size_t>(std::max(parameters.min_neighbours, 3))) {
    return result;
  }

  // One kd-tree, rebuilt on the support surface below. Unsorted results: every consumer sums over
  // its neighbours, so sorting them by distance would only change float rounding, at a cost.
  auto tree = pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>>(/*sorted=*/false);
  tree->setInputCloud(surface);

  // The FPFH search surface: voxel centroids of the cloud (or the cloud itself). At 0.6 m a depth
  // camera samples the surface every ~1.1 mm, far denser than a 3 cm descriptor needs.
  const Cloud::Ptr support_candidates =
      parameters.support_voxel > 0.0 ? voxelCentroids(surface, parameters.support_voxel) : surface;

  // Normals only where FPFH needs them (the support points), each from the full-resolution cloud
  // within normal_radius: the cost follows the support, not the camera's resolution.
  const auto normals =
      normalsAt(support_candidates, surface, tree, parameters.normal_radius, viewpoint, workers);

  // FPFH's pair features use every support point's normal; a NaN normal (too few neighbours
  // within normal_radius) would poison the histogram, so such points leave the search surface.
  auto support = pcl::make_shared<Cloud>();
  auto support_normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>>();
  support->reserve(support_candidates->size());
  support_normals->reserve(support_candidates->size());
  for (std::size_t i = 0; i < support_candidates->size(); ++i) {
    if (!finiteNormal((*normals)[i])) continue;
    support->push_back((*support_candidates)[i]);
    support_normals->push_back((*normals)[i]);
  }
  if (support->size() < static_cast<std::size_t>(parameters.min_neighbours)) return result;
  tree->setInputCloud(support);

  const Cloud::Ptr keypoints = voxelCentroids(support, parameters.keypoint_voxel);
  if (keypoints->empty()) return result;

  // Support neighbourhoods of the keypoints: one search each gives the support count (the
  // min_neighbours test) and the FPFH weights.
  const std::size_t keypoint_count = keypoints->size();
  std::vector<pcl::Indices> keypoint_neighbours(keypoint_count);
  std::vector<std::vector<float>> keypoint_distances(keypoint_count);
  parallelFor(keypoint_count, workers, [&](int, std::size_t k) {
    tree->radiusSearch((*keypoints)[k], parameters.fpfh_radius, keypoint_neighbours[k],
                       keypoint_distances[k]);
  });
  std::vector<char> needed(support->size(), 0);
  std::vector<std::size_t> candidates;
  candidates.reserve(keypoint_count);
  for (std::size_t k = 0; k < keypoint_count; ++k) {
    if (keypoint_neighbours[k].size() < static_cast<std::size_t>(parameters.min_neighbours)) {
      continue;
    }
    candidates.push_back(k);
    for (const auto j : keypoint_neighbours[k]) needed[static_cast<std::size_t>(j)] = 1;
  }
  if (candidates.empty()) return result;

  const std::vector<Spfh> spfh = computeSpfh(*support, *support_normals, *tree, needed,
                                             static_cast<float>(parameters.fpfh_radius), workers);

  result.keypoints.reserve(candidates.size());
  std::vector<std::array<float, kFpfhBins>> histograms;
  histograms.reserve(candidates.size());
  for (const std::size_t k : candidates) {
    std::array<float, kFpfhBins> histogram;
    if (!weightedHistogram(spfh, keypoint_neighbours[k], keypoint_distances[k], &histogram)) {
      continue;
    }
    const auto& point = (*keypoints)[k];
    result.keypoints.emplace_back(point.x, point.y, point.z);
    histograms.push_back(histogram);
  }
  result.descriptors.resize(static_cast<Eigen::Index>(histograms.size()), kFpfhBins);
  for (std::size_t row = 0; row < histograms.size(); ++row) {
    for (int b = 0; b < kFpfhBins; ++b) {
      result.descriptors(static_cast<Eigen::Index>(row), b) = histograms[row][b];
    }
  }
  return result;
}

}  // namespace vdc
