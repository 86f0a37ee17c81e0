#include "view_direction_classification/bop/bop_vsd.h"

#include <gtest/gtest.h>

#include <vector>

#include "view_direction_classification/geometry/primitive_meshes.h"

namespace vdc {
namespace {

// A 100 x 100 x 40 mm box seen straight along its z axis, 500 mm from the camera: only its
// front face (z = 480 mm) shows, about 208 pixels wide (a long focal length keeps the pixel
// quantisation of the areas below 1 %).
struct BoxView {
  DepthRenderer renderer{makeBoxMesh({0.1, 0.1, 0.04}),
                         CameraIntrinsics{640, 480, 1000, 1000, 319.5, 239.5}};
  BopPose truth{Eigen::Matrix3d::Identity(), {0, 0, 500}};
  BopDepthImage image = quantiseDepth(
      renderer.renderDepth(Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.5))), 640, 480, 0.1);
};

TEST(BopVsd, TruePoseHasNoDiscrepancy) {
  const BoxView view;
  const auto errors =
      visibleSurfaceDiscrepancy(view.truth, view.truth, view.renderer, view.image, 0.1, {1, 30});
  EXPECT_EQ(errors, (std::vector<double>{0.0, 0.0}));
}

TEST(BopVsd, PoseBehindTheTruthCostsItsDepthOrItsMissingArea) {
  const BoxView view;
  // 20 mm further: the estimate's face is hidden behind the truth's (more than delta behind the
  // image), counted visible only where the truth is; they differ by 20 mm everywhere.
  const BopPose behind{Eigen::Matrix3d::Identity(), {0, 0, 520}};
  const auto errors =
      visibleSurfaceDiscrepancy(behind, view.truth, view.renderer, view.image, 0.1, {10, 30});
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0], 1.0);  // tau 10 mm < 20 mm: every pixel of the union costs
  // tau 30 mm: only the truth's pixels the smaller estimate misses: 1 - (480 / 500)^2.
  EXPECT_NEAR(errors[1], 1.0 - (480.0 / 500.0) * (480.0 / 500.0), 0.01);
}

TEST(BopVsd, PoseElsewhereIsAllDiscrepancy) {
  const BoxView view;
  const BopPose aside{Eigen::Matrix3d::Identity(), {200, 0, 500}};
  const auto errors =
      visibleSurfaceDiscrepancy(aside, view.truth, view.renderer, view.image, 0.1, {100});
  EXPECT_EQ(errors, std::vector<double>{1.0});
}

TEST(BopVsd, ThresholdsAreBops) {
  const auto taus = vsdTaus(200);
  ASSERT_EQ(taus.size(), 10u);
  EXPECT_NEAR(taus.front(), 10, 1e-12);
  EXPECT_NEAR(taus.back(), 100, 1e-12);
  EXPECT_NEAR(vsdCorrectThresholds().back(), 0.5, 1e-12);
}

}  // namespace
}  // namespace vdc
