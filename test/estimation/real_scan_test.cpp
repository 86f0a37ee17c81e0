#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {
namespace {

// PCL's real stereo scan of a mug with a handle on a table (table_scene_mug_stereo_textured.pcd,
// BSD-3, from Debian's python3-pcl; scripts/install_deps.sh caches it), or VDC_REAL_SCAN.
std::string realScanPath() {
  if (const char* path = std::getenv("VDC_REAL_SCAN")) return path;
  return VDC_REAL_SCAN_CACHE "/table_scene_mug_stereo_textured.pcd";
}

// Its truth from the geometry (issue 13: the table normal is the mug's axis, the handle's azimuth
// its yaw), in the camera's optical frame; the camera is at the identity.
Eigen::Vector4d trueOrientation() {
  return Eigen::Vector4d(0.4761, 0.8774, 0.0557, -0.0211).normalized();
}
const Eigen::Vector3d kTrueOrigin(0.0565, 0.0742, 0.770);

double axisErrorDeg(const Eigen::Vector4d& q, const Eigen::Vector4d& truth) {
  const double cosine =
      quaternionToRotationMatrix(q).col(2).dot(quaternionToRotationMatrix(truth).col(2));
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / M_PI;
}

// The whole scene (table, mug and background, not a cut) through the estimator with tabletop
// segmentation and ICP refinement: one real view gives a grasp-ready pose (doc/evaluation.md,
// "Real scan"). The model is the quick test model `vdc train --quick` makes at build time
// (test/ros/CMakeLists.txt): its 12 directions make a poorer belief than the default training's,
// and its 4 mm surface set is what refinement thins the default's 2 mm one to anyway.
TEST(RealScanTest, OneRealViewOfTheWholeSceneGivesTheMugsPose) {
  const std::string path = realScanPath();
  if (!std::filesystem::exists(path)) {
    GTEST_SKIP() << "PCL's real scan is not at " << path
                 << ": run scripts/install_deps.sh (it unpacks it from `apt-get download "
                    "python3-pcl`) or set VDC_REAL_SCAN to the .pcd";
  }
  const std::string model_path = VDC_BINARY_DIR "/test_data/mug_quick.h5";
  if (!std::filesystem::exists(model_path)) {
    GTEST_SKIP() << "the quick test model " << model_path
                 << " is missing: build the `tests` target (it trains it)";
  }
  pcl::PointCloud<pcl::PointXYZ> scene;
  ASSERT_EQ(pcl::io::loadPCDFile(path, scene), 0) << path;
  const auto model = std::make_shared<const ModelBundle>(loadModelBundle(model_path));
  EstimatorParameters parameters;
  parameters.segmentation.mode = SegmentationMode::kTabletop;
  parameters.refinement = RefinementMode::kIcp;
  OrientationEstimator estimator(model, parameters);

  const ViewUpdate update = estimator.update(scene, Eigen::Isometry3d::Identity());
  ASSERT_TRUE(update.updated) << update.skip_reason;
  EXPECT_GE(update.refined_poses, 1) << update.refinement_skip_reason;
  const Eigen::Vector4d estimate = estimator.mapOrientation();
  const double rotation_error = rotationErrorDeg(estimate, trueOrientation());
  const double axis_error = axisErrorDeg(estimate, trueOrientation());
  const std::optional<Eigen::Vector3d> position = estimator.positionEstimate();
  ASSERT_TRUE(position.has_value());
  const double position_error_mm = 1000.0 * (*position - kTrueOrigin).norm();
  RecordProperty("object_points", std::to_string(update.object_points));
  RecordProperty("refined_poses", std::to_string(update.refined_poses));
  RecordProperty("rotation_error_deg", std::to_string(rotation_error));
  RecordProperty("axis_error_deg", std::to_string(axis_error));
  RecordProperty("position_error_mm", std::to_string(position_error_mm));
  RecordProperty("refinement_ms", std::to_string(update.timing.refinement));
  RecordProperty("searched_beyond_belief", update.searched ? "yes" : "no");
  RecordProperty("belief_rebuilt", update.rebuild_reason.empty() ? "no" : update.rebuild_reason);
  EXPECT_LT(axis_error, 5.0);
  EXPECT_LT(rotation_error, 10.0);
  EXPECT_LT(position_error_mm, 10.0);
}

}  // namespace
}  // namespace vdc
