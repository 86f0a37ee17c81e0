// The polish's weighted fit (refinement's private counted_voxels.h and icp_alignment.h): voxel
// centroids that remember their points, and ICP that weighs each observed point.
#include <gtest/gtest.h>
#include <pcl/filters/voxel_grid.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "counted_voxels.h"
#include "icp_alignment.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/surface_sampling.h"
#include "view_direction_classification/refinement/model_surface.h"

namespace vdc {
namespace {

// Points scattered over a few centimetres, every 50th NaN.
pcl::PointCloud<pcl::PointXYZ>::Ptr scatteredPoints(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coordinate(-0.03f, 0.03f);
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (int i = 0; i < count; ++i) {
    if (i % 50 == 0) {
      cloud->push_back(pcl::PointXYZ(NAN, 0.0f, 0.0f));
      continue;
    }
    cloud->push_back(pcl::PointXYZ(coordinate(rng), coordinate(rng), coordinate(rng)));
  }
  cloud->is_dense = true;  // wrongly, as a careless producer says: PCL's grid trusts it
  return cloud;
}

TEST(CountedVoxels, CountsEveryFinitePointInTheVoxelOfItsCentroid) {
  const auto points = scatteredPoints(5000, 1);
  const double voxel = 0.01;
  const CountedVoxels counted = countedVoxels(points, voxel);
  // The same centroids as PCL's grid gives the finite points without counting.
  auto finite = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : points->points) {
    if (std::isfinite(p.x)) finite->push_back(p);
  }
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(finite);
  grid.setLeafSize(0.01f, 0.01f, 0.01f);
  pcl::PointCloud<pcl::PointXYZ> plain;
  grid.filter(plain);
  ASSERT_EQ(counted.centroids->size(), plain.size());
  ASSERT_EQ(counted.counts.size(), plain.size());
  float total = 0.0f;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(counted.centroids->points[i].getVector3fMap(), plain.points[i].getVector3fMap());
    // A centroid's points lie in its voxel: recount them by brute force for a few.
    if (i % 20 == 0) {
      const Eigen::Vector3i cell =
          (plain.points[i].getVector3fMap() / 0.01f).array().floor().cast<int>();
      int inside = 0;
      for (const auto& p : points->points) {
        if (!std::isfinite(p.x)) continue;
        inside += (p.getVector3fMap() / 0.01f).array().floor().cast<int>().matrix() == cell;
      }
      EXPECT_EQ(counted.counts[i], static_cast<float>(inside)) << "centroid " << i;
    }
    total += counted.counts[i];
  }
  EXPECT_EQ(total, 5000.0f - 100.0f);  // every point but the NaN ones
}

// The mug's surface samples (object frame), and an observed subset in the world frame.
class WeightedIcpTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const SurfaceSamples samples = sampleSurface(makeMug(), 0.002, 1);
    const Eigen::AlignedBox3f box = makeMug().bounds();
    surface_ = std::make_shared<const ModelSurface>(
        samples.points, samples.normals,
        Eigen::AlignedBox3d(box.min().cast<double>(), box.max().cast<double>()), 0.002, 0.002);
    world_from_object_ = Eigen::Translation3d(0.4, -0.1, 0.7) *
                         Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, 2, -1).normalized());
    std::mt19937 rng(2);
    std::normal_distribution<float> noise(0.0f, 0.0005f);
    std::uniform_int_distribution<int> count(1, 6);
    observed_ = pcl::make_shared<pcl::PointCloud<pcl::PointNormal>>();
    for (std::size_t i = 0; i < samples.points.size(); i += 7) {
      if (samples.normals[i].z() < 0.2f) continue;  // the part a camera above would see
      pcl::PointNormal p;
      p.getVector3fMap() = (world_from_object_.cast<float>() * samples.points[i]) +
                           Eigen::Vector3f(noise(rng), noise(rng), noise(rng));
      p.getNormalVector3fMap().setZero();
      observed_->push_back(p);
      weights_.push_back(static_cast<float>(count(rng)));
    }
  }

  // Three ICP iterations from a start 3 degrees and 4 mm off (object_from_world).
  Eigen::Isometry3d aligned(const pcl::PointCloud<pcl::PointNormal>::Ptr& observed,
                            const std::vector<float>& weights) const {
    IcpSettings settings;
    settings.max_iterations = 3;
    settings.settle_iterations = 3;
    settings.max_correspondence_distance = 0.01;
    const Eigen::Isometry3d start =
        (Eigen::Translation3d(0.003, -0.002, 0.002) * world_from_object_ *
         Eigen::AngleAxisd(3.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()))
            .inverse();
    return IcpAlignment(surface_, observed, settings, weights).align(start).object_from_world;
  }

  std::shared_ptr<const ModelSurface> surface_;
  Eigen::Isometry3d world_from_object_;
  pcl::PointCloud<pcl::PointNormal>::Ptr observed_;
  std::vector<float> weights_;
};

TEST_F(WeightedIcpTest, APointsWeightCountsAsThatManyCopiesOfIt) {
  auto repeated = pcl::make_shared<pcl::PointCloud<pcl::PointNormal>>();
  for (std::size_t i = 0; i < observed_->size(); ++i) {
    for (int k = 0; k < static_cast<int>(weights_[i]); ++k)
      repeated->push_back(observed_->points[i]);
  }
  const Eigen::Isometry3d weighted = aligned(observed_, weights_);
  const Eigen::Isometry3d copies = aligned(repeated, {});
  const Eigen::Isometry3d plain = aligned(observed_, {});
  const auto gap = [](const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
    const Eigen::Isometry3d d = a.inverse() * b;
    return d.translation().norm() + Eigen::AngleAxisd(d.linear()).angle() * 0.1;
  };
  EXPECT_LT(gap(weighted, copies), 1e-6);
  // And the weights matter: unweighted, the same points end elsewhere.
  EXPECT_GT(gap(weighted, plain), 1e-5);
}

// A start 30 cm from the points (a search's far start): no pairs within the correspondence
// distance, so ICP stops at once, not converged, where it started, and says so only in its
// outcome: PCL's own error line on stderr (unthrottled, once per such start) is not printed.
TEST_F(WeightedIcpTest, AStartWithoutPairsStopsThereQuietly) {
  IcpSettings settings;
  settings.max_correspondence_distance = 0.01;
  const Eigen::Isometry3d start =
      (Eigen::Translation3d(0.3, 0.0, 0.0) * world_from_object_).inverse();
  testing::internal::CaptureStderr();
  const IcpOutcome outcome = IcpAlignment(surface_, observed_, settings, {}).align(start);
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_TRUE(outcome.too_few_pairs);
  EXPECT_FALSE(outcome.converged);
  EXPECT_TRUE(outcome.ended());
  EXPECT_TRUE(outcome.object_from_world.isApprox(start, 1e-5));  // ICP composes in floats
  EXPECT_EQ(printed.find("correspondences"), std::string::npos) << printed;
  // From near the truth the same points align.
  const IcpOutcome near =
      IcpAlignment(surface_, observed_, settings, {})
          .align((Eigen::Translation3d(0.002, 0.0, 0.0) * world_from_object_).inverse());
  EXPECT_TRUE(near.converged);
  EXPECT_FALSE(near.too_few_pairs);
}

TEST_F(WeightedIcpTest, RefusesWeightsThatAreNotOnePerPoint) {
  std::vector<float> too_few(weights_.begin(), weights_.end() - 1);
  EXPECT_THROW(IcpAlignment(surface_, observed_, IcpSettings{}, too_few), Error);
}

}  // namespace
}  // namespace vdc
