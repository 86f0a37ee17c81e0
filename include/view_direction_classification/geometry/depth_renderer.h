#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <random>
#include <vector>

#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_noise.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Simulated depth camera (doc/method.md section 2): a z-buffer rasteriser of one triangle mesh.
// Each pixel samples the ray through its centre (see CameraIntrinsics) and keeps the nearest
// surface hit, so self-occlusion is exact. Depth comes from screen-space barycentric
// interpolation of 1/z, which is exact for a pinhole camera. Both faces of every triangle are
// drawn: open meshes (the mug's inner wall, seen through its opening) show their back faces.
// Geometry in front of the near plane (kNearPlane) is clipped away.
// render() is const and keeps no state, so one renderer may serve several threads.
class DepthRenderer {
 public:
  static constexpr double kNearPlane = 0.01;  // [m]

  // Throws vdc::Error for a mesh without triangles, invalid indices or non-finite vertices, or
  // invalid intrinsics.
  explicit DepthRenderer(TriangleMesh mesh, CameraIntrinsics intrinsics = {});

  // Organised cloud (width x height, row-major, is_dense = false) in the camera's optical frame,
  // one point per pixel that hits the mesh, NaN elsewhere. With noise enabled and the default
  // sensor every depth gets axial Gaussian noise (the point moves along its pixel ray) drawn
  // from *rng in row-major pixel order; a hit whose noisy depth falls before the near plane
  // becomes NaN. Another noise.sensor replaces that noise with its model (sensor_simulation.h;
  // shadows render the mesh a second time, from the projector).
  // Throws vdc::Error if noise is enabled without an rng, or for a bad sensor model.
  pcl::PointCloud<pcl::PointXYZ> render(const Eigen::Isometry3d& camera_from_object,
                                        const DepthNoiseModel& noise = {false},
                                        std::mt19937* rng = nullptr) const;

  // Noise-free depth image (row-major, width x height) [m], 0 where nothing is hit.
  std::vector<float> renderDepth(const Eigen::Isometry3d& camera_from_object) const;

  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  const TriangleMesh& mesh() const { return mesh_; }

 private:
  // The depth image `sensor` measures (0 = nothing), drawing its noise from rng.
  std::vector<float> sensorDepth(const Eigen::Isometry3d& camera_from_object,
                                 const SensorModel& sensor, std::mt19937& rng) const;
  // All-NaN organised cloud of the image size.
  pcl::PointCloud<pcl::PointXYZ> emptyCloud() const;
  // The point at depth z on the ray of pixel (col, row).
  void setPoint(int col, int row, double z, pcl::PointXYZ* point) const;
  // Cloud of a depth image; depths before the near plane (and 0) become NaN.
  pcl::PointCloud<pcl::PointXYZ> cloudOfDepth(const std::vector<float>& depth) const;
  // Fills inverse_depth (1/z per pixel, 0 = no hit).
  void rasterize(const Eigen::Isometry3d& camera_from_object,
                 std::vector<float>* inverse_depth) const;

  TriangleMesh mesh_;
  CameraIntrinsics intrinsics_;
};

// Number of points with finite coordinates.
std::size_t countValidPoints(const pcl::PointCloud<pcl::PointXYZ>& cloud);

}  // namespace vdc
