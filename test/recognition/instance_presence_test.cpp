// Change in the scene's memory (doc/method.md section 13, "Change"): a mug taken away from a
// rendered table is marked gone only after its place was seen free in absent_views frames, not
// while it is hidden or out of view, and a mug moved elsewhere keeps its instance.
#include "view_direction_classification/recognition/instance_presence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "support/mug_scene.h"
#include "support/quick_mug_model.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/estimation/verification_scene.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/recognition/scene_estimator.h"
#include "view_direction_classification/scene/scene_segmentation.h"

namespace vdc {
namespace {

using test::kMugPosition;
using test::placed;

const Eigen::Isometry3d kMugAtA = placed(kMugPosition, 0.7);
// 30 cm from A, turned: where the mug is put after it was taken from A.
const Eigen::Isometry3d kMugAtB = placed(kMugPosition + Eigen::Vector3d(0.0, 0.3, 0.0), -0.8);
// A wall-like box 12 cm on A's -y side, 30 cm tall: it hides A from a camera on that side.
const Eigen::Isometry3d kScreen =
    placed(Eigen::Vector3d(kMugPosition.x(), kMugPosition.y() - 0.12, test::tableTop()));

// A table with a 25 cm cylinder (too large to be a mug; the table is centred under it) and
// `parts` on it: a mug where there is one, a screen.
Scene tableWith(const std::vector<ScenePart>& parts) {
  Scene scene;
  scene.object = {makeCylinderMesh(0.03, 0.25),
                  placed(Eigen::Vector3d(0.15, -0.05, test::tableTop()))};
  scene.table_size = Eigen::Vector2d(1.4, 1.0);
  scene.distractors = parts;
  return scene;
}

ScenePart mugAt(const Eigen::Isometry3d& pose) { return {makeMug(), pose}; }
ScenePart screen() { return {makeBoxMesh(Eigen::Vector3d(0.3, 0.03, 0.3)), kScreen}; }

// The camera `distance` from `target`, looking at it from `direction` (fixed frame).
Eigen::Isometry3d worldFromCamera(const Eigen::Vector3d& direction,
                                  const Eigen::Vector3d& target = kMugPosition,
                                  double distance = 0.7) {
  return test::cameraFromWorld(direction.normalized(), distance, target).inverse();
}

pcl::PointCloud<pcl::PointXYZ> render(const Scene& scene,
                                      const Eigen::Isometry3d& world_from_camera,
                                      std::uint32_t seed) {
  const DepthRenderer renderer(sceneMesh(scene));
  std::mt19937 rng(seed);
  return renderer.render(world_from_camera.inverse(), DepthNoiseModel{true}, &rng);
}

// Views of A from different sides, as a camera moving round the table takes them.
const Eigen::Vector3d kView0(1.0, 0.2, 0.9), kView1(0.6, 0.8, 0.9), kView2(-0.2, 1.0, 0.8),
    kView3(0.9, -0.4, 0.9);

SceneEstimator makeEstimator(SceneEstimatorParameters parameters = {}) {
  return SceneEstimator(ModelLibrary({{"mug", test::quickMugModel()}}), parameters);
}

// The mug identified at A from kView0 (time 0): the estimator's one instance.
const ObjectInstance& mugFoundAtA(SceneEstimator& estimator) {
  const Eigen::Isometry3d pose = worldFromCamera(kView0);
  estimator.update(render(tableWith({mugAt(kMugAtA)}), pose, 1), pose, 0.0);
  EXPECT_EQ(estimator.instances().size(), 1u);
  if (estimator.instances().size() != 1u) throw Error("the mug at A was not identified");
  return estimator.instances().front();
}

SceneUpdate look(SceneEstimator& estimator, const Scene& scene, const Eigen::Isometry3d& pose,
                 double time) {
  return estimator.update(render(scene, pose, static_cast<std::uint32_t>(100 + time)), pose, time);
}

std::string describe(const ObjectInstance& instance) {
  const PresenceCheck& check = instance.presence.last_check;
  return instance.name + ": absent frames " + std::to_string(instance.presence.absent_frames) +
         ", last check predicted " + std::to_string(check.predicted) + " seen " +
         std::to_string(check.seen) + " free " + std::to_string(check.free) + " hidden " +
         std::to_string(check.hidden);
}

// The mug found at A, taken away and its place seen free from kView1 and kView2 (times 1, 2):
// gone. Returns its id.
int mugGoneFromA(SceneEstimator& estimator) {
  const int id = mugFoundAtA(estimator).id;
  const Scene empty = tableWith({});
  look(estimator, empty, worldFromCamera(kView1), 1.0);
  look(estimator, empty, worldFromCamera(kView2), 2.0);
  const ObjectInstance* mug = estimator.instance(id);
  EXPECT_NE(mug, nullptr);
  if (mug == nullptr || mug->presence.state != InstanceState::kGone) {
    throw Error("the mug taken from A is not gone: " + (mug ? describe(*mug) : "forgotten"));
  }
  return id;
}

TEST(InstancePresence, ARemovedMugIsGoneOnlyAfterItsPlaceWasSeenFreeInAbsentViewsFrames) {
  SceneEstimatorParameters parameters;
  parameters.forget_gone_after = 5.0;
  SceneEstimator estimator = makeEstimator(parameters);
  const int id = mugFoundAtA(estimator).id;
  const Scene empty = tableWith({});

  // One frame of free space is not enough: still present, still reported.
  SceneUpdate update = look(estimator, empty, worldFromCamera(kView1), 1.0);
  ASSERT_TRUE(update.segmented);
  const ObjectInstance* mug = estimator.instance(id);
  ASSERT_NE(mug, nullptr);
  EXPECT_EQ(mug->presence.last_check.evidence, PresenceEvidence::kAbsent) << describe(*mug);
  EXPECT_EQ(mug->presence.absent_frames, 1) << describe(*mug);
  EXPECT_EQ(mug->presence.state, InstanceState::kPresent);
  EXPECT_TRUE(estimator.confirmed(*mug));
  EXPECT_TRUE(update.gone.empty());

  // The second, from another side: gone, kept with its state, no longer confirmed.
  update = look(estimator, empty, worldFromCamera(kView2), 2.0);
  mug = estimator.instance(id);
  ASSERT_NE(mug, nullptr);
  EXPECT_EQ(mug->presence.state, InstanceState::kGone) << describe(*mug);
  ASSERT_TRUE(mug->presence.gone_since.has_value());
  EXPECT_EQ(*mug->presence.gone_since, 2.0);
  EXPECT_FALSE(estimator.confirmed(*mug));
  EXPECT_TRUE(estimator.identified(*mug));
  EXPECT_EQ(update.gone, std::vector<int>{id});

  // Forgotten once forget_gone_after (5 s) has passed since, not before.
  update = look(estimator, empty, worldFromCamera(kView3), 4.0);
  EXPECT_NE(estimator.instance(id), nullptr);
  EXPECT_TRUE(update.forgotten.empty());
  update = look(estimator, empty, worldFromCamera(kView0), 8.0);
  EXPECT_EQ(estimator.instance(id), nullptr);
  EXPECT_EQ(update.forgotten, std::vector<int>{id});
}

// A gone instance takes no candidate by where it was: a box put down where the mug was taken from
// is tried as itself, and the mug's belief is not fed the box's points.
TEST(InstancePresence, ABoxPutWhereAGoneMugStoodIsNotTakenForTheMug) {
  SceneEstimator estimator = makeEstimator();
  const int id = mugGoneFromA(estimator);
  const ObjectInstance* mug = estimator.instance(id);
  const int frames_seen = mug->frames_seen;

  const ScenePart box{
      makeBoxMesh(Eigen::Vector3d(0.08, 0.07, 0.09)),
      placed(Eigen::Vector3d(kMugPosition.x(), kMugPosition.y(), test::tableTop()))};
  const SceneUpdate update = look(estimator, tableWith({box}), worldFromCamera(kView3), 3.0);
  ASSERT_TRUE(update.segmented);
  bool box_seen = false;
  for (const CandidateOutcome& candidate : update.candidates) {
    if ((candidate.centroid_world - kMugPosition).head<2>().norm() > 0.05) continue;
    box_seen = true;
    EXPECT_NE(candidate.instance, id) << candidate.note;
  }
  EXPECT_TRUE(box_seen);
  mug = estimator.instance(id);
  ASSERT_NE(mug, nullptr);
  EXPECT_EQ(mug->presence.state, InstanceState::kGone) << describe(*mug);
  EXPECT_EQ(mug->frames_seen, frames_seen);
}

TEST(InstancePresence, AMugHiddenBehindAnotherObjectIsNotGone) {
  SceneEstimator estimator = makeEstimator();
  const Eigen::Isometry3d start = worldFromCamera(kView0);
  estimator.update(render(tableWith({mugAt(kMugAtA), screen()}), start, 1), start, 0.0);
  ASSERT_EQ(estimator.instances().size(), 1u);
  const int id = estimator.instances().front().id;
  // Taken away, but the screen stands between A and the camera on its side.
  const Scene behind_screen = tableWith({screen()});
  int t = 1;
  for (const Eigen::Vector3d& side : {Eigen::Vector3d(0.2, -1.0, 0.5), {-0.2, -1.0, 0.45}}) {
    look(estimator, behind_screen, worldFromCamera(side), t++);
    const ObjectInstance* mug = estimator.instance(id);
    ASSERT_NE(mug, nullptr);
    const PresenceCheck& check = mug->presence.last_check;
    // Its place is in the image, and hidden: no evidence either way.
    EXPECT_GT(check.hidden, check.predicted / 2) << describe(*mug);
    EXPECT_EQ(check.evidence, PresenceEvidence::kNone) << describe(*mug);
    EXPECT_EQ(mug->presence.absent_frames, 0) << describe(*mug);
    EXPECT_EQ(mug->presence.state, InstanceState::kPresent);
    EXPECT_TRUE(estimator.confirmed(*mug));
  }
}

TEST(InstancePresence, AMugOutOfTheCameraViewIsNotGone) {
  SceneEstimator estimator = makeEstimator();
  const int id = mugFoundAtA(estimator).id;
  // Taken away while the camera looks at the table 55 cm to its side: A is 38 degrees off the
  // optical axis, past the image's 31.
  const Scene empty = tableWith({});
  const Eigen::Vector3d aside = kMugPosition + Eigen::Vector3d(0.0, 0.55, 0.0);
  int t = 1;
  for (const Eigen::Vector3d& side : {Eigen::Vector3d(1.0, 0.0, 0.9), {1.0, 0.1, 0.8}}) {
    look(estimator, empty, worldFromCamera(side, aside), t++);
    const ObjectInstance* mug = estimator.instance(id);
    ASSERT_NE(mug, nullptr);
    const PresenceCheck& check = mug->presence.last_check;
    EXPECT_GT(check.predicted, 0) << "A is in front of the camera, outside its image";
    EXPECT_EQ(check.evidence, PresenceEvidence::kNone) << describe(*mug);
    EXPECT_EQ(mug->presence.absent_frames, 0) << describe(*mug);
    EXPECT_EQ(mug->presence.state, InstanceState::kPresent);
  }
}

TEST(InstancePresence, AMugMovedThirtyCentimetresKeepsItsInstance) {
  SceneEstimator estimator = makeEstimator();
  const ObjectInstance& found = mugFoundAtA(estimator);
  const int id = found.id;
  const std::string name = found.name;
  // Taken from A and put down at B, turned; the camera sees both places.
  const Eigen::Vector3d between = kMugPosition + Eigen::Vector3d(0.0, 0.15, 0.0);
  const SceneUpdate update =
      look(estimator, tableWith({mugAt(kMugAtB)}),
           worldFromCamera(Eigen::Vector3d(1.0, 0.1, 0.9), between, 0.8), 1.0);
  ASSERT_EQ(estimator.instances().size(), 1u) << "the moved mug became a second instance";
  const ObjectInstance& mug = estimator.instances().front();
  EXPECT_EQ(mug.id, id);
  EXPECT_EQ(mug.name, name);
  EXPECT_EQ(mug.presence.state, InstanceState::kPresent);
  EXPECT_EQ(mug.presence.absent_frames, 0);
  EXPECT_TRUE(estimator.confirmed(mug));
  const auto position = mug.estimator->positionEstimate();
  ASSERT_TRUE(position.has_value());
  EXPECT_LT((*position - kMugAtB.translation()).norm(), 0.02);
  // Its belief starts from the view at B: the mug may have been turned on the way.
  EXPECT_EQ(mug.estimator->viewsFused(), 1);
  int moved = 0;
  for (const CandidateOutcome& candidate : update.candidates) moved += candidate.moved ? 1 : 0;
  EXPECT_EQ(moved, 1);
}

// The same move with the segmentation over-splitting on purpose: at B the mug is found from its
// pieces together, and the note that reports the piece says the mug moved, not only that pieces
// were joined (the node logs a moved candidate's note).
TEST(InstancePresence, AMovedMugFoundFromItsPiecesIsReportedMoved) {
  SceneEstimatorParameters parameters;
  parameters.segmentation.concavity_tolerance_deg = 0.5;
  parameters.segmentation.min_part_fraction = 0.02;
  parameters.segmentation.supervoxel_seed = 0.01;
  SceneEstimator estimator = makeEstimator(parameters);
  const std::string name = mugFoundAtA(estimator).name;
  const Eigen::Vector3d between = kMugPosition + Eigen::Vector3d(0.0, 0.15, 0.0);
  const SceneUpdate update =
      look(estimator, tableWith({mugAt(kMugAtB)}),
           worldFromCamera(Eigen::Vector3d(1.0, 0.1, 0.9), between, 0.8), 1.0);
  ASSERT_EQ(estimator.instances().size(), 1u) << "the moved mug became a second instance";
  int moved = 0;
  for (const CandidateOutcome& candidate : update.candidates) {
    if (!candidate.moved) continue;
    ++moved;
    EXPECT_NE(candidate.note.find(name + " moved here"), std::string::npos) << candidate.note;
    EXPECT_NE(candidate.note.find("piece(s) beside it"), std::string::npos) << candidate.note;
  }
  EXPECT_EQ(moved, 1);
}

// Taken away, and a small box put down 4 cm from where it stood: the box's candidate lies within
// association_distance of the mug's, but the mug's place shows free. The box is not taken for
// the mug (nor for a part of it), and does not keep it present.
TEST(InstancePresence, SomethingElseBesideARemovedMugDoesNotKeepItPresent) {
  SceneEstimator estimator = makeEstimator();
  const int id = mugFoundAtA(estimator).id;
  const ScenePart box{makeBoxMesh(Eigen::Vector3d(0.03, 0.03, 0.03)),
                      placed(kMugPosition + Eigen::Vector3d(0.04, 0.0, -0.0475))};
  const Scene box_only = tableWith({box});
  SceneUpdate update = look(estimator, box_only, worldFromCamera(kView1), 1.0);
  bool box_associated = false;
  for (const CandidateOutcome& candidate : update.candidates) {
    box_associated = box_associated || candidate.instance == id;
  }
  update = look(estimator, box_only, worldFromCamera(kView2), 2.0);
  const ObjectInstance* mug = estimator.instance(id);
  ASSERT_NE(mug, nullptr);
  EXPECT_EQ(mug->presence.state, InstanceState::kGone) << describe(*mug);
  EXPECT_FALSE(estimator.confirmed(*mug));
  EXPECT_FALSE(box_associated) << "the box was taken for (a part of) the mug";
}

// Gone is not forgotten (forget_gone_after 0): put down elsewhere later, it is known again.
TEST(InstancePresence, AGoneMugPutDownElsewhereLaterIsItsInstanceAgain) {
  SceneEstimator estimator = makeEstimator();
  const int id = mugGoneFromA(estimator);
  const Eigen::Vector3d between = kMugPosition + Eigen::Vector3d(0.0, 0.15, 0.0);
  look(estimator, tableWith({mugAt(kMugAtB)}),
       worldFromCamera(Eigen::Vector3d(1.0, 0.1, 0.9), between, 0.8), 30.0);
  ASSERT_EQ(estimator.instances().size(), 1u) << "the mug came back as a second instance";
  const ObjectInstance& mug = estimator.instances().front();
  EXPECT_EQ(mug.id, id);
  EXPECT_EQ(mug.presence.state, InstanceState::kPresent);
  EXPECT_FALSE(mug.presence.gone_since.has_value());
  EXPECT_TRUE(estimator.confirmed(mug));
}

TEST(InstancePresence, AMugMovedTenCentimetresIsFollowedNotDuplicated) {
  SceneEstimator estimator = makeEstimator();
  const int id = mugFoundAtA(estimator).id;
  // Beyond association_distance (5 cm), its old place partly free.
  const Eigen::Isometry3d nearby = placed(kMugPosition + Eigen::Vector3d(-0.07, 0.07, 0.0), 0.7);
  look(estimator, tableWith({mugAt(nearby)}), worldFromCamera(kView1), 1.0);
  ASSERT_EQ(estimator.instances().size(), 1u) << "the moved mug became a second instance";
  EXPECT_EQ(estimator.instances().front().id, id);
  const auto position = estimator.instances().front().estimator->positionEstimate();
  ASSERT_TRUE(position.has_value());
  EXPECT_LT((*position - nearby.translation()).norm(), 0.02);
}

// Within association_distance but turned: its candidate is near the instance, yet the mug is no
// longer where its belief puts it (its old place is seen free). Fused into the old belief, the
// pose stayed at the old place for views on the patrol; found afresh, it follows at once.
TEST(InstancePresence, AMugMovedFourCentimetresAndTurnedIsFoundAtItsNewPoseAtOnce) {
  SceneEstimator estimator = makeEstimator();
  const int id = mugFoundAtA(estimator).id;
  const Eigen::Isometry3d moved = placed(kMugPosition + Eigen::Vector3d(0.0, -0.04, 0.0), 2.2);
  // kView0 again would be a still camera: not segmented.
  look(estimator, tableWith({mugAt(moved)}), worldFromCamera(kView1), 1.0);
  ASSERT_EQ(estimator.instances().size(), 1u) << "the moved mug became a second instance";
  const ObjectInstance& mug = estimator.instances().front();
  EXPECT_EQ(mug.id, id);
  const std::optional<Eigen::Isometry3d> pose = believedPose(*mug.estimator);
  ASSERT_TRUE(pose.has_value());
  EXPECT_LT((pose->translation() - moved.translation()).norm(), 0.01)
      << pose->translation().transpose();
  const Eigen::Quaterniond q(pose->linear()), truth(moved.linear());
  EXPECT_LT(q.angularDistance(truth) * 180.0 / M_PI, 10.0);
}

// Moved towards the camera, the mug hides its old place, which is never seen free; its centroid
// moved beyond association_distance. Still the same mug: both would fill one space.
TEST(InstancePresence, AMugMovedInFrontOfItsOldPlaceIsFollowedNotDuplicated) {
  SceneEstimator estimator = makeEstimator();
  const int id = mugFoundAtA(estimator).id;
  const Eigen::Vector3d towards_camera = Eigen::Vector3d(kView1.x(), kView1.y(), 0.0).normalized();
  const Eigen::Isometry3d nearer = placed(kMugPosition + 0.06 * towards_camera, 0.7);
  const SceneUpdate update =
      look(estimator, tableWith({mugAt(nearer)}), worldFromCamera(kView1), 1.0);
  ASSERT_EQ(estimator.instances().size(), 1u) << "the moved mug became a second instance";
  EXPECT_EQ(estimator.instances().front().id, id);
  const auto position = estimator.instances().front().estimator->positionEstimate();
  ASSERT_TRUE(position.has_value());
  EXPECT_LT((*position - nearer.translation()).norm(), 0.02);
  for (const CandidateOutcome& candidate : update.candidates) EXPECT_FALSE(candidate.new_instance);
}

TEST(InstancePresence, SeeingTheMugAtItsPlaceRestartsTheCount) {
  SceneEstimator estimator = makeEstimator();
  const int id = mugFoundAtA(estimator).id;
  const Scene empty = tableWith({}), with_mug = tableWith({mugAt(kMugAtA)});
  look(estimator, empty, worldFromCamera(kView1), 1.0);
  ASSERT_EQ(estimator.instance(id)->presence.absent_frames, 1);
  // Put back: seen there, the frame before no longer counts.
  look(estimator, with_mug, worldFromCamera(kView2), 2.0);
  ASSERT_EQ(estimator.instances().size(), 1u);
  EXPECT_EQ(estimator.instance(id)->presence.absent_frames, 0);
  look(estimator, empty, worldFromCamera(kView3), 3.0);
  const ObjectInstance* mug = estimator.instance(id);
  ASSERT_NE(mug, nullptr);
  EXPECT_EQ(mug->presence.absent_frames, 1) << describe(*mug);
  EXPECT_EQ(mug->presence.state, InstanceState::kPresent) << "gone after 1 + 1 frames apart";
}

pcl::PointCloud<pcl::PointXYZ> shuffled(const pcl::PointCloud<pcl::PointXYZ>& organised) {
  pcl::PointCloud<pcl::PointXYZ> points;
  for (const auto& p : organised.points) {
    if (std::isfinite(p.z)) points.push_back(p);
  }
  std::mt19937 rng(3);
  std::shuffle(points.points.begin(), points.points.end(), rng);
  points.width = static_cast<std::uint32_t>(points.size());
  points.height = 1;
  return points;
}

// The check alone, at the true pose: a frame's depth for the three cases.
class PresenceCheckTest : public ::testing::Test {
 protected:
  // unorganised: the finite points shuffled into one row, as a lidar or a filter gives them.
  PresenceCheck checkAtA(const Scene& scene, const Eigen::Vector3d& direction,
                         bool unorganised = false) const {
    const Eigen::Isometry3d pose = worldFromCamera(direction);
    pcl::PointCloud<pcl::PointXYZ> cloud = render(scene, pose, 7);
    if (unorganised) cloud = shuffled(cloud);
    const SceneSegmentationParameters segmentation;
    std::vector<Eigen::Vector4d> supports;
    for (const SupportPlane& plane : segmentScene(cloud, segmentation).planes) {
      supports.push_back(plane.coefficients);
    }
    const SceneDepth depth =
        indexRays(verificationScene(cloud, supports, segmentation.plane_distance));
    return presence_.check(0, kMugAtA, depth, pose);
  }

  InstancePresence presence_{ModelLibrary({{"mug", test::quickMugModel()}}),
                             VerificationParameters{}, 2, 0.0};
};

TEST_F(PresenceCheckTest, TheMugAtItsPlaceIsSeenItsEmptyPlaceFreeAndItsHiddenPlaceNeither) {
  const PresenceCheck there = checkAtA(tableWith({mugAt(kMugAtA)}), kView0);
  EXPECT_EQ(there.evidence, PresenceEvidence::kSeen);
  EXPECT_GT(there.seen, there.predicted / 2);
  const PresenceCheck away = checkAtA(tableWith({}), kView0);
  EXPECT_EQ(away.evidence, PresenceEvidence::kAbsent);
  EXPECT_GT(away.free, away.predicted * 2 / 3);
  const PresenceCheck hidden = checkAtA(tableWith({screen()}), Eigen::Vector3d(0.2, -1.0, 0.5));
  EXPECT_EQ(hidden.evidence, PresenceEvidence::kNone);
  EXPECT_GT(hidden.hidden, hidden.predicted / 2);
}

// Seen from nearly straight above, most of a mug's camera-facing samples are its inside floor,
// a few millimetres above the table: where the mug was taken away the table lies within the
// tolerance of them. They must not count as the mug seen (a patrolled mug's removal went
// unnoticed for three passes so), and the rim's samples, seen free, tell.
TEST_F(PresenceCheckTest, FromAboveTheTableWhereTheMugsFloorWasIsNoEvidenceAndItsRimTells) {
  const Eigen::Vector3d above(0.15, 0.1, 1.0);
  const PresenceCheck there = checkAtA(tableWith({mugAt(kMugAtA)}), above);
  EXPECT_EQ(there.evidence, PresenceEvidence::kSeen);
  const PresenceCheck away = checkAtA(tableWith({}), above);
  EXPECT_GT(away.on_support, away.predicted / 3);
  EXPECT_EQ(away.seen, 0);
  EXPECT_EQ(away.evidence, PresenceEvidence::kAbsent)
      << "predicted " << away.predicted << " free " << away.free << " on support "
      << away.on_support;
}

// Rays index points by their direction, not by their pixel: the same answers without the grid.
TEST_F(PresenceCheckTest, AnUnorganisedCloudGivesTheSameAnswers) {
  EXPECT_EQ(checkAtA(tableWith({mugAt(kMugAtA)}), kView0, true).evidence, PresenceEvidence::kSeen);
  EXPECT_EQ(checkAtA(tableWith({}), kView0, true).evidence, PresenceEvidence::kAbsent);
  EXPECT_EQ(checkAtA(tableWith({screen()}), Eigen::Vector3d(0.2, -1.0, 0.5), true).evidence,
            PresenceEvidence::kNone);
}

// Where the cloud has no point near a ray (no return, out of range), there is no evidence.
TEST_F(PresenceCheckTest, AFrameWithoutDepthThereIsNoEvidence) {
  const PresenceCheck check = presence_.check(0, kMugAtA, SceneDepth{}, worldFromCamera(kView0));
  EXPECT_GT(check.predicted, 0);
  EXPECT_EQ(check.noData(), check.predicted);
  EXPECT_EQ(check.evidence, PresenceEvidence::kNone);
}

PresenceCheck counted(int predicted, int seen, int free, int hidden = 0, int on_support = 0) {
  PresenceCheck check;
  check.predicted = predicted;
  check.seen = seen;
  check.free = free;
  check.hidden = hidden;
  check.on_support = on_support;
  return check;
}

TEST(PresenceEvidence, APlaceHalfFreeIsNeitherSeenNorAbsent) {
  EXPECT_EQ(presenceEvidence(counted(1000, 900, 0, 100)), PresenceEvidence::kSeen);
  EXPECT_EQ(presenceEvidence(counted(1000, 700, 200)), PresenceEvidence::kSeen);
  EXPECT_EQ(presenceEvidence(counted(1000, 300, 700)), PresenceEvidence::kAbsent);
  EXPECT_EQ(presenceEvidence(counted(1000, 263, 266)), PresenceEvidence::kNone);
  EXPECT_EQ(presenceEvidence(counted(1000, 400, 600)), PresenceEvidence::kAbsent);
  EXPECT_EQ(presenceEvidence(counted(1000, 600, 400)), PresenceEvidence::kNone);
}

TEST(PresenceEvidence, APlaceMostlyHiddenOrOutOfViewIsNoEvidence) {
  EXPECT_EQ(presenceEvidence(counted(1000, 0, 246)), PresenceEvidence::kNone);
  EXPECT_EQ(presenceEvidence(counted(1000, 100, 100, 800)), PresenceEvidence::kNone);
  EXPECT_EQ(presenceEvidence(counted(0, 0, 0)), PresenceEvidence::kNone);
}

// Samples the table explains are left out of the share that must be judged, but a handful of
// judged samples never decide.
TEST(PresenceEvidence, SamplesOnTheSupportAreLeftOutButAFewJudgedNeverDecide) {
  EXPECT_EQ(presenceEvidence(counted(373, 0, 119, 0, 254)), PresenceEvidence::kAbsent);
  EXPECT_EQ(presenceEvidence(counted(373, 119, 0, 0, 254)), PresenceEvidence::kSeen);
  EXPECT_EQ(presenceEvidence(counted(373, 0, 119, 130, 124)), PresenceEvidence::kNone);
  EXPECT_EQ(presenceEvidence(counted(373, 0, 19, 0, 354)), PresenceEvidence::kNone);
}

TEST(InstancePresenceParameters, BadValuesAreRefusedNamingThem) {
  SceneEstimatorParameters parameters;
  parameters.absent_views = 0;
  try {
    makeEstimator(parameters);
    FAIL() << "absent_views 0 was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("absent_views"), std::string::npos) << error.what();
  }
  parameters = {};
  parameters.forget_gone_after = -1.0;
  EXPECT_THROW(makeEstimator(parameters), Error);
}

}  // namespace
}  // namespace vdc
