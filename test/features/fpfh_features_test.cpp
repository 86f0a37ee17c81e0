#include "view_direction_classification/features/fpfh_features.h"

#include <gtest/gtest.h>
#include <pcl/features/fpfh.h>
#include <pcl/features/normal_3d.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/search/kdtree.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// A curved, non-symmetric patch (a bump on a tilted wave) on a 3 mm grid: rich enough that FPFH
// histograms differ from point to point.
Cloud wavySurface(double spacing = 0.003) {
  Cloud cloud;
  for (double x = -0.05; x <= 0.05; x += spacing) {
    for (double y = -0.05; y <= 0.05; y += spacing) {
      const double z =
          0.01 * std::sin(40.0 * x) + 0.02 * std::exp(-(x * x + y * y) / 0.0008) + 0.1 * y * y;
      cloud.push_back(
          pcl::PointXYZ(static_cast<float>(x), static_cast<float>(y), static_cast<float>(0.6 + z)));
    }
  }
  return cloud;
}

bool allFinite(const FeatureSet& features) {
  if (!features.descriptors.allFinite()) return false;
  return std::all_of(features.keypoints.begin(), features.keypoints.end(),
                     [](const Eigen::Vector3f& p) { return p.allFinite(); });
}

TEST(FpfhFeatures, EmptyCloudGivesNoFeatures) {
  const FeatureSet features = computeFeatures(Cloud{});
  EXPECT_TRUE(features.empty());
  EXPECT_EQ(features.descriptors.rows(), 0);
  EXPECT_EQ(features.descriptors.cols(), kFpfhBins);
}

TEST(FpfhFeatures, AllNanCloudGivesNoFeatures) {
  Cloud cloud(64, 48);  // organised, as a depth camera that sees nothing delivers it
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (auto& p : cloud) p = pcl::PointXYZ(nan, nan, nan);
  cloud.is_dense = false;
  EXPECT_TRUE(computeFeatures(cloud).empty());
}

TEST(FpfhFeatures, SinglePointAndFewPointsGiveNoFeatures) {
  Cloud one;
  one.push_back(pcl::PointXYZ(0.f, 0.f, 0.6f));
  EXPECT_TRUE(computeFeatures(one).empty());
  Cloud few;
  for (int i = 0; i < 5; ++i) few.push_back(pcl::PointXYZ(0.001f * i, 0.f, 0.6f));
  EXPECT_TRUE(computeFeatures(few).empty());
}

TEST(FpfhFeatures, KeypointsWithTooFewNeighboursAreDropped) {
  // Points 5 cm apart: no keypoint has a neighbour within the 3 cm FPFH radius.
  Cloud sparse;
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) sparse.push_back(pcl::PointXYZ(0.05f * i, 0.05f * j, 0.6f));
  }
  EXPECT_TRUE(computeFeatures(sparse).empty());
}

TEST(FpfhFeatures, DenseSurfaceGivesFiniteFeaturesAtKeypointDensity) {
  // Keypoints are a voxel subsample of the support: a 3 mm support, finer than the 4 mm keypoint
  // grid, occupies every keypoint voxel (the default 7 mm support sets the density itself).
  FeatureParameters parameters;
  parameters.support_voxel = 0.003;
  const FeatureSet features = computeFeatures(wavySurface(), parameters);
  ASSERT_FALSE(features.empty());
  EXPECT_EQ(features.descriptors.rows(), static_cast<Eigen::Index>(features.size()));
  EXPECT_TRUE(allFinite(features));
  // A 10 x 10 cm patch subsampled with 4 mm voxels has at most ~26 x 26 keypoints; with 3 mm
  // source spacing every voxel is occupied, so far fewer would mean dropped features.
  EXPECT_GT(features.size(), 300u);
  EXPECT_LT(features.size(), 800u);
  // Each FPFH block (3 x 11 bins) is a percentage histogram: rows sum to ~300.
  for (Eigen::Index i = 0; i < features.descriptors.rows(); ++i) {
    EXPECT_NEAR(features.descriptors.row(i).sum(), 300.0f, 1.0f);
  }
}

TEST(FpfhFeatures, TheThreadCountDoesNotChangeTheFeatures) {
  // Each point's normal and histogram are computed by one thread and written to its own slot.
  FeatureParameters parameters;
  parameters.support_voxel = 0.003;
  const FeatureSet one = computeFeatures(wavySurface(), parameters, Eigen::Vector3f::Zero(), 1);
  const FeatureSet three = computeFeatures(wavySurface(), parameters, Eigen::Vector3f::Zero(), 3);
  ASSERT_FALSE(one.empty());
  ASSERT_EQ(one.size(), three.size());
  EXPECT_EQ(one.keypoints, three.keypoints);
  EXPECT_EQ(one.descriptors, three.descriptors);
}

TEST(FpfhFeatures, NanPointsAreIgnored) {
  const Cloud clean = wavySurface();
  Cloud with_nans;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < clean.size(); ++i) {
    with_nans.push_back(clean[i]);
    if (i % 3 == 0) with_nans.push_back(pcl::PointXYZ(nan, nan, nan));
  }
  with_nans.is_dense = false;
  const FeatureSet expected = computeFeatures(clean);
  const FeatureSet actual = computeFeatures(with_nans);
  ASSERT_EQ(actual.size(), expected.size());
  EXPECT_TRUE(allFinite(actual));
  EXPECT_TRUE(actual.descriptors.isApprox(expected.descriptors, 1e-5f));
}

TEST(FpfhFeatures, AreDeterministic) {
  const Cloud cloud = wavySurface();
  const FeatureSet first = computeFeatures(cloud);
  const FeatureSet second = computeFeatures(cloud);
  ASSERT_EQ(first.size(), second.size());
  EXPECT_EQ(first.descriptors, second.descriptors);
}

TEST(FpfhFeatures, DescriptorsAreInvariantToRotatingTheCloudAndViewpoint) {
  // Keypoints must coincide in both frames, so use a voxel smaller than the 3 mm point spacing
  // (every point is its own keypoint) and compare descriptors point by point.
  // The axis-aligned support voxel grid is not rotation invariant by construction: use the full
  // cloud as support here (SubsampledSupportKeepsDescriptorsClose covers the default).
  FeatureParameters parameters;
  parameters.keypoint_voxel = 0.001;
  parameters.support_voxel = 0.0;
  const Cloud cloud = wavySurface();
  const Eigen::Vector3f viewpoint(0.f, 0.f, 0.f);
  const Eigen::Matrix3f rotation =
      (Eigen::AngleAxisf(0.7f, Eigen::Vector3f(0.3f, -0.5f, 0.8f).normalized())).toRotationMatrix();
  const Eigen::Vector3f translation(0.2f, -0.1f, 0.3f);
  Cloud moved;
  for (const auto& p : cloud) {
    const Eigen::Vector3f q = rotation * p.getVector3fMap() + translation;
    moved.push_back(pcl::PointXYZ(q.x(), q.y(), q.z()));
  }
  const FeatureSet original = computeFeatures(cloud, parameters, viewpoint);
  const FeatureSet rotated = computeFeatures(moved, parameters, rotation * viewpoint + translation);
  ASSERT_GT(original.size(), 500u);
  ASSERT_EQ(original.size(), rotated.size());

  std::vector<float> differences;
  std::vector<float> unrelated;
  for (std::size_t i = 0; i < rotated.size(); ++i) {
    const Eigen::Vector3f back = rotation.transpose() * (rotated.keypoints[i] - translation);
    std::size_t match = 0;
    float best = std::numeric_limits<float>::max();
    for (std::size_t j = 0; j < original.size(); ++j) {
      const float d = (original.keypoints[j] - back).squaredNorm();
      if (d < best) best = d, match = j;
    }
    ASSERT_LT(std::sqrt(best), 1e-4f);
    differences.push_back(
        (rotated.descriptors.row(i) - original.descriptors.row(match)).cwiseAbs().sum());
    const std::size_t other = (match + original.size() / 2) % original.size();
    unrelated.push_back(
        (rotated.descriptors.row(i) - original.descriptors.row(other)).cwiseAbs().sum());
  }
  auto median = [](std::vector<float> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  // Rows sum to 300: a median L1 difference below 1 is rounding and bin-edge noise, while
  // descriptors of different points differ by tens.
  EXPECT_LT(median(differences), 1.0f);
  EXPECT_GT(median(unrelated), 20.0f);
}

TEST(FpfhFeatures, SubsampledSupportKeepsDescriptorsClose) {
  // Dense enough (1.5 mm) that the 3 mm support grid really reduces the surface.
  const Cloud cloud = wavySurface(0.0015);
  FeatureParameters full;
  full.support_voxel = 0.0;
  FeatureParameters reduced;  // the default support voxel
  ASSERT_GT(reduced.support_voxel, 0.0);
  const FeatureSet exact = computeFeatures(cloud, full);
  const FeatureSet approximate = computeFeatures(cloud, reduced);
  ASSERT_GT(exact.size(), 300u);
  // Keypoints come from the (coarser) support, so there are fewer, but none may be lost: about
  // one per support voxel on this 10 x 10 cm patch.
  const double per_voxel = 0.1 / reduced.support_voxel;
  ASSERT_GT(approximate.size(), static_cast<std::size_t>(0.9 * per_voxel * per_voxel));

  // Keypoints are voxel centroids of slightly different point sets: match by position.
  std::vector<float> differences, unrelated;
  for (std::size_t i = 0; i < approximate.size(); ++i) {
    std::size_t match = 0;
    float best = std::numeric_limits<float>::max();
    for (std::size_t j = 0; j < exact.size(); ++j) {
      const float d = (exact.keypoints[j] - approximate.keypoints[i]).squaredNorm();
      if (d < best) best = d, match = j;
    }
    if (std::sqrt(best) > 0.002f) continue;
    differences.push_back(
        (approximate.descriptors.row(i) - exact.descriptors.row(match)).cwiseAbs().sum());
    const std::size_t other = (match + exact.size() / 2) % exact.size();
    unrelated.push_back(
        (approximate.descriptors.row(i) - exact.descriptors.row(other)).cwiseAbs().sum());
  }
  ASSERT_GT(differences.size(), approximate.size() / 2);
  auto median = [](std::vector<float> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  EXPECT_LT(median(differences), 0.25f * median(unrelated));
}

TEST(FpfhFeatures, MatchPclFpfhEstimationOnTheSameSupport) {
  // The reference: PCL's own pipeline (normals on the cloud, 4 mm voxel keypoints, FPFHEstimation
  // with the cloud as search surface). With support_voxel = 0 and every normal finite, the
  // support surface is the cloud itself, so only float rounding may separate the two.
  const Cloud cloud = wavySurface();
  FeatureParameters parameters;
  parameters.support_voxel = 0.0;
  const auto surface = cloud.makeShared();
  auto tree = pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>>();
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> normal_estimation;
  normal_estimation.setInputCloud(surface);
  normal_estimation.setSearchMethod(tree);
  normal_estimation.setRadiusSearch(parameters.normal_radius);
  normal_estimation.compute(*normals);
  for (const auto& n : *normals) ASSERT_TRUE(std::isfinite(n.normal_x));
  Cloud::Ptr keypoints(new Cloud);
  pcl::VoxelGrid<pcl::PointXYZ> voxel_grid;
  voxel_grid.setInputCloud(surface);
  const auto leaf = static_cast<float>(parameters.keypoint_voxel);
  voxel_grid.setLeafSize(leaf, leaf, leaf);
  voxel_grid.filter(*keypoints);
  pcl::PointCloud<pcl::FPFHSignature33> reference;
  pcl::FPFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::FPFHSignature33> fpfh;
  fpfh.setInputCloud(keypoints);
  fpfh.setSearchSurface(surface);
  fpfh.setInputNormals(normals);
  fpfh.setSearchMethod(tree);
  fpfh.setRadiusSearch(parameters.fpfh_radius);
  fpfh.compute(reference);

  const FeatureSet features = computeFeatures(cloud, parameters);
  ASSERT_GT(features.size(), 300u);
  float worst = 0.0f;
  for (std::size_t i = 0; i < features.size(); ++i) {
    std::size_t match = 0;
    float best = std::numeric_limits<float>::max();
    for (std::size_t j = 0; j < keypoints->size(); ++j) {
      const float d = ((*keypoints)[j].getVector3fMap() - features.keypoints[i]).squaredNorm();
      if (d < best) best = d, match = j;
    }
    ASSERT_LT(std::sqrt(best), 1e-6f);
    float difference = 0.0f;
    for (int b = 0; b < kFpfhBins; ++b) {
      difference += std::abs(features.descriptors(static_cast<Eigen::Index>(i), b) -
                             reference[match].histogram[b]);
    }
    worst = std::max(worst, difference);
  }
  // Rows sum to 300; float rounding moves them by far less than 0.01.
  EXPECT_LT(worst, 0.01f);
}

TEST(FpfhFeatures, RejectsNonPositiveRadii) {
  FeatureParameters parameters;
  parameters.fpfh_radius = 0.0;
  EXPECT_THROW(computeFeatures(wavySurface(), parameters), Error);
  parameters = FeatureParameters{};
  parameters.normal_radius = -0.01;
  EXPECT_THROW(computeFeatures(wavySurface(), parameters), Error);
  parameters = FeatureParameters{};
  parameters.keypoint_voxel = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(computeFeatures(wavySurface(), parameters), Error);
  parameters = FeatureParameters{};
  parameters.support_voxel = -0.001;
  EXPECT_THROW(computeFeatures(wavySurface(), parameters), Error);
}

}  // namespace
}  // namespace vdc
