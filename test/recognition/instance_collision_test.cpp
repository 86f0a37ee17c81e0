// Whether identifications of two models would stand inside each other (InstanceCollision):
// objects side by side or touching do not, a model placed into another does.
#include "view_direction_classification/recognition/instance_collision.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "support/mug_scene.h"
#include "support/quick_mug_model.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/geometry/scene.h"
#include "view_direction_classification/geometry/surface_sampling.h"
#include "view_direction_classification/recognition/instance_overlap.h"
#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc {
namespace {

using test::kMugPosition;
using test::placed;

constexpr double kDepth = 0.01;  // the scene estimator's
constexpr int kMug = 0, kBlock = 1;
const Eigen::Vector3d kBlockSize(0.16, 0.12, 0.14);  // a box the mug fits in with 2 cm to spare

// A solid box's bundle (origin at its base's centre), sampled every `spacing` [m]: collision
// needs only its surface samples, their normals and bounds.
std::shared_ptr<const ModelBundle> boxBundle(const Eigen::Vector3d& size, double spacing) {
  const TriangleMesh mesh = makeBoxMesh(size);
  const SurfaceSamples samples = sampleSurface(mesh, spacing, 1);
  auto bundle = std::make_shared<ModelBundle>();
  bundle->surface_points = samples.points;
  bundle->surface_normals = samples.normals;
  const Eigen::AlignedBox3f bounds = mesh.bounds();
  bundle->bounds = Eigen::AlignedBox3d(bounds.min().cast<double>(), bounds.max().cast<double>());
  return bundle;
}

class InstanceCollisionTest : public ::testing::Test {
 protected:
  InstanceCollisionTest()
      : library_({{"mug", test::quickMugModel()}, {"block", boxBundle(kBlockSize, 0.004)}}),
        collision_(library_),
        mug_(library_.models()[kMug].bundle->bounds) {}

  // The block's pose with its centre at `centre` (makeBoxMesh's origin is its base's centre).
  static Eigen::Isometry3d blockCentredAt(const Eigen::Vector3d& centre) {
    return placed(centre - Eigen::Vector3d(0.0, 0.0, 0.5 * kBlockSize.z()));
  }
  // The block beside the mug's body along +y, level with the mug's middle, `gap` [m] from
  // touching it (negative: pushed in).
  double blockBeside(double gap) const {
    const Eigen::Vector3d mug_centre = placed(kMugPosition) * mug_.center();
    const Eigen::Vector3d block_centre =
        mug_centre + Eigen::Vector3d(0.0, 0.5 * (mug_.sizes().y() + kBlockSize.y()) + gap, 0.0);
    return collision_.penetration(kMug, placed(kMugPosition), kBlock, blockCentredAt(block_centre),
                                  kDepth);
  }
  double twoBlocks(const Eigen::Vector3d& shift) const {
    return collision_.penetration(kBlock, blockCentredAt(kMugPosition), kBlock,
                                  blockCentredAt(kMugPosition + shift), kDepth);
  }

  ModelLibrary library_;
  InstanceCollision collision_;
  Eigen::AlignedBox3d mug_;  // the mug's bounds, object frame
};

TEST_F(InstanceCollisionTest, ObjectsSideBySideOrTouchingDoNotCollide) {
  EXPECT_EQ(blockBeside(0.02), 0.0);
  EXPECT_EQ(blockBeside(0.0), 0.0);
  EXPECT_EQ(twoBlocks(Eigen::Vector3d(kBlockSize.x(), 0.0, 0.0)), 0.0);
  EXPECT_EQ(twoBlocks(Eigen::Vector3d(0.5, 0.0, 0.0)), 0.0);
  // A few millimetres into each other, what a pose error makes of two objects that touch:
  // nothing lies a centimetre deep inside the other.
  EXPECT_EQ(blockBeside(-0.004), 0.0);
  EXPECT_EQ(twoBlocks(Eigen::Vector3d(kBlockSize.x() - 0.004, 0.0, 0.0)), 0.0);
}

TEST_F(InstanceCollisionTest, AModelPushedIntoAnotherCollides) {
  // The mug inside the box, with 2 cm to spare on every side: all of it.
  EXPECT_GT(blockBeside(-0.5 * (mug_.sizes().y() + kBlockSize.y())), 0.9);
  // Half the mug's width into the box's side: the mug is hollow, so the box's samples in its
  // cavity are outside it, but the part of the mug inside the box is not.
  EXPECT_GT(blockBeside(-0.5 * mug_.sizes().y()), 0.1);
  EXPECT_GT(twoBlocks(Eigen::Vector3d(0.5 * kBlockSize.x(), 0.0, 0.0)), 0.1);
  EXPECT_GT(twoBlocks(Eigen::Vector3d(0.5 * kBlockSize.x(), 0.5 * kBlockSize.y(), 0.0)), 0.1);
}

TEST_F(InstanceCollisionTest, ThePenetrationGrowsAsTheMugIsPushedFurtherIntoTheBox) {
  double previous = 0.0;
  for (double in = 0.0; in <= 0.5 * (mug_.sizes().y() + kBlockSize.y()); in += 0.01) {
    const double shared = blockBeside(-in);
    EXPECT_GE(shared, previous) << "at " << in << " m";
    previous = shared;
  }
  EXPECT_GT(previous, 0.9);
}

TEST_F(InstanceCollisionTest, TheInstanceAnotherModelWouldStandInIsFoundUnlessGoneOrOfItsModel) {
  // The mug identified on a rendered table by a scene estimator of the mug alone: its instance,
  // model 0 of this library too.
  SceneEstimator estimator(ModelLibrary({{"mug", test::quickMugModel()}}), {});
  Scene scene = test::mugScene(true, false);
  const Eigen::Isometry3d world_from_camera =
      test::cameraFromWorld(Eigen::Vector3d(1.0, 0.2, 0.9).normalized(), 0.7).inverse();
  std::mt19937 rng(1);
  estimator.update(DepthRenderer(sceneMesh(scene))
                       .render(world_from_camera.inverse(), DepthNoiseModel{true}, &rng),
                   world_from_camera, 0.0);
  ASSERT_EQ(estimator.instances().size(), 1u);
  // Marked gone by hand below, as two frames that show its place free would.
  std::vector<ObjectInstance>& instances =
      const_cast<std::vector<ObjectInstance>&>(estimator.instances());
  const Eigen::Isometry3d mug = *believedPose(*instances.front().estimator);

  // The box around the mug, then beside it.
  const Eigen::Isometry3d block_in_mug = blockCentredAt(mug * mug_.center());
  EXPECT_EQ(collision_.collidingInstance(instances, kBlock, block_in_mug, kDepth, 0.1), 0);
  // Beside it, nothing; its own model is the overlap rule's (InstanceOverlap), not this one's.
  Eigen::Isometry3d block_beside = block_in_mug;
  block_beside.translation().y() += 0.2;
  EXPECT_EQ(collision_.collidingInstance(instances, kBlock, block_beside, kDepth, 0.1), -1);
  EXPECT_EQ(collision_.collidingInstance(instances, kMug, block_in_mug, kDepth, 0.1), -1);
  // A gone instance stands nowhere.
  instances.front().presence.state = InstanceState::kGone;
  EXPECT_EQ(collision_.collidingInstance(instances, kBlock, block_in_mug, kDepth, 0.1), -1);
}

// A one-sided plate 14 cm square at z = 0, outward +z: what lies under it is inside it, like the
// space behind a cow's ear or hoof as its nearest samples tell it.
std::shared_ptr<const ModelBundle> plateBundle() {
  auto bundle = std::make_shared<ModelBundle>();
  for (double x = -0.07; x <= 0.0701; x += 0.004) {
    for (double y = -0.07; y <= 0.0701; y += 0.004) {
      bundle->surface_points.emplace_back(x, y, 0.0);
      bundle->surface_normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
  }
  bundle->bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-0.07, -0.07, -0.001),
                                       Eigen::Vector3d(0.07, 0.07, 0.001));
  return bundle;
}

// Inside is told only within 37 degrees of the nearest sample's inward normal. A cube 1.5-2.5 cm
// under the plate's middle is inside it; the same cube 2.5-3.5 cm beside its edge lies just as
// far behind the edge samples' tangent plane, but off to the side, 45 degrees or more from their
// normal: outside. (By the tangent plane alone it would count as wholly inside.)
TEST(InstanceCollisionCone, APointBesideAnEdgeBehindItsTangentPlaneIsNotInside) {
  constexpr int kPlate = 0, kCube = 1;
  const ModelLibrary library(
      {{"plate", plateBundle()}, {"cube", boxBundle(Eigen::Vector3d::Constant(0.01), 0.002)}});
  const InstanceCollision collision(library);
  const Eigen::Isometry3d plate = Eigen::Isometry3d::Identity();
  EXPECT_GT(collision.penetration(kCube, placed(Eigen::Vector3d(0.0, 0.0, -0.025)), kPlate, plate,
                                  kDepth),
            0.9);
  EXPECT_EQ(collision.penetration(kCube, placed(Eigen::Vector3d(0.10, 0.0, -0.025)), kPlate, plate,
                                  kDepth),
            0.0);
}

}  // namespace
}  // namespace vdc
