#include "view_direction_classification/visualisation/surface_splat_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

constexpr Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kYellow{255, 255, 0};
constexpr Rgb kNear{10, 10, 10}, kFar{200, 200, 200};

// Four points facing +x at (0, +-a, 0) and (0, 0, +-a): centroid 0, bounding radius a. Seen
// from +x (object +z up, +y to the right) in a 100 px image the scale is 0.45 * 100 / a px/m
// about the centre (50, 50), so they land at (95, 50), (5, 50), (50, 5) and (50, 95).
struct Scene {
  std::vector<Eigen::Vector3f> points{{0, 0.05f, 0}, {0, -0.05f, 0}, {0, 0, 0.05f}, {0, 0, -0.05f}};
  std::vector<Eigen::Vector3f> normals = std::vector<Eigen::Vector3f>(4, Eigen::Vector3f::UnitX());
  std::vector<Rgb> colours{kRed, kGreen, kBlue, kYellow};

  void add(const Eigen::Vector3f& point, const Eigen::Vector3f& normal, const Rgb& colour) {
    points.push_back(point);
    normals.push_back(normal);
    colours.push_back(colour);
  }
  RgbImage render(const SplatView& view) const {
    return renderSplats(points, normals, colours, view);
  }
};

SplatView fromPlusX() {
  SplatView view;
  view.direction = Eigen::Vector3d(2, 0, 0);  // any length
  view.size = 100;
  return view;
}

TEST(SurfaceSplatRenderer, APointLandsAtItsProjectedPixelInItsColour) {
  const SplatView view = fromPlusX();
  const RgbImage image = Scene().render(view);
  ASSERT_EQ(image.width, 100);
  ASSERT_EQ(image.height, 100);
  EXPECT_EQ(image.at(95, 50), kRed);     // +y: right
  EXPECT_EQ(image.at(5, 50), kGreen);    // -y: left
  EXPECT_EQ(image.at(50, 5), kBlue);     // +z: up
  EXPECT_EQ(image.at(50, 95), kYellow);  // -z: down
  // Discs of one point spacing (1.8 px here): the neighbours are drawn, 3 px away is not.
  EXPECT_EQ(image.at(94, 51), kRed);
  EXPECT_EQ(image.at(92, 50), view.background);
  EXPECT_EQ(image.at(50, 50), view.background);
  EXPECT_EQ(image.at(0, 0), view.background);
}

TEST(SurfaceSplatRenderer, TheNearerOfTwoPointsOnOnePixelWinsWhateverTheOrder) {
  for (const bool near_first : {true, false}) {
    Scene scene;
    // Both on the optical axis through the centre; +x is nearer a viewer on +x.
    const Eigen::Vector3f near(0.02f, 0, 0), far(-0.02f, 0, 0);
    if (near_first) {
      scene.add(near, Eigen::Vector3f::UnitX(), kNear);
      scene.add(far, Eigen::Vector3f::UnitX(), kFar);
    } else {
      scene.add(far, Eigen::Vector3f::UnitX(), kFar);
      scene.add(near, Eigen::Vector3f::UnitX(), kNear);
    }
    EXPECT_EQ(scene.render(fromPlusX()).at(50, 50), kNear) << "near first: " << near_first;
  }
}

TEST(SurfaceSplatRenderer, PointsFacingAwayAreNotDrawn) {
  Scene scene;
  scene.add({0, 0, 0}, -Eigen::Vector3f::UnitX(), kNear);
  const SplatView view = fromPlusX();
  EXPECT_EQ(scene.render(view).at(50, 50), view.background);
  // Seen from -x the four +x-facing points vanish and the centre one shows.
  SplatView behind = view;
  behind.direction = -Eigen::Vector3d::UnitX();
  const RgbImage image = scene.render(behind);
  EXPECT_EQ(image.at(50, 50), kNear);
  EXPECT_EQ(image.at(5, 50), behind.background);
  EXPECT_EQ(image.at(95, 50), behind.background);
}

TEST(SurfaceSplatRenderer, DiscsReachingPastTheImageEdgeAreClippedToIt) {
  SplatView view = fromPlusX();
  view.point_spacing = 0.05;  // discs of 45 px: the edge points' discs leave the image
  const RgbImage image = Scene().render(view);
  EXPECT_EQ(image.at(99, 50), kRed);
  EXPECT_EQ(image.at(0, 50), kGreen);
  EXPECT_EQ(image.at(50, 0), kBlue);
  EXPECT_EQ(image.at(50, 99), kYellow);
}

TEST(SurfaceSplatRenderer, NoPointsGiveTheBackgroundAndBadInputIsRefused) {
  const SplatView view = fromPlusX();
  const RgbImage empty = renderSplats({}, {}, {}, view);
  EXPECT_EQ(empty.pixels, RgbImage(100, 100, view.background).pixels);
  const Scene scene;
  EXPECT_THROW(renderSplats(scene.points, scene.normals, {kRed}, view), Error);
  SplatView no_direction = view;
  no_direction.direction = Eigen::Vector3d::Zero();
  EXPECT_THROW(scene.render(no_direction), Error);
  no_direction.direction = Eigen::Vector3d(std::nan(""), 0, 1);
  EXPECT_THROW(scene.render(no_direction), Error);
}

}  // namespace
}  // namespace vdc
