#pragma once

// PCL's Kinect scene of a milk carton among other objects on a table (correspondence grouping
// tutorial, BSD-3, from Debian's python3-pcl) and the carton's own cloud, from the cache
// scripts/install_deps.sh fills (VDC_REAL_SCAN_CACHE, set by test/CMakeLists.txt) or from
// VDC_REAL_SCENE_DIR. Shared by the segmentation's and the scene estimator's real-data tests.

#include <pcl/common/transforms.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <cstdlib>
#include <string>

namespace vdc::test {

inline std::string realSceneDirectory() {
  if (const char* directory = std::getenv("VDC_REAL_SCENE_DIR")) return directory;
  return VDC_REAL_SCAN_CACHE;
}
inline std::string milkScenePath() {
  return realSceneDirectory() + "/milk_cartoon_all_small_clorox.pcd";
}
inline std::string milkCartonPath() { return realSceneDirectory() + "/milk.pcd"; }
inline constexpr char kMilkSceneMissing[] =
    "run scripts/install_deps.sh (it unpacks it from `apt-get download python3-pcl`) or set "
    "VDC_REAL_SCENE_DIR";

// milk.pcd is NOT in the scene's frame as shipped (its points lie up to 13 cm from the scene's):
// it is the carton cut out of the scene and moved by this rigid transform, the pose PCL's
// correspondence grouping tutorial finds (R ~ 14 degrees, t ~ (-0.16, 0.21, -0.04) m), refined
// here once by ICP. Applied, it puts every carton point on a scene point (the segmentation test
// checks it).
inline pcl::PointCloud<pcl::PointXYZ> cartonInSceneFrame(
    const pcl::PointCloud<pcl::PointXYZ>& carton) {
  Eigen::Matrix4f scene_from_carton;
  scene_from_carton << 0.968884f, -0.119713f, 0.216661f, -0.158966f,  //
      0.116827f, 0.992814f, 0.0261251f, 0.212499f,                    //
      -0.21823f, 9.8e-7f, 0.975901f, -0.0421221f,                     //
      0.0f, 0.0f, 0.0f, 1.0f;
  pcl::PointCloud<pcl::PointXYZ> moved;
  pcl::transformPointCloud(carton, moved, scene_from_carton);
  return moved;
}

// The scene's frame is not a camera optical frame: its points lie at z -0.5 to -2.1 m and its
// y grows upwards. A half turn about x makes it one (z forward, x right, y down): the organised
// cloud's pixel (u, v) then holds a point at u = 525 x / z + 319.5, v = 525 y / z + 239.5 to a
// thousandth of a pixel, a Kinect's intrinsics with both focal lengths positive.
inline Eigen::Isometry3d opticalFromMilkScene() {
  Eigen::Isometry3d optical_from_scene = Eigen::Isometry3d::Identity();
  optical_from_scene.linear() = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  return optical_from_scene;
}

}  // namespace vdc::test
