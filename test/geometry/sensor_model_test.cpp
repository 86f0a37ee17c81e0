// The depth sensor models (geometry/sensor_model.h, sensor_simulation.h) through the renderer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "support/geometry_test_meshes.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/sensor_model.h"
#include "view_direction_classification/geometry/sensor_simulation.h"

namespace vdc {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

constexpr double kCx = 319.5, kF = 525.0;
constexpr float kForegroundZ = 0.8f, kBackgroundZ = 1.0f;  // test::makeDepthStep()
// The 0.2 m foreground square at 0.8 m covers pixel centres within 65.625 px of the centre.
constexpr double kForegroundHalfPx = 0.1 * kF / 0.8;

bool valid(const pcl::PointXYZ& p) { return std::isfinite(p.z); }

// Pixel distance (Chebyshev) from (col, row) to the foreground square's border.
double distanceToEdge(int col, int row) {
  const double du = std::abs(col - kCx), dv = std::abs(row - 239.5);
  const double outside = std::max(du, dv) - kForegroundHalfPx;
  return std::abs(outside);
}

bool inForeground(int col, int row) {
  return std::abs(col - kCx) < kForegroundHalfPx && std::abs(row - 239.5) < kForegroundHalfPx;
}

Cloud renderStep(const SensorModel& sensor, unsigned seed) {
  std::mt19937 rng(seed);
  return DepthRenderer(test::makeDepthStep())
      .render(Eigen::Isometry3d::Identity(), DepthNoiseModel{true, sensor}, &rng);
}

// A model with every effect off: each test switches on the one it checks.
SensorModel bareModel() {
  SensorModel m;
  m.kind = DepthSensor::kStructuredLight;
  m.edge_band_px = 1;
  return m;
}

TEST(SensorModel, DefaultNoiseRendersExactlyAsBeforeTheSensorModels) {
  // The default draws one standard normal per hit in row-major order and adds sigma(z) times it
  // to the exact depth: replayed here from the same seed.
  const DepthRenderer renderer(makeMug());
  const Eigen::Isometry3d pose = cameraFromObject(Eigen::Vector3d(1, -0.5, 0.7), 0.6, 0.3);
  const Cloud clean = renderer.render(pose);
  std::mt19937 rng(17), replay(17), named(17);
  const Cloud noisy = renderer.render(pose, DepthNoiseModel{}, &rng);
  const DepthNoiseModel model;
  std::normal_distribution<double> standard_normal(0.0, 1.0);
  std::size_t compared = 0;
  for (std::size_t i = 0; i < clean.size(); ++i) {
    ASSERT_EQ(valid(clean[i]), valid(noisy[i])) << i;
    if (!valid(clean[i])) continue;
    const double z = clean[i].z;
    // The renderer adds the noise to the double depth before rounding to float.
    ASSERT_NEAR(noisy[i].z, z + model.sigma(z) * standard_normal(replay), 2e-7) << i;
    ++compared;
  }
  EXPECT_GT(compared, 5000u);
  // Naming the default sensor is the default.
  const Cloud by_name = renderer.render(
      pose, DepthNoiseModel{true, sensorModel(DepthSensor::kKinectGaussian)}, &named);
  for (std::size_t i = 0; i < noisy.size(); ++i) {
    if (valid(noisy[i])) {
      ASSERT_EQ(by_name[i].z, noisy[i].z) << i;
    }
  }
}

TEST(SensorModel, StructuredLightDepthsLieOnTheDisparityGrid) {
  const SensorModel sl = sensorModel(DepthSensor::kStructuredLight);
  const double fb = sl.disparity_focal_px * sl.baseline;
  // A plane tilted 40 degrees spans many disparity levels.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitY()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.2);
  const DepthRenderer renderer(test::makeSquare(0.6f, 0.0f));
  std::mt19937 rng(3), gaussian_rng(3);
  const Cloud cloud = renderer.render(pose, DepthNoiseModel{true, sl}, &rng);
  const Cloud gaussian = renderer.render(pose, DepthNoiseModel{}, &gaussian_rng);
  const auto onGrid = [&](float z) {
    const double steps = fb / z / sl.disparity_step_px;
    return std::abs(steps - std::round(steps)) < 2e-3;
  };
  std::size_t points = 0, gaussian_on_grid = 0, gaussian_points = 0;
  std::vector<long> levels;
  for (const auto& p : cloud) {
    if (!valid(p)) continue;
    ++points;
    ASSERT_TRUE(onGrid(p.z)) << p.z;
    levels.push_back(std::lround(fb / p.z / sl.disparity_step_px));
  }
  for (const auto& p : gaussian) {
    if (!valid(p)) continue;
    ++gaussian_points;
    gaussian_on_grid += onGrid(p.z);
  }
  EXPECT_GT(points, 10000u);
  std::sort(levels.begin(), levels.end());
  EXPECT_GT(std::unique(levels.begin(), levels.end()) - levels.begin(), 20);
  // Continuous noise lands on the grid by chance only (0.4 % of a step's width here).
  EXPECT_LT(gaussian_on_grid, gaussian_points / 50);
}

TEST(SensorModel, EdgePixelsDropOutWhileFlatInteriorsKeepTheirPoints) {
  SensorModel always = bareModel();
  always.edge_dropout = 1.0;
  const Cloud cloud = renderStep(always, 1);
  const Cloud published = renderStep(sensorModel(DepthSensor::kStructuredLight), 1);
  std::size_t edge_pixels = 0, published_lost = 0;
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) {
      const double d = distanceToEdge(col, row);
      const auto& p = cloud.at(col, row);
      if (d < 1.0) {  // next to the depth step: lost
        ASSERT_FALSE(valid(p)) << col << "," << row;
        ++edge_pixels;
        published_lost += !valid(published.at(col, row));
      } else if (d > 2.0 && col > 2 && col < 637 && row > 2 && row < 477) {
        ASSERT_TRUE(valid(p)) << col << "," << row;
        ASSERT_EQ(p.z, inForeground(col, row) ? kForegroundZ : kBackgroundZ);
      }
    }
  }
  EXPECT_GT(edge_pixels, 1000u);  // rings of 132 and 134 px squares
  // The published model loses about half of them (plus the shadow on the left).
  EXPECT_GT(published_lost, edge_pixels / 4);
  EXPECT_LT(published_lost, edge_pixels * 3 / 4);
  // And keeps the flat interiors away from the edge and the shadow.
  for (int row = 100; row < 380; ++row) {
    for (int col = 100; col < 540; ++col) {
      if (distanceToEdge(col, row) > 15.0) {
        ASSERT_TRUE(valid(published.at(col, row)));
      }
    }
  }
}

TEST(SensorModel, TimeOfFlightGivesPointsBetweenForegroundAndBackgroundOnlyAtEdges) {
  const Cloud cloud = renderStep(sensorModel(DepthSensor::kTimeOfFlight), 2);
  const Cloud gaussian = renderStep(SensorModel{}, 2);
  std::size_t between = 0, gaussian_between = 0;
  const auto isBetween = [](float z) {
    return z > kForegroundZ + 0.02f && z < kBackgroundZ - 0.02f;
  };
  for (int row = 2; row < 478; ++row) {
    for (int col = 2; col < 638; ++col) {
      const auto& p = cloud.at(col, row);
      gaussian_between += valid(gaussian.at(col, row)) && isBetween(gaussian.at(col, row).z);
      if (!valid(p) || !isBetween(p.z)) continue;
      ++between;
      // Only next to the depth step.
      ASSERT_LT(distanceToEdge(col, row), 1.0) << col << "," << row;
      // On its own pixel's ray.
      ASSERT_NEAR(p.x / p.z, (col - kCx) / kF, 1e-6);
    }
  }
  EXPECT_GT(between, 100u);
  EXPECT_EQ(gaussian_between, 0u);
}

TEST(SensorModel, ShadowsFallOnTheSideAwayFromTheProjector) {
  SensorModel shadows = bareModel();
  shadows.shadows = true;
  shadows.baseline = 0.075;
  const Cloud cloud = renderStep(shadows, 1);
  // The projector at +x sees the background through the foreground's left border 525 * 0.075 *
  // (1/0.8 - 1/1) = 9.8 px further left than the camera: that band is dark.
  std::size_t left_missing = 0, right_missing = 0;
  for (int row = 200; row < 280; ++row) {
    for (int col = 0; col < 640; ++col) {
      if (inForeground(col, row) || valid(cloud.at(col, row))) continue;
      (col < kCx ? left_missing : right_missing) += 1;
      ASSERT_LT(distanceToEdge(col, row), 11.0) << col << "," << row;
    }
  }
  EXPECT_GE(left_missing, 80u * 8u);
  EXPECT_EQ(right_missing, 0u);
}

TEST(SensorModel, SameSeedGivesTheSameCloudForEverySensor) {
  const DepthRenderer renderer(makeMug());
  const Eigen::Isometry3d pose = cameraFromObject(Eigen::Vector3d(1, 1, 0.5), 0.7, 0.1);
  for (DepthSensor kind : {DepthSensor::kKinectGaussian, DepthSensor::kStructuredLight,
                           DepthSensor::kActiveStereo, DepthSensor::kTimeOfFlight}) {
    const DepthNoiseModel noise{true, sensorModel(kind)};
    std::mt19937 a(9), b(9), c(10);
    const Cloud first = renderer.render(pose, noise, &a);
    const Cloud second = renderer.render(pose, noise, &b);
    const Cloud other = renderer.render(pose, noise, &c);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < first.size(); ++i) {
      ASSERT_EQ(valid(first[i]), valid(second[i])) << sensorName(kind) << " " << i;
      if (valid(first[i])) {
        ASSERT_EQ(first[i].z, second[i].z) << sensorName(kind);
      }
      differing +=
          valid(first[i]) != valid(other[i]) || (valid(first[i]) && first[i].z != other[i].z);
    }
    EXPECT_GT(differing, 100u) << sensorName(kind) << ": another seed, another cloud";
  }
}

// The message of the vdc::Error `action` throws ("" if none).
template <typename Action>
std::string errorOf(Action action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SensorModel, BadSettingsAreRefusedWithAClearError) {
  const DepthRenderer renderer(test::makeSquare(0.2f, 1.0f));
  std::mt19937 rng(1);
  const auto renderWith = [&](const SensorModel& m) {
    return [&renderer, &rng, m] {
      renderer.render(Eigen::Isometry3d::Identity(), DepthNoiseModel{true, m}, &rng);
    };
  };
  SensorModel m = sensorModel(DepthSensor::kStructuredLight);
  m.disparity_sigma_px = -0.1;
  EXPECT_NE(errorOf(renderWith(m)).find("disparity_sigma_px"), std::string::npos);
  m = sensorModel(DepthSensor::kTimeOfFlight);
  m.flying_pixel = 1.5;
  EXPECT_NE(errorOf(renderWith(m)).find("flying_pixel"), std::string::npos);
  m = sensorModel(DepthSensor::kStructuredLight);
  m.edge_dropout = std::nan("");
  EXPECT_NE(errorOf(renderWith(m)).find("edge_dropout"), std::string::npos);
  m = sensorModel(DepthSensor::kActiveStereo);
  m.disparity_focal_px = 0.0;
  EXPECT_NE(errorOf(renderWith(m)).find("disparity_focal_px"), std::string::npos);
  m = bareModel();
  m.shadows = true;
  EXPECT_NE(errorOf(renderWith(m)).find("baseline"), std::string::npos);
  m = bareModel();
  m.edge_band_px = -1;
  EXPECT_NE(errorOf(renderWith(m)).find("edge_band_px"), std::string::npos);
  EXPECT_NE(errorOf([] { parseDepthSensor("kinect"); }).find("structured_light|"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              std::mt19937 r(1);
              simulateSensor(SensorModel{}, CameraIntrinsics{}, std::vector<float>(10), {}, r);
            }).find("depth image has 10 pixels"),
            std::string::npos);
}

TEST(SensorModel, NamesRoundTrip) {
  for (DepthSensor kind : {DepthSensor::kKinectGaussian, DepthSensor::kStructuredLight,
                           DepthSensor::kActiveStereo, DepthSensor::kTimeOfFlight}) {
    EXPECT_EQ(parseDepthSensor(sensorName(kind)), kind);
    EXPECT_EQ(sensorModel(kind).kind, kind);
  }
}

}  // namespace
}  // namespace vdc
