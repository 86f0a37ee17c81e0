#include "explained_pieces.h"

#include <gtest/gtest.h>

#include <vector>

#include "support/quick_mug_model.h"

namespace vdc {
namespace {

// Pieces of the mug's surface samples (its body, its handle on +x), placed in the fixed frame,
// and a camera frame for them.
// [m, object frame] Beyond this x the samples are the handle's (the body's radius is 4 cm).
constexpr float kHandle = 0.045f;

class ExplainedPiecesTest : public ::testing::Test {
 protected:
  ExplainedPiecesTest() : bundle_(test::quickMugModel()), explanation_(*bundle_) {
    world_from_object_ =
        Eigen::Translation3d(0.5, 0.1, 0.7) * Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ());
    camera_from_world_ =
        Eigen::Translation3d(-0.5, 0.0, 0.8) * Eigen::AngleAxisd(2.5, Eigen::Vector3d::UnitX());
  }

  struct Piece {
    pcl::PointCloud<pcl::PointXYZ> points;
    std::vector<Eigen::Vector3f> points_world;
    PieceView view() const { return {&points, &points_world}; }
  };

  // The samples whose object-frame x is in [low, high), shifted by `offset` [m, fixed frame].
  Piece samples(float low, float high, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
    Piece piece;
    for (const Eigen::Vector3f& p : bundle_->surface_points) {
      if (p.x() < low || p.x() >= high) continue;
      const Eigen::Vector3d world = world_from_object_ * p.cast<double>() + offset;
      piece.points_world.push_back(world.cast<float>());
      const Eigen::Vector3f camera = (camera_from_world_ * world).cast<float>();
      piece.points.push_back(pcl::PointXYZ(camera.x(), camera.y(), camera.z()));
    }
    return piece;
  }

  std::shared_ptr<const ModelBundle> bundle_;
  InstanceExplanation explanation_;
  Eigen::Isometry3d world_from_object_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d camera_from_world_ = Eigen::Isometry3d::Identity();
};

TEST_F(ExplainedPiecesTest, ThePiecesThePoseExplainsJoinAndTheOthersDoNot) {
  const Piece body = samples(-1.0f, kHandle);
  const Piece handle = samples(kHandle, 1.0f);
  const Piece elsewhere = samples(kHandle, 1.0f, Eigen::Vector3d(0.0, 0.2, 0.0));
  ASSERT_GT(body.points.size(), 50u);
  ASSERT_GT(handle.points.size(), 50u);
  int joined = -1;
  const pcl::PointCloud<pcl::PointXYZ> object =
      withExplainedPieces(body.points, {elsewhere.view(), handle.view()}, explanation_,
                          world_from_object_, 0.005, 0.8, &joined);
  EXPECT_EQ(joined, 1);
  ASSERT_EQ(object.size(), body.points.size() + handle.points.size());
  // The piece first, then its part, as they were (camera frame).
  EXPECT_EQ(object[0].getVector3fMap(), body.points[0].getVector3fMap());
  EXPECT_EQ(object[body.points.size()].getVector3fMap(), handle.points[0].getVector3fMap());
}

TEST_F(ExplainedPiecesTest, NothingJoinsAPoseThatExplainsNoOtherPiece) {
  const Piece body = samples(-1.0f, kHandle);
  const Piece handle = samples(kHandle, 1.0f);
  // The pose turned half a turn about the mug's axis: its body is where it was, its handle not.
  const Eigen::Isometry3d turned =
      world_from_object_ * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ());
  int joined = -1;
  const pcl::PointCloud<pcl::PointXYZ> object =
      withExplainedPieces(body.points, {handle.view()}, explanation_, turned, 0.005, 0.8, &joined);
  EXPECT_EQ(joined, 0);
  EXPECT_EQ(object.size(), body.points.size());
  EXPECT_EQ(
      withExplainedPieces(body.points, {}, explanation_, world_from_object_, 0.005, 0.8, &joined)
          .size(),
      body.points.size());
  EXPECT_EQ(joined, 0);
}

TEST_F(ExplainedPiecesTest, APartNeedsAtLeastTheMinimumFractionOfItsPointsOnTheSurface) {
  const Piece handle = samples(kHandle, 1.0f);
  const Piece away = samples(kHandle, 1.0f, Eigen::Vector3d(0.0, 0.2, 0.0));
  // Every handle point, then as many 20 cm away: half of them on the placed model's surface.
  std::vector<Eigen::Vector3f> half = handle.points_world;
  half.insert(half.end(), away.points_world.begin(), away.points_world.end());
  EXPECT_DOUBLE_EQ(explanation_.explainedFraction(half, world_from_object_, 0.005), 0.5);
  EXPECT_TRUE(explanation_.explainsPart(half, world_from_object_, 0.005, 0.5));
  EXPECT_FALSE(explanation_.explainsPart(half, world_from_object_, 0.005, 0.6));
  EXPECT_FALSE(explanation_.explainsPart({}, world_from_object_, 0.005, 0.1));
}

}  // namespace
}  // namespace vdc
