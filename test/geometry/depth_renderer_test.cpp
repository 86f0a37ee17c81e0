#include "view_direction_classification/geometry/depth_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/geometry_test_meshes.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

bool valid(const pcl::PointXYZ& p) { return std::isfinite(p.z); }

const pcl::PointXYZ& pixel(const Cloud& cloud, int col, int row) { return cloud.at(col, row); }

TEST(DepthRenderer, CloudIsOrganisedAndNotDense) {
  const DepthRenderer renderer(test::makeSquare(0.2f, 1.0f));
  const Cloud cloud = renderer.render(Eigen::Isometry3d::Identity());
  EXPECT_EQ(cloud.width, 640u);
  EXPECT_EQ(cloud.height, 480u);
  EXPECT_EQ(cloud.size(), 640u * 480u);
  EXPECT_FALSE(cloud.is_dense);
}

TEST(DepthRenderer, FrontalPlaneGivesItsDepthEverywhereItCovers) {
  // A 0.25 m square at 1 m spans u, v in 319.5 -/+ 65.625 (or 239.5 -/+ 65.625): 132 pixel
  // centres each way.
  const DepthRenderer renderer(test::makeSquare(0.25f, 1.0f));
  const Cloud cloud = renderer.render(Eigen::Isometry3d::Identity());
  std::size_t hits = 0;
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) {
      const auto& p = pixel(cloud, col, row);
      const bool inside = std::abs(col - 319.5) < 65.6 && std::abs(row - 239.5) < 65.6;
      const bool outside = std::abs(col - 319.5) > 65.65 || std::abs(row - 239.5) > 65.65;
      if (inside) {
        ASSERT_TRUE(valid(p)) << col << "," << row;
      }
      if (outside) {
        ASSERT_FALSE(valid(p)) << col << "," << row;
      }
      if (!valid(p)) continue;
      ++hits;
      EXPECT_NEAR(p.z, 1.0f, 1e-6f);
      // The point lies on the ray through its pixel.
      EXPECT_NEAR(p.x, (col - 319.5) / 525.0, 1e-6);
      EXPECT_NEAR(p.y, (row - 239.5) / 525.0, 1e-6);
    }
  }
  EXPECT_EQ(hits, 132u * 132u);
  EXPECT_EQ(countValidPoints(cloud), hits);
}

TEST(DepthRenderer, TiltedPlaneDepthIsExactRayPlaneIntersection) {
  // Plane through (0, 0, 0.8) tilted 50 degrees about the image's vertical axis: 1/z is
  // interpolated in screen space, which is exact, so every pixel matches the analytic
  // intersection of its ray with the plane.
  const TriangleMesh square = test::makeSquare(0.4f, 0.0f);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.87, Eigen::Vector3d::UnitY()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0, 0, 0.8);
  const Eigen::Vector3d n = pose.linear() * Eigen::Vector3d::UnitZ();
  const Cloud cloud = DepthRenderer(square).render(pose);
  ASSERT_GT(countValidPoints(cloud), 10000u);
  double worst = 0.0;
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) {
      const auto& p = pixel(cloud, col, row);
      if (!valid(p)) continue;
      const Eigen::Vector3d ray((col - 319.5) / 525.0, (row - 239.5) / 525.0, 1.0);
      const double z = n.dot(Eigen::Vector3d(0, 0, 0.8)) / n.dot(ray);
      worst = std::max(worst, std::abs(p.z - z) / z);
    }
  }
  EXPECT_LT(worst, 1e-6);  // float storage, no interpolation error
}

TEST(DepthRenderer, SphereSilhouetteRadiusMatchesPerspectiveFormula) {
  const double r = 0.1, d = 1.0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0, 0, d);
  const Cloud cloud = DepthRenderer(test::makeSphere(static_cast<float>(r), 4)).render(pose);
  const double expected = 525.0 * r / std::sqrt(d * d - r * r);
  const double area_radius = std::sqrt(countValidPoints(cloud) / M_PI);
  EXPECT_NEAR(area_radius, expected, 0.5);
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) {
      const double rho = std::hypot(col - 319.5, row - 239.5);
      if (rho < expected - 1.0) {
        EXPECT_TRUE(valid(pixel(cloud, col, row)));
      }
      if (rho > expected + 1.0) {
        EXPECT_FALSE(valid(pixel(cloud, col, row)));
      }
    }
  }
  // The nearest point is the sphere's front pole.
  EXPECT_NEAR(pixel(cloud, 320, 240).z, d - r, 2e-4);
}

TEST(DepthRenderer, ClosedBoxSeenFromAFaceShowsOnlyThatFace) {
  const float half = 0.05f;
  const DepthRenderer renderer(test::makeBox({half, half, half}));
  const std::vector<Eigen::Vector3d> face_directions = {
      Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
      -Eigen::Vector3d::UnitZ()};
  for (const Eigen::Vector3d& d : face_directions) {
    const Cloud cloud = renderer.render(cameraFromObject(d, 0.5, 0.3));
    ASSERT_GT(countValidPoints(cloud), 5000u);
    for (const auto& p : cloud) {
      if (valid(p)) {
        ASSERT_NEAR(p.z, 0.5f - half, 1e-6f) << d.transpose();
      }
    }
  }
}

TEST(DepthRenderer, OpenMugShowsItsInnerBottomThroughTheOpening) {
  const MugShape shape;
  const DepthRenderer renderer(makeMug(shape));
  const Cloud top = renderer.render(cameraFromObject(Eigen::Vector3d::UnitZ(), 0.6, 0.0));
  EXPECT_NEAR(pixel(top, 320, 240).z, 0.6 + shape.height / 2 - shape.bottom, 1e-5);
  const Cloud bottom = renderer.render(cameraFromObject(-Eigen::Vector3d::UnitZ(), 0.6, 0.0));
  EXPECT_NEAR(pixel(bottom, 320, 240).z, 0.6 - shape.height / 2, 1e-5);
}

TEST(DepthRenderer, MugSeenFromPositiveXShowsTheHandleInFront) {
  const MugShape shape;
  const DepthRenderer renderer(makeMug(shape));
  const Cloud cloud = renderer.render(cameraFromObject(Eigen::Vector3d::UnitX(), 0.6, 0.0));
  const double handle_front =
      shape.outer_radius - shape.wall / 2 + shape.handle_reach + shape.handle_tube_radius;
  // Polygonal tube: the centre pixel lies within the tube's sagitta of the round surface.
  EXPECT_NEAR(pixel(cloud, 320, 240).z, 0.6 - handle_front, 3e-4);
}

TEST(DepthRenderer, GeometryCrossingTheNearPlaneIsClipped) {
  // A floor plane below the camera reaching from behind it to 2 m ahead.
  TriangleMesh floor;
  floor.vertices = {{-1, 0.2f, -1}, {1, 0.2f, -1}, {1, 0.2f, 2}, {-1, 0.2f, 2}};
  floor.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Cloud cloud = DepthRenderer(floor).render(Eigen::Isometry3d::Identity());
  ASSERT_GT(countValidPoints(cloud), 1000u);
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) {
      const auto& p = pixel(cloud, col, row);
      if (!valid(p)) continue;
      EXPECT_NEAR(p.y, 0.2f, 1e-5f);
      EXPECT_GE(p.z, DepthRenderer::kNearPlane);
      EXPECT_LE(p.z, 2.0f + 1e-4f);
    }
  }
  // Every pixel below the horizon row up to the far edge's row sees the floor.
  EXPECT_TRUE(valid(pixel(cloud, 320, 479)));
}

TEST(DepthRenderer, ObjectBehindOrFarBesideTheCameraGivesAnAllNanCloud) {
  const DepthRenderer renderer(makeMug());
  Eigen::Isometry3d behind = Eigen::Isometry3d::Identity();
  behind.translation() = Eigen::Vector3d(0, 0, -0.6);
  const Cloud behind_cloud = renderer.render(behind);
  EXPECT_EQ(behind_cloud.size(), 640u * 480u);
  EXPECT_EQ(countValidPoints(behind_cloud), 0u);
  Eigen::Isometry3d beside = Eigen::Isometry3d::Identity();
  beside.translation() = Eigen::Vector3d(5.0, 0, 0.6);
  EXPECT_EQ(countValidPoints(renderer.render(beside)), 0u);
}

TEST(DepthRenderer, NoiseIsUnbiasedWithTheModelsSigmaAlongThePixelRays) {
  const double depth = 1.2;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0, 0, depth);
  const DepthRenderer renderer(test::makeSquare(1.0f, 0.0f));
  std::mt19937 rng(99);
  const DepthNoiseModel noise;
  const Cloud cloud = renderer.render(pose, noise, &rng);
  double sum = 0, sum_sq = 0;
  std::size_t n = 0;
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) {
      const auto& p = pixel(cloud, col, row);
      if (!valid(p)) continue;
      const double e = p.z - depth;
      sum += e;
      sum_sq += e * e;
      ++n;
      ASSERT_NEAR(p.x / p.z, (col - 319.5) / 525.0, 1e-6);
      ASSERT_NEAR(p.y / p.z, (row - 239.5) / 525.0, 1e-6);
    }
  }
  ASSERT_GT(n, 100000u);
  const double sigma = noise.sigma(depth);
  const double mean = sum / n;
  const double std_dev = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_LT(std::abs(mean), 4 * sigma / std::sqrt(static_cast<double>(n)));
  EXPECT_NEAR(std_dev, sigma, 0.01 * sigma);
  EXPECT_NEAR(sigma, 0.0012 + 0.0019 * 0.64, 1e-12);
}

TEST(DepthRenderer, NoiseIsReproducibleForASeedAndOffWhenDisabled) {
  const DepthRenderer renderer(makeMug());
  const Eigen::Isometry3d pose = cameraFromObject(Eigen::Vector3d(1, 1, 1), 0.6, 0.2);
  std::mt19937 a(5), b(5);
  const Cloud first = renderer.render(pose, DepthNoiseModel{}, &a);
  const Cloud second = renderer.render(pose, DepthNoiseModel{}, &b);
  const Cloud clean = renderer.render(pose);
  ASSERT_EQ(countValidPoints(first), countValidPoints(clean));
  std::size_t differing = 0;
  for (std::size_t i = 0; i < clean.size(); ++i) {
    if (!valid(clean[i])) continue;
    ASSERT_EQ(first[i].z, second[i].z);
    differing += first[i].z != clean[i].z;
  }
  EXPECT_EQ(differing, countValidPoints(clean));
}

TEST(DepthRenderer, DepthImageAgreesWithTheCloud) {
  const DepthRenderer renderer(makeMug());
  const Eigen::Isometry3d pose = cameraFromObject(Eigen::Vector3d(0.2, -1, 0.4), 0.6, 1.0);
  const Cloud cloud = renderer.render(pose);
  const std::vector<float> depth = renderer.renderDepth(pose);
  ASSERT_EQ(depth.size(), cloud.size());
  for (std::size_t i = 0; i < depth.size(); ++i) {
    if (valid(cloud[i])) {
      EXPECT_FLOAT_EQ(depth[i], cloud[i].z);
    } else {
      EXPECT_EQ(depth[i], 0.0f);
    }
  }
}

TEST(DepthRenderer, CustomIntrinsicsSetTheCloudSize) {
  CameraIntrinsics small;
  small.width = 160;
  small.height = 120;
  small.fx = small.fy = 131.25;
  small.cx = 79.5;
  small.cy = 59.5;
  const DepthRenderer renderer(makeMug(), small);
  const Cloud cloud = renderer.render(cameraFromObject(Eigen::Vector3d::UnitY(), 0.6, 0.0));
  EXPECT_EQ(cloud.width, 160u);
  EXPECT_EQ(cloud.height, 120u);
  EXPECT_GT(countValidPoints(cloud), 100u);
  EXPECT_EQ(renderer.intrinsics().width, 160);
}

TEST(DepthRenderer, BadInputsThrow) {
  EXPECT_THROW(DepthRenderer{TriangleMesh{}}, Error);
  TriangleMesh broken = test::makeSquare(0.1f, 0.0f);
  broken.triangles.emplace_back(0, 2, 4);
  EXPECT_THROW(DepthRenderer{broken}, Error);
  CameraIntrinsics bad;
  bad.fy = -1;
  EXPECT_THROW(DepthRenderer(makeMug(), bad), Error);
  const DepthRenderer renderer(makeMug());
  EXPECT_THROW(renderer.render(Eigen::Isometry3d::Identity(), DepthNoiseModel{}, nullptr), Error);
  Eigen::Isometry3d nan_pose = Eigen::Isometry3d::Identity();
  nan_pose.translation().x() = std::nan("");
  EXPECT_THROW(renderer.render(nan_pose), Error);
}

}  // namespace
}  // namespace vdc
