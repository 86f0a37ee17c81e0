#include "view_direction_classification/evaluation/baseline_icp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

double rotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / M_PI;
}

// The PPF detector (for its scenes and the whole recipe) trains in seconds: once for the suite.
class BaselineIcpTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mesh_ = new TriangleMesh(makeMug());
    ppf_ = new PpfBaseline(*mesh_);
    icp_ = new BaselineIcp(*mesh_);
  }
  static void TearDownTestSuite() {
    delete icp_;
    delete ppf_;
    delete mesh_;
    icp_ = nullptr;
    ppf_ = nullptr;
    mesh_ = nullptr;
  }
  static pcl::PointCloud<pcl::PointNormal>::Ptr renderScene(const Eigen::Isometry3d& truth) {
    return ppf_->sceneWithNormals(DepthRenderer(*mesh_).render(truth));
  }

  static TriangleMesh* mesh_;
  static PpfBaseline* ppf_;
  static BaselineIcp* icp_;
};
TriangleMesh* BaselineIcpTest::mesh_ = nullptr;
PpfBaseline* BaselineIcpTest::ppf_ = nullptr;
BaselineIcp* BaselineIcpTest::icp_ = nullptr;

TEST_F(BaselineIcpTest, ReturnsToTheTruthFromAPosePerturbedByAFewDegrees) {
  // A PPF-like start: 4 degrees about an oblique axis through the object origin and 4 mm off, on
  // noise-free views with the handle visible, from above and from below.
  const Eigen::Vector3d directions[] = {{1.0, 0.4, 0.8}, {0.2, -1.0, 0.3}, {-0.5, 0.6, -0.7}};
  for (const auto& direction : directions) {
    const Eigen::Isometry3d truth = cameraFromObject(direction, 0.6, 0.3);
    Eigen::Isometry3d start = truth;
    start.rotate(Eigen::AngleAxisd(4.0 * M_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized()));
    start.pretranslate(Eigen::Vector3d(0.003, -0.002, 0.002));
    ASSERT_GT(rotationErrorDeg(start, truth), 3.9);

    const BaselineIcpResult result = icp_->align(renderScene(truth), start);
    ASSERT_TRUE(result.converged);
    const double rotation_error = rotationErrorDeg(result.camera_from_object, truth);
    const double position_error =
        (result.camera_from_object.translation() - truth.translation()).norm();
    std::printf("ICP: rotation error %.2f deg, position error %.2f mm, fitness %.2g m^2, %.0f ms\n",
                rotation_error, 1e3 * position_error, result.fitness_m2, result.milliseconds);
    EXPECT_LT(rotation_error, 1.0);
    EXPECT_LT(position_error, 0.001);
  }
}

TEST_F(BaselineIcpTest, NoPpfPoseGivesNoIcp) {
  const PpfIcpMatch empty = matchPpfIcp(*ppf_, *icp_, pcl::PointCloud<pcl::PointXYZ>());
  EXPECT_FALSE(empty.ppf.found);
  EXPECT_FALSE(empty.icp.has_value());
  EXPECT_FALSE(empty.pose().has_value());
}

TEST_F(BaselineIcpTest, ThePipelineRefinesThePpfPoseOfARenderedView) {
  const Eigen::Isometry3d truth = cameraFromObject(Eigen::Vector3d(1.0, 0.4, 0.8), 0.6, 0.3);
  const PpfIcpMatch match = matchPpfIcp(*ppf_, *icp_, DepthRenderer(*mesh_).render(truth));
  ASSERT_TRUE(match.ppf.found);
  ASSERT_TRUE(match.icp.has_value());
  ASSERT_TRUE(match.icp->converged);
  ASSERT_TRUE(match.pose().has_value());
  EXPECT_TRUE(match.pose()->isApprox(match.icp->camera_from_object));
  // ICP moves the PPF pose (PPF's clustered pose is not a least-squares fit).
  EXPECT_FALSE(match.pose()->isApprox(match.ppf.camera_from_object, 1e-9));
}

TEST_F(BaselineIcpTest, TooFewScenePointsKeepTheStartingPose) {
  const Eigen::Isometry3d start = cameraFromObject(Eigen::Vector3d(0, 0, 1), 0.6, 0.0);
  pcl::PointCloud<pcl::PointNormal>::Ptr few(new pcl::PointCloud<pcl::PointNormal>);
  for (int i = 0; i < 3; ++i) {
    pcl::PointNormal point;
    point.getVector3fMap() = Eigen::Vector3f(0.01f * i, 0.0f, 0.6f);
    point.getNormalVector3fMap() = -Eigen::Vector3f::UnitZ();
    few->push_back(point);
  }
  for (const auto& scene : {few, pcl::PointCloud<pcl::PointNormal>::Ptr()}) {
    const BaselineIcpResult result = icp_->align(scene, start);
    EXPECT_FALSE(result.converged);
    EXPECT_TRUE(result.camera_from_object.isApprox(start));
  }
}

TEST_F(BaselineIcpTest, AFlatPatchLeavesThePoseUndeterminedAndKeepsTheStartingPose) {
  // The centre of the mug's flat bottom seen from below: every pair's target normal is the
  // bottom's, so the point-to-plane system fixes 3 of the 6 degrees of freedom and PCL's inverse
  // of it is not finite. Unguarded, the next iteration's NaN points abort PCL's k-d tree.
  const SurfaceSamples samples = sampleSurface(*mesh_, 0.002, 3);
  float lowest = 0.0f;
  for (const auto& p : samples.points) lowest = std::min(lowest, p.z());
  const Eigen::Isometry3d start = cameraFromObject(Eigen::Vector3d(0, 0, -1), 0.6, 0.0);
  pcl::PointCloud<pcl::PointNormal>::Ptr patch(new pcl::PointCloud<pcl::PointNormal>);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector3f& p = samples.points[i];
    if (p.z() > lowest + 1e-4f || p.head<2>().norm() > 0.02f) continue;
    pcl::PointNormal point;
    point.getVector3fMap() = (start.cast<float>() * p);
    point.getNormalVector3fMap() = start.linear().cast<float>() * samples.normals[i];
    patch->push_back(point);
  }
  ASSERT_GT(patch->size(), 100u);
  const BaselineIcpResult result = icp_->align(patch, start);
  EXPECT_FALSE(result.converged);
  EXPECT_TRUE(result.camera_from_object.isApprox(start));
}

TEST(BaselineIcpParametersTest, InvalidParametersAndEmptyMeshesAreRefused) {
  BaselineIcpParameters bad;
  bad.max_correspondence_distance = 0.0;
  EXPECT_THROW(BaselineIcp(makeMug(), bad), Error);
  bad = BaselineIcpParameters{};
  bad.max_iterations = 0;
  EXPECT_THROW(BaselineIcp(makeMug(), bad), Error);
  bad = BaselineIcpParameters{};
  bad.model_spacing = std::nan("");
  EXPECT_THROW(BaselineIcp(makeMug(), bad), Error);
  EXPECT_THROW(BaselineIcp(TriangleMesh{}), Error);
}

}  // namespace
}  // namespace vdc
