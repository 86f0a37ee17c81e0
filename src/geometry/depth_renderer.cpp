#include "view_direction_classification/geometry/depth_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_check.h"
#include "view_direction_classification/geometry/sensor_simulation.h"

namespace vdc {
namespace {

// Barycentric coordinates within this much outside a triangle still count as inside: shared
// edges then never leave a crack from rounding (a doubly hit pixel gets the same depth twice).
constexpr double kInsideTolerance = 1e-9;
// Twice the projected area [px^2] below which a triangle is skipped.
constexpr double kMinProjectedArea = 1e-6;

// A vertex in the optical frame.
using CameraPoint = Eigen::Vector3d;

class TriangleRasterizer {
 public:
  TriangleRasterizer(const CameraIntrinsics& intrinsics, std::vector<float>* inverse_depth)
      : c_(intrinsics), buffer_(*inverse_depth) {}

  // Draws a triangle, clipping it at the near plane first.
  void draw(const CameraPoint& a, const CameraPoint& b, const CameraPoint& c) {
    const double near = DepthRenderer::kNearPlane;
    const bool in_a = a.z() >= near, in_b = b.z() >= near, in_c = c.z() >= near;
    if (in_a && in_b && in_c) {
      drawVisible(a, b, c);
      return;
    }
    if (!in_a && !in_b && !in_c) return;
    // Sutherland-Hodgman against z >= near: a triangle becomes a triangle or a quadrilateral.
    std::array<CameraPoint, 4> clipped;
    int n = 0;
    const std::array<const CameraPoint*, 3> polygon = {&a, &b, &c};
    for (int i = 0; i < 3; ++i) {
      const CameraPoint& p = *polygon[i];
      const CameraPoint& q = *polygon[(i + 1) % 3];
      const bool p_in = p.z() >= near, q_in = q.z() >= near;
      if (p_in) clipped[n++] = p;
      if (p_in != q_in) {
        const double t = (near - p.z()) / (q.z() - p.z());
        CameraPoint crossing = p + t * (q - p);
        crossing.z() = near;
        clipped[n++] = crossing;
      }
    }
    for (int i = 1; i + 1 < n; ++i) drawVisible(clipped[0], clipped[i], clipped[i + 1]);
  }

 private:
  // Draws a triangle entirely beyond the near plane.
  void drawVisible(const CameraPoint& a, const CameraPoint& b, const CameraPoint& c) {
    const double u[3] = {c_.fx * a.x() / a.z() + c_.cx, c_.fx * b.x() / b.z() + c_.cx,
                         c_.fx * c.x() / c.z() + c_.cx};
    const double v[3] = {c_.fy * a.y() / a.z() + c_.cy, c_.fy * b.y() / b.z() + c_.cy,
                         c_.fy * c.y() / c.z() + c_.cy};
    const int u_min = std::max(0, static_cast<int>(std::ceil(std::min({u[0], u[1], u[2]}))));
    const int u_max =
        std::min(c_.width - 1, static_cast<int>(std::floor(std::max({u[0], u[1], u[2]}))));
    const int v_min = std::max(0, static_cast<int>(std::ceil(std::min({v[0], v[1], v[2]}))));
    const int v_max =
        std::min(c_.height - 1, static_cast<int>(std::floor(std::max({v[0], v[1], v[2]}))));
    if (u_min > u_max || v_min > v_max) return;
    const double area = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
    // Seen edge-on (or NaN): such a sliver covers no pixel centre, and its barycentric
    // gradients would be dominated by rounding.
    if (!(std::abs(area) > kMinProjectedArea)) return;
    // Barycentric weight of vertex k is affine in (u, v): lambda_k = base + du * u + dv * v.
    // With 1/z interpolated by the same weights the depth is exact for a pinhole.
    double base[3], du[3], dv[3];
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      du[k] = (v[i] - v[j]) / area;
      dv[k] = (u[j] - u[i]) / area;
      base[k] = (u[i] * v[j] - u[j] * v[i]) / area;
    }
    const double w[3] = {1.0 / a.z(), 1.0 / b.z(), 1.0 / c.z()};
    // 1/z is affine in (u, v) as well.
    const double w_base = base[0] * w[0] + base[1] * w[1] + base[2] * w[2];
    const double w_du = du[0] * w[0] + du[1] * w[1] + du[2] * w[2];
    const double w_dv = dv[0] * w[0] + dv[1] * w[1] + dv[2] * w[2];
    for (int row = v_min; row <= v_max; ++row) {
      float* line = buffer_.data() + static_cast<std::size_t>(row) * c_.width;
      double l0 = base[0] + dv[0] * row + du[0] * u_min;
      double l1 = base[1] + dv[1] * row + du[1] * u_min;
      double l2 = base[2] + dv[2] * row + du[2] * u_min;
      double inverse_z = w_base + w_dv * row + w_du * u_min;
      for (int col = u_min; col <= u_max; ++col) {
        if (l0 >= -kInsideTolerance && l1 >= -kInsideTolerance && l2 >= -kInsideTolerance) {
          const float value = static_cast<float>(inverse_z);
          if (value > line[col]) line[col] = value;
        }
        l0 += du[0];
        l1 += du[1];
        l2 += du[2];
        inverse_z += w_du;
      }
    }
  }

  const CameraIntrinsics& c_;
  std::vector<float>& buffer_;
};

}  // namespace

DepthRenderer::DepthRenderer(TriangleMesh mesh, CameraIntrinsics intrinsics)
    : mesh_(std::move(mesh)), intrinsics_(intrinsics) {
  checkIntrinsics(intrinsics_);
  if (mesh_.triangles.empty()) {
    throw Error("the depth renderer needs a mesh with at least one triangle");
  }
  checkMesh(mesh_);  // throws for invalid indices or non-finite vertices
}

void DepthRenderer::rasterize(const Eigen::Isometry3d& camera_from_object,
                              std::vector<float>* inverse_depth) const {
  if (!camera_from_object.matrix().allFinite()) {
    throw Error("the camera pose passed to the depth renderer is not finite");
  }
  inverse_depth->assign(static_cast<std::size_t>(intrinsics_.width) * intrinsics_.height, 0.0f);
  std::vector<CameraPoint> vertices(mesh_.vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    vertices[i] = camera_from_object * mesh_.vertices[i].cast<double>();
  }
  TriangleRasterizer rasterizer(intrinsics_, inverse_depth);
  for (const auto& tri : mesh_.triangles) {
    rasterizer.draw(vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]);
  }
}

std::vector<float> DepthRenderer::renderDepth(const Eigen::Isometry3d& camera_from_object) const {
  std::vector<float> depth;
  rasterize(camera_from_object, &depth);
  for (float& d : depth) d = d > 0.0f ? 1.0f / d : 0.0f;
  return depth;
}

pcl::PointCloud<pcl::PointXYZ> DepthRenderer::render(const Eigen::Isometry3d& camera_from_object,
                                                     const DepthNoiseModel& noise,
                                                     std::mt19937* rng) const {
  if (noise.enabled && rng == nullptr) {
    throw Error("the depth renderer needs a random number generator when noise is enabled");
  }
  if (noise.enabled && noise.sensor.kind != DepthSensor::kKinectGaussian) {
    return cloudOfDepth(sensorDepth(camera_from_object, noise.sensor, *rng));
  }
  std::vector<float> inverse_depth;
  rasterize(camera_from_object, &inverse_depth);

  pcl::PointCloud<pcl::PointXYZ> cloud = emptyCloud();
  std::normal_distribution<double> standard_normal(0.0, 1.0);
  for (int row = 0; row < intrinsics_.height; ++row) {
    for (int col = 0; col < intrinsics_.width; ++col) {
      const std::size_t index = static_cast<std::size_t>(row) * intrinsics_.width + col;
      if (!(inverse_depth[index] > 0.0f)) continue;
      double z = 1.0 / inverse_depth[index];
      if (noise.enabled) {
        z += noise.sigma(z) * standard_normal(*rng);
        if (z < kNearPlane) continue;
      }
      setPoint(col, row, z, &cloud.points[index]);
    }
  }
  return cloud;
}

std::vector<float> DepthRenderer::sensorDepth(const Eigen::Isometry3d& camera_from_object,
                                              const SensorModel& sensor, std::mt19937& rng) const {
  checkSensorModel(sensor);
  const std::vector<float> depth = renderDepth(camera_from_object);
  std::vector<float> projector_depth;
  if (sensor.shadows) {
    // The projector (second imager) sits at +baseline along the camera's x axis.
    const Eigen::Isometry3d projector_from_camera(Eigen::Translation3d(-sensor.baseline, 0.0, 0.0));
    projector_depth = renderDepth(projector_from_camera * camera_from_object);
  }
  return simulateSensor(sensor, intrinsics_, depth, projector_depth, rng);
}

pcl::PointCloud<pcl::PointXYZ> DepthRenderer::emptyCloud() const {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.points.assign(static_cast<std::size_t>(intrinsics_.width) * intrinsics_.height,
                      pcl::PointXYZ(nan, nan, nan));
  cloud.width = static_cast<std::uint32_t>(intrinsics_.width);
  cloud.height = static_cast<std::uint32_t>(intrinsics_.height);
  cloud.is_dense = false;
  return cloud;
}

void DepthRenderer::setPoint(int col, int row, double z, pcl::PointXYZ* point) const {
  point->x = static_cast<float>((col - intrinsics_.cx) * z / intrinsics_.fx);
  point->y = static_cast<float>((row - intrinsics_.cy) * z / intrinsics_.fy);
  point->z = static_cast<float>(z);
}

pcl::PointCloud<pcl::PointXYZ> DepthRenderer::cloudOfDepth(const std::vector<float>& depth) const {
  pcl::PointCloud<pcl::PointXYZ> cloud = emptyCloud();
  for (int row = 0; row < intrinsics_.height; ++row) {
    for (int col = 0; col < intrinsics_.width; ++col) {
      const std::size_t index = static_cast<std::size_t>(row) * intrinsics_.width + col;
      if (depth[index] >= kNearPlane) setPoint(col, row, depth[index], &cloud.points[index]);
    }
  }
  return cloud;
}

std::size_t countValidPoints(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  return static_cast<std::size_t>(std::count_if(cloud.begin(), cloud.end(), [](const auto& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  }));
}

}  // namespace vdc
