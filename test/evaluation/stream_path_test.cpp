#include "view_direction_classification/evaluation/stream_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/camera.h"

namespace vdc {
namespace {

constexpr double kDegree = M_PI / 180.0;

std::vector<Eigen::Isometry3d> threeViews() {
  return {cameraFromObject(Eigen::Vector3d(1, 0, 0.5), 0.6, 0.0),
          cameraFromObject(Eigen::Vector3d(0, 1, 0.2), 0.6, 0.7),
          cameraFromObject(Eigen::Vector3d(-1, -0.3, -0.4), 0.5, -1.0)};
}

double rotationAngle(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::Quaterniond(a.linear()).angularDistance(Eigen::Quaterniond(b.linear()));
}

TEST(StreamPath, FramesComeAtTheRateAndStartAndEndDwellingAtTheFirstAndLastView) {
  const std::vector<Eigen::Isometry3d> views = threeViews();
  StreamPathSettings settings;
  settings.rate_hz = 15.0;
  settings.dwell_s = 1.0;
  const std::vector<StreamFrame> frames = streamPath(views, settings, 3);
  ASSERT_GT(frames.size(), 3u * 15u);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    EXPECT_NEAR(frames[k].time, static_cast<double>(k) / 15.0, 1e-9);
  }
  EXPECT_TRUE(frames.front().dwelling);
  EXPECT_EQ(frames.front().view, 0);
  EXPECT_TRUE(frames.front().camera_from_object.isApprox(views[0], 1e-9));
  EXPECT_TRUE(frames.back().dwelling);
  EXPECT_EQ(frames.back().view, 2);
  EXPECT_TRUE(frames.back().camera_from_object.isApprox(views[2], 1e-9));
}

TEST(StreamPath, DwellsAtEveryViewForTheDwellTime) {
  StreamPathSettings settings;
  settings.rate_hz = 20.0;
  settings.dwell_s = 2.0;
  const std::vector<Eigen::Isometry3d> views = threeViews();
  const std::vector<StreamFrame> frames = streamPath(views, settings, 1);
  std::vector<int> dwelling_frames(views.size(), 0);
  for (const StreamFrame& f : frames) {
    if (!f.dwelling) continue;
    ++dwelling_frames[f.view];
    EXPECT_TRUE(f.camera_from_object.isApprox(views[f.view], 1e-9)) << "frame at " << f.time;
  }
  // 2 s at 20 Hz: 40 frames, one more or less depending on where the ticks fall.
  for (const int count : dwelling_frames) EXPECT_NEAR(count, 40, 1);
}

TEST(StreamPath, ArcsTurnAtARateWithinTheSettingsAndAlwaysLookAtTheObject) {
  StreamPathSettings settings;
  settings.rate_hz = 30.0;
  settings.min_speed_deg_s = 10.0;
  settings.max_speed_deg_s = 30.0;
  settings.dwell_s = 0.5;
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {  // 20 arcs, each at its own drawn rate
    const std::vector<StreamFrame> frames = streamPath(threeViews(), settings, seed);
    int moving = 0;
    for (std::size_t k = 1; k < frames.size(); ++k) {
      const Eigen::Vector3d origin = frames[k].camera_from_object.translation();
      EXPECT_NEAR(origin.head<2>().norm(), 0.0, 1e-9) << "the optical axis misses the object";
      EXPECT_GT(origin.z(), 0.0);
      const double step =
          rotationAngle(frames[k - 1].camera_from_object, frames[k].camera_from_object);
      EXPECT_LE(step, 30.0 * kDegree / 30.0 + 1e-9) << "faster than 30 deg/s, seed " << seed;
      // Wholly inside one arc (both frames on the same arc) the step is at least 10 deg/s.
      if (!frames[k - 1].dwelling && !frames[k].dwelling && frames[k - 1].view == frames[k].view) {
        EXPECT_GE(step, 10.0 * kDegree / 30.0 - 1e-9) << "slower than 10 deg/s, seed " << seed;
        ++moving;
      }
    }
    EXPECT_GT(moving, 30);  // the arcs are long enough to be sampled (tens of degrees each)
  }
}

TEST(StreamPath, IsDeterministicInItsSeedAndTheSeedSetsTheArcRates) {
  const StreamPathSettings settings;
  const std::vector<StreamFrame> a = streamPath(threeViews(), settings, 5);
  const std::vector<StreamFrame> b = streamPath(threeViews(), settings, 5);
  const std::vector<StreamFrame> c = streamPath(threeViews(), settings, 6);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_TRUE(a[k].camera_from_object.isApprox(b[k].camera_from_object, 0.0));
  }
  bool differs = a.size() != c.size();  // other arc rates: other poses along the arcs
  for (std::size_t k = 0; k < std::min(a.size(), c.size()) && !differs; ++k) {
    differs = !a[k].camera_from_object.isApprox(c[k].camera_from_object, 1e-9);
  }
  EXPECT_TRUE(differs);
}

TEST(StreamPath, RefusesBadSettingsAndViewsThatDoNotLookAtTheObject) {
  StreamPathSettings bad;
  bad.rate_hz = 0.0;
  EXPECT_THROW(streamPath(threeViews(), bad, 1), Error);
  bad = StreamPathSettings{};
  bad.min_speed_deg_s = 40.0;  // above the maximum
  EXPECT_THROW(streamPath(threeViews(), bad, 1), Error);
  bad = StreamPathSettings{};
  bad.dwell_s = -1.0;
  EXPECT_THROW(streamPath(threeViews(), bad, 1), Error);
  EXPECT_THROW(streamPath({}, StreamPathSettings{}, 1), Error);
  std::vector<Eigen::Isometry3d> views = threeViews();
  views[1].translation().x() += 0.1;  // looks past the object
  EXPECT_THROW(streamPath(views, StreamPathSettings{}, 1), Error);
}

}  // namespace
}  // namespace vdc
