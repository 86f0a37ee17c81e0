#include "view_direction_classification/evaluation/patrol_truth.h"

#include <gtest/gtest.h>

#include <vector>

#include "view_direction_classification/evaluation/patrol_changes.h"
#include "view_direction_classification/evaluation/scene_generation.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

// The built-in mug's origin is its centre, this far above its bottom.
constexpr double kMugHalfHeight = 0.0475;

// An optical frame (z forward, x right, y down) at `eye` looking at `target`, z up in the world.
Eigen::Isometry3d lookingAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d forward = (target - eye).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  world_from_camera.linear().col(0) = right;
  world_from_camera.linear().col(1) = forward.cross(right);
  world_from_camera.linear().col(2) = forward;
  world_from_camera.translation() = eye;
  return world_from_camera;
}

// A mug taken from the middle of the default 1.2 x 0.8 m table; the truth of its empty place.
class TakenMugPlace : public ::testing::Test {
 protected:
  TakenMugPlace() {
    TableScene table;
    Eigen::Isometry3d world_from_mug = Eigen::Isometry3d::Identity();
    world_from_mug.translation() = Eigen::Vector3d(0.0, 0.0, kMugHalfHeight);
    table.known.push_back({"mug", {makeMug(), world_from_mug}});
    scene_ = patrolSceneOf(table);
    scene_.objects[0].present = false;
    present_ = presentScene(scene_, &ids_);
    place_ = {scene_.objects[0].id, "mug", world_from_mug, 0.0};
  }

  // Of the place, the fraction the view from `eye` sees, looking at the mug's centre shifted by
  // `aside`.
  double placeSeenFrom(const Eigen::Vector3d& eye,
                       const Eigen::Vector3d& aside = Eigen::Vector3d::Zero()) const {
    const Eigen::Isometry3d world_from_camera =
        lookingAt(eye, Eigen::Vector3d(0.0, 0.0, kMugHalfHeight) + aside);
    const PatrolTruthRenderer truths(scene_, present_, ids_, {place_});
    const PatrolTruth truth =
        truths.truth(TableSceneRenderer(present_).render(world_from_camera, DepthNoiseModel{false}),
                     world_from_camera);
    EXPECT_EQ(truth.vacated.size(), 1u);
    return truth.vacated.empty() ? -1.0 : truth.vacated[0].visible_fraction;
  }

  PatrolScene scene_;
  TableScene present_;
  std::vector<int> ids_;
  VacatedPlace place_;
};

TEST_F(TakenMugPlace, IsSeenFreeWhereTheTableShowsBehindIt) {
  EXPECT_GT(placeSeenFrom(Eigen::Vector3d(-0.5, 0.0, 0.5)), 0.95);
}

// From the table's height, beyond its edge, most rays through the place meet nothing: a depth
// camera returns no depth there, which shows free space no better than a dropout does.
TEST_F(TakenMugPlace, IsNotSeenWhereTheRaysThroughItMeetNothing) {
  EXPECT_LT(placeSeenFrom(Eigen::Vector3d(-1.5, 0.0, kMugHalfHeight)), 0.3);
}

// From 0.71 m, looking 46 cm to the mug's left: the place's centre falls about on the image's
// right border, so about half of it lies beyond the image. The part in the image shows the table
// behind it, and counted alone it would be seen whole.
TEST_F(TakenMugPlace, CountsThePartBeyondTheImageBorderAsUnseen) {
  const double seen =
      placeSeenFrom(Eigen::Vector3d(-0.5, 0.0, 0.5), Eigen::Vector3d(0.0, 0.46, 0.0));
  EXPECT_GT(seen, 0.35);
  EXPECT_LT(seen, 0.65);
}

TEST_F(TakenMugPlace, IsNotSeenWhenTheCameraLooksAway) {
  const Eigen::Isometry3d away =
      lookingAt(Eigen::Vector3d(-0.5, 0.0, 0.5), Eigen::Vector3d(-1.5, 0.0, 0.5));
  const PatrolTruthRenderer truths(scene_, present_, ids_, {place_});
  const PatrolTruth truth =
      truths.truth(TableSceneRenderer(present_).render(away, DepthNoiseModel{false}), away);
  ASSERT_EQ(truth.vacated.size(), 1u);
  EXPECT_EQ(truth.vacated[0].visible_fraction, 0.0);
}

}  // namespace
}  // namespace vdc
