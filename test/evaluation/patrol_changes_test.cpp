#include "view_direction_classification/evaluation/patrol_changes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/table_footprint.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/primitive_meshes.h"

namespace vdc {
namespace {

std::vector<KnownModel> knownModels() {
  return {{"mug", makeMug()}, {"block", makeBoxMesh(Eigen::Vector3d(0.06, 0.04, 0.1))}};
}

PatrolScene startScene() {
  SceneGenerationSettings settings;
  settings.known_objects = 3;
  settings.distractors = 2;
  settings.occluder_fraction = 0.0;
  return patrolSceneOf(generateTableScene(
      knownModels(), {makeBoxMesh(Eigen::Vector3d(0.08, 0.08, 0.1)), makeCylinderMesh(0.03, 0.1)},
      settings, 3));
}

// Several rounds of changes from one seed.
std::vector<std::vector<PatrolChange>> rounds(PatrolScene* scene, std::uint32_t seed,
                                              int count = 5) {
  PatrolChangeSettings settings;
  settings.changes = 3;
  std::mt19937 rng(seed);
  std::vector<std::vector<PatrolChange>> all;
  for (int r = 0; r < count; ++r)
    all.push_back(applyRandomChanges(knownModels(), settings, rng, scene));
  return all;
}

bool samePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return a.isApprox(b, 1e-12);
}

const PatrolObject* objectWithId(const PatrolScene& scene, int id) {
  for (const PatrolObject& object : scene.objects) {
    if (object.id == id) return &object;
  }
  return nullptr;
}

TEST(PatrolChanges, TheSameSeedMakesTheSameChanges) {
  PatrolScene a = startScene(), b = startScene(), c = startScene();
  const auto first = rounds(&a, 11), second = rounds(&b, 11), other = rounds(&c, 12);
  ASSERT_EQ(first.size(), second.size());
  bool differs = false;
  for (std::size_t r = 0; r < first.size(); ++r) {
    ASSERT_EQ(first[r].size(), second[r].size());
    for (std::size_t i = 0; i < first[r].size(); ++i) {
      EXPECT_EQ(first[r][i].kind, second[r][i].kind);
      EXPECT_EQ(first[r][i].object, second[r][i].object);
      EXPECT_TRUE(samePose(first[r][i].to, second[r][i].to));
      if (i >= other[r].size() || !samePose(first[r][i].to, other[r][i].to)) differs = true;
    }
  }
  EXPECT_TRUE(differs);
}

// Each change said is applied: the scene after a round holds what its changes claim.
TEST(PatrolChanges, TheChangesClaimedAreAppliedToTheScene) {
  PatrolScene scene = startScene();
  PatrolChangeSettings settings;
  settings.changes = 3;
  std::mt19937 rng(5);
  std::set<PatrolChangeKind> kinds;
  for (int round = 0; round < 8; ++round) {
    const PatrolScene before = scene;
    const auto changes = applyRandomChanges(knownModels(), settings, rng, &scene);
    EXPECT_EQ(changes.size(), 3u);  // the table has room for every one
    std::set<int> changed;
    for (const PatrolChange& change : changes) {
      kinds.insert(change.kind);
      if (change.kind == PatrolChangeKind::kDistractorMoved) {
        EXPECT_TRUE(samePose(before.distractors[change.object].world_from_part, change.from));
        EXPECT_TRUE(samePose(scene.distractors[change.object].world_from_part, change.to));
        continue;
      }
      EXPECT_TRUE(changed.insert(change.object).second) << "an object changed twice in a round";
      const PatrolObject* after = objectWithId(scene, change.object);
      ASSERT_NE(after, nullptr);
      EXPECT_EQ(after->placed.model, change.model);
      const double moved = (change.to.translation() - change.from.translation()).head<2>().norm();
      switch (change.kind) {
        case PatrolChangeKind::kRemoved:
          EXPECT_TRUE(objectWithId(before, change.object)->present);
          EXPECT_FALSE(after->present);
          break;
        case PatrolChangeKind::kMoved:
          EXPECT_TRUE(after->present);
          EXPECT_TRUE(samePose(after->placed.part.world_from_part, change.to));
          EXPECT_GE(moved, settings.min_move - 1e-9);
          EXPECT_LE(moved, settings.max_move + 1e-9);
          EXPECT_NEAR(change.to.translation().z(), change.from.translation().z(), 1e-12);
          break;
        case PatrolChangeKind::kAdded:
          EXPECT_TRUE(after->present);
          EXPECT_TRUE(samePose(after->placed.part.world_from_part, change.to));
          break;
        case PatrolChangeKind::kDistractorMoved:
          break;
      }
    }
    // Nothing changed but what the changes name, and nothing overlaps on the table.
    for (const PatrolObject& object : before.objects) {
      if (changed.count(object.id)) continue;
      EXPECT_EQ(objectWithId(scene, object.id)->present, object.present);
    }
    const TableScene present = presentScene(scene);
    std::vector<Footprint> footprints;
    for (const auto& k : present.known)
      footprints.push_back(footprintOf(k.part.mesh, k.part.world_from_part));
    for (const auto& d : present.distractors)
      footprints.push_back(footprintOf(d.mesh, d.world_from_part));
    for (std::size_t i = 0; i < footprints.size(); ++i) {
      EXPECT_TRUE(footprintInsideRectangle(footprints[i], scene.table_size));
      for (std::size_t j = i + 1; j < footprints.size(); ++j) {
        EXPECT_GT(footprintSeparation(footprints[i], footprints[j]), 0.0) << i << " " << j;
      }
    }
  }
  EXPECT_EQ(kinds.size(), 4u) << "every kind of change in 8 rounds";
}

TEST(PatrolChanges, PresentSceneHoldsThePresentObjectsWithTheirIds) {
  PatrolScene scene = startScene();
  scene.objects[1].present = false;
  std::vector<int> ids;
  const TableScene present = presentScene(scene, &ids);
  EXPECT_EQ(ids, (std::vector<int>{0, 2}));
  ASSERT_EQ(present.known.size(), 2u);
  EXPECT_EQ(present.distractors.size(), 2u);
  EXPECT_TRUE(samePose(present.known[1].part.world_from_part,
                       scene.objects[2].placed.part.world_from_part));
}

TEST(PatrolChanges, BadSettingsAreRefused) {
  PatrolScene scene = startScene();
  std::mt19937 rng(1);
  PatrolChangeSettings settings;
  settings.min_move = 0.4;  // beyond max_move
  EXPECT_THROW(applyRandomChanges(knownModels(), settings, rng, &scene), Error);
  settings = PatrolChangeSettings{};
  settings.distractor_share = 1.5;
  EXPECT_THROW(applyRandomChanges(knownModels(), settings, rng, &scene), Error);
}

}  // namespace
}  // namespace vdc
