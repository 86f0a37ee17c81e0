// The scene layer on rendered table scenes: two mugs (two instances of one model), a box of a
// mug's size (fits the model's size, is no mug) and a tall cylinder, seen by a moving camera.
#include "view_direction_classification/recognition/scene_estimator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "shared_surfaces.h"
#include "support/mug_scene.h"
#include "support/quick_mug_model.h"
#include "support/scene_update_text.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/scene/label_segmentation.h"

namespace vdc {
namespace {

using test::kMugPosition;
using test::placed;

const Eigen::Isometry3d kFirstMug = placed(kMugPosition, 0.7);
const Eigen::Isometry3d kSecondMug = placed(kMugPosition + Eigen::Vector3d(0.0, 0.2, 0.0), -1.2);
// A 9 x 8 x 10 cm box standing on the table: its size fits the mug's, its shape does not.
const Eigen::Vector3d kBoxCentre = kMugPosition + Eigen::Vector3d(0.05, -0.2, 0.0);

Scene tableScene() {
  Scene scene;
  scene.object = {makeMug(), kFirstMug};
  scene.table_size = Eigen::Vector2d(1.4, 1.0);
  const double z = test::tableTop();
  scene.distractors.push_back({makeMug(), kSecondMug});
  scene.distractors.push_back({makeBoxMesh(Eigen::Vector3d(0.09, 0.08, 0.10)),
                               placed(Eigen::Vector3d(kBoxCentre.x(), kBoxCentre.y(), z), 0.4)});
  scene.distractors.push_back(
      {makeCylinderMesh(0.03, 0.25), placed(Eigen::Vector3d(0.15, -0.05, z))});
  return scene;
}

// The camera 0.7 m from the first mug, looking at it from `direction` (fixed frame).
Eigen::Isometry3d worldFromCamera(const Eigen::Vector3d& direction) {
  return test::cameraFromWorld(direction.normalized(), 0.7).inverse();
}

pcl::PointCloud<pcl::PointXYZ> render(const Eigen::Isometry3d& world_from_camera,
                                      std::uint32_t seed) {
  static const DepthRenderer renderer(sceneMesh(tableScene()));
  std::mt19937 rng(seed);
  return renderer.render(world_from_camera.inverse(), DepthNoiseModel{true}, &rng);
}

SceneEstimator makeEstimator() {
  return SceneEstimator(ModelLibrary({{"mug", test::quickMugModel()}}), {});
}

// The instance whose position estimate is within 2 cm of `truth`, or null.
const ObjectInstance* instanceAt(const SceneEstimator& estimator, const Eigen::Vector3d& truth) {
  for (const ObjectInstance& instance : estimator.instances()) {
    const auto position = instance.estimator->positionEstimate();
    if (position && (*position - truth).norm() < 0.02) return &instance;
  }
  return nullptr;
}

std::string describe(const SceneEstimator& estimator, const SceneUpdate& update) {
  return test::describeSceneUpdate(estimator, update);
}

const Eigen::Vector3d kFirstView(1.0, 0.2, 0.9);

TEST(SceneEstimator, FindsTwoMugsAsTwoInstancesAndLeavesTheBoxAndTheCylinderAlone) {
  SceneEstimator estimator = makeEstimator();
  const SceneUpdate update =
      estimator.update(render(worldFromCamera(kFirstView), 1), worldFromCamera(kFirstView), 0.0);
  ASSERT_TRUE(update.segmented);
  EXPECT_EQ(update.planes, 1);
  ASSERT_EQ(estimator.instances().size(), 2u) << describe(estimator, update);
  const ObjectInstance* first = instanceAt(estimator, kFirstMug.translation());
  const ObjectInstance* second = instanceAt(estimator, kSecondMug.translation());
  ASSERT_NE(first, nullptr) << describe(estimator, update);
  ASSERT_NE(second, nullptr) << describe(estimator, update);
  EXPECT_NE(first->id, second->id);
  EXPECT_EQ((std::set<std::string>{first->name, second->name}),
            (std::set<std::string>{"mug_1", "mug_2"}));
  EXPECT_GT(first->identity_probability, 0.5);
  // The box fits the mug's size and was tried: no mug explains it.
  bool box_tried = false;
  for (const CandidateOutcome& candidate : update.candidates) {
    if ((candidate.centroid_world.head<2>() - kBoxCentre.head<2>()).norm() > 0.05) continue;
    box_tried = true;
    EXPECT_EQ(candidate.instance, -1) << describe(estimator, update);
    EXPECT_FALSE(candidate.note.empty());
  }
  EXPECT_TRUE(box_tried) << describe(estimator, update);
  // Segmentation cuts a mug's handle off its body where they meet concavely: the handle is a
  // part of its mug's instance, not a third mug placed behind the first.
  int parts = 0;
  for (const CandidateOutcome& candidate : update.candidates) {
    if (candidate.note.rfind("a part of mug_", 0) == 0) ++parts;
  }
  EXPECT_GE(parts, 1) << describe(estimator, update);
}

TEST(SceneEstimator, InstancesKeepTheirIdsAndFuseTheirViewsAsTheCameraMoves) {
  SceneEstimator estimator = makeEstimator();
  const std::vector<Eigen::Vector3d> directions{kFirstView, {0.6, 0.8, 0.9}, {-0.2, 1.0, 0.8}};
  std::set<int> ids;
  for (std::size_t v = 0; v < directions.size(); ++v) {
    const Eigen::Isometry3d pose = worldFromCamera(directions[v]);
    const SceneUpdate update = estimator.update(render(pose, 10 + v), pose, 1.0 * v);
    ASSERT_TRUE(update.segmented);
    if (v == 0) {
      for (const ObjectInstance& instance : estimator.instances()) ids.insert(instance.id);
    }
    std::set<int> now;
    for (const ObjectInstance& instance : estimator.instances()) now.insert(instance.id);
    EXPECT_EQ(now, ids) << "view " << v + 1 << ": " << describe(estimator, update);
  }
  ASSERT_EQ(ids.size(), 2u);
  for (const Eigen::Isometry3d& truth : {kFirstMug, kSecondMug}) {
    const ObjectInstance* instance = instanceAt(estimator, truth.translation());
    ASSERT_NE(instance, nullptr);
    EXPECT_GE(instance->estimator->viewsFused(), 2) << instance->name;
    EXPECT_LT(rotationErrorDeg(instance->estimator->mapOrientation(),
                               quaternionFromRotationMatrix(truth.linear())),
              5.0)
        << instance->name;
  }
}

// Two mugs, three views: with the models and the instances' updates on one thread or side by
// side, the same instances with the same identities and poses, to the last bit.
TEST(SceneEstimator, InstancesUpdatedSideBySideEndExactlyAsOneAfterTheOther) {
  const auto run = [](int threads) {
    SceneEstimatorParameters parameters;
    parameters.identification.threads = threads;
    SceneEstimator estimator(ModelLibrary({{"mug", test::quickMugModel()}}), parameters);
    const std::vector<Eigen::Vector3d> directions{kFirstView, {0.6, 0.8, 0.9}, {-0.2, 1.0, 0.8}};
    for (std::size_t v = 0; v < directions.size(); ++v) {
      const Eigen::Isometry3d pose = worldFromCamera(directions[v]);
      estimator.update(render(pose, 10 + v), pose, 1.0 * v);
    }
    return estimator;
  };
  const SceneEstimator alone = run(1);
  const SceneEstimator side_by_side = run(2);
  ASSERT_EQ(alone.instances().size(), 2u);
  ASSERT_EQ(side_by_side.instances().size(), alone.instances().size());
  for (std::size_t i = 0; i < alone.instances().size(); ++i) {
    const ObjectInstance& a = alone.instances()[i];
    const ObjectInstance& b = side_by_side.instances()[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.identity_probability, b.identity_probability) << a.name;
    EXPECT_EQ(a.estimator->viewsFused(), b.estimator->viewsFused()) << a.name;
    EXPECT_EQ(a.estimator->mapOrientation(), b.estimator->mapOrientation()) << a.name;
    EXPECT_EQ(a.estimator->positionEstimate(), b.estimator->positionEstimate()) << a.name;
  }
}

TEST(SceneEstimator, AStillCameraIsNotSegmentedAgainAndAnInstanceOutOfViewKeepsItsBelief) {
  SceneEstimator estimator = makeEstimator();
  const Eigen::Isometry3d pose = worldFromCamera(kFirstView);
  estimator.update(render(pose, 1), pose, 0.0);
  const SceneUpdate still = estimator.update(render(pose, 2), pose, 0.1);
  EXPECT_FALSE(still.segmented);
  EXPECT_FALSE(still.skip_reason.empty());

  // The camera turned away to an empty part of the table: nothing seen, both kept.
  const Eigen::Isometry3d away =
      test::cameraFromWorld(Eigen::Vector3d(1.0, 0.0, 0.9).normalized(), 0.7,
                            kMugPosition + Eigen::Vector3d(0.0, -0.6, 0.0))
          .inverse();
  const ObjectInstance* first = instanceAt(estimator, kFirstMug.translation());
  ASSERT_NE(first, nullptr);
  const int id = first->id;
  const Eigen::Vector4d map = first->estimator->mapOrientation();
  const SceneUpdate elsewhere = estimator.update(render(away, 3), away, 0.2);
  EXPECT_TRUE(elsewhere.segmented);
  ASSERT_NE(estimator.instance(id), nullptr);
  EXPECT_EQ(estimator.instance(id)->estimator->mapOrientation(), map);
  EXPECT_EQ(estimator.instances().size(), 2u);

  EXPECT_TRUE(estimator.resetInstance(id));
  EXPECT_EQ(estimator.instance(id), nullptr);
  EXPECT_FALSE(estimator.resetInstance(id));
  estimator.reset();
  EXPECT_TRUE(estimator.instances().empty());
}

TEST(SceneEstimator, BadInputIsSkippedOrRefused) {
  SceneEstimator estimator = makeEstimator();
  pcl::PointCloud<pcl::PointXYZ> empty;
  const SceneUpdate update = estimator.update(empty, worldFromCamera(kFirstView), 0.0);
  EXPECT_TRUE(update.candidates.empty());
  Eigen::Isometry3d bad = worldFromCamera(kFirstView);
  bad.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(estimator.update(empty, bad, 0.0), Error);
  SceneEstimatorParameters parameters;
  parameters.association_distance = -1.0;
  EXPECT_THROW(SceneEstimator(ModelLibrary({{"mug", test::quickMugModel()}}), parameters), Error);
}

// A robot's table changes: where an unknown box stood and the camera then saw the table, a mug
// put down later is a new thing to try, even seen from the same direction (unknown things are
// otherwise tried once per place: UnknownObjects).
TEST(SceneEstimator, AMugPutWhereAnUnknownBoxWasTakenAwayIsIdentified) {
  Scene layout;  // only to place the table under the first mug's place
  layout.object = {makeMug(), kFirstMug};
  layout.table_size = Eigen::Vector2d(1.4, 1.0);
  const ScenePart table = tablePart(layout);
  const Eigen::Isometry3d box_pose = placed(
      Eigen::Vector3d(kFirstMug.translation().x(), kFirstMug.translation().y(), test::tableTop()),
      0.4);
  const ScenePart box{makeBoxMesh(Eigen::Vector3d(0.09, 0.08, 0.10)), box_pose};
  const std::vector<std::vector<ScenePart>> scenes{{table, box}, {table}, {table, layout.object}};
  // Nearly the same direction each time (the camera moves a little: every frame is segmented).
  const std::vector<Eigen::Vector3d> directions{kFirstView, {1.0, 0.25, 0.9}, {1.0, 0.3, 0.9}};
  SceneEstimator estimator = makeEstimator();
  for (std::size_t v = 0; v < scenes.size(); ++v) {
    const DepthRenderer renderer(partsMesh(scenes[v]));
    const Eigen::Isometry3d pose = worldFromCamera(directions[v]);
    std::mt19937 rng(20 + v);
    const SceneUpdate update = estimator.update(
        renderer.render(pose.inverse(), DepthNoiseModel{true}, &rng), pose, 1.0 * v);
    ASSERT_TRUE(update.segmented) << v;
    if (v == 0) {
      ASSERT_TRUE(estimator.instances().empty()) << describe(estimator, update);
    }
  }
  EXPECT_NE(instanceAt(estimator, kFirstMug.translation()), nullptr);
}

// Every candidate gets fresh estimators, whose refiners share their model's surfaces
// (refinement/shared_surfaces.h) only while something holds them: the scene estimator does, so
// the k-d trees and distance fields are not rebuilt for each candidate.
TEST(SceneEstimator, KeepsEachModelsRefinementSurfaceAliveBetweenCandidates) {
  const std::shared_ptr<const ModelBundle> bundle = test::quickMugModel();
  const EstimatorParameters instance;
  std::weak_ptr<const ModelSurface> surface;
  {
    const SceneEstimator estimator(ModelLibrary({{"mug", bundle}}), {});
    // The returned pointer is dropped at once: only the scene estimator can keep it.
    surface = sharedModelSurface(*bundle, instance.refinement_parameters.model_spacing);
    EXPECT_FALSE(surface.expired());
    std::weak_ptr<const ModelSurface> polish =
        sharedModelSurface(*bundle, instance.refinement_parameters.polish_model_spacing);
    EXPECT_FALSE(polish.expired());
  }
  EXPECT_TRUE(surface.expired());
}

}  // namespace
}  // namespace vdc

namespace vdc {
namespace {

// Segmentation over-split on purpose (every slight concavity cuts, pieces down to 2 % kept): each
// mug comes in a dozen pieces. The largest is still identified, and the others are parts of it,
// not mugs of their own.
TEST(SceneEstimatorOverSplit, AMugCutIntoPiecesIsOneInstanceWithItsPiecesAsParts) {
  SceneEstimatorParameters parameters;
  parameters.segmentation.concavity_tolerance_deg = 0.5;
  parameters.segmentation.min_part_fraction = 0.02;
  parameters.segmentation.supervoxel_seed = 0.01;
  SceneEstimator estimator(ModelLibrary({{"mug", test::quickMugModel()}}), parameters);
  const Eigen::Isometry3d pose = worldFromCamera(kFirstView);
  const SceneUpdate update = estimator.update(render(pose, 1), pose, 0.0);
  int parts = 0;
  for (const CandidateOutcome& candidate : update.candidates) {
    if (candidate.note.rfind("a part of mug_", 0) == 0) ++parts;
  }
  ASSERT_GE(parts, 6) << "the over-split did not cut the mugs: " << describe(estimator, update);
  EXPECT_EQ(estimator.instances().size(), 2u) << describe(estimator, update);
  // Each mug is identified from its pieces together, on the frame that cut it.
  int whole = 0;
  for (const CandidateOutcome& candidate : update.candidates) {
    if (candidate.new_instance && candidate.note.rfind("identified with the", 0) == 0) ++whole;
  }
  EXPECT_EQ(whole, 2) << describe(estimator, update);
  EXPECT_NE(instanceAt(estimator, kFirstMug.translation()), nullptr);
  EXPECT_NE(instanceAt(estimator, kSecondMug.translation()), nullptr);
}

// A rendered frame segmented as usual but for the first mug, whose candidates (within 8 cm of it)
// are joined into `mug` and left out of `segments`, for a test to cut them its own way.
struct FirstMugApart {
  SceneSegments segments;
  SceneCandidate mug;
};

FirstMugApart firstMugApart(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                            const Eigen::Isometry3d& world_from_camera) {
  FirstMugApart apart{segmentScene(cloud, {}), {}};
  std::vector<SceneCandidate> others;
  for (const SceneCandidate& candidate : apart.segments.candidates) {
    const Eigen::Vector3d centroid = world_from_camera * candidate.centroid;
    if ((centroid - kFirstMug.translation()).head<2>().norm() < 0.08) {
      apart.mug.indices.insert(apart.mug.indices.end(), candidate.indices.begin(),
                               candidate.indices.end());
      apart.mug.support = candidate.support;
    } else {
      others.push_back(candidate);
    }
  }
  apart.segments.candidates = others;
  return apart;
}

// The segments with the mug's pieces back, each a cluster of its own numbered from
// first_cluster, on the mug's support.
SceneSegments withMugPieces(const pcl::PointCloud<pcl::PointXYZ>& cloud, FirstMugApart apart,
                            std::vector<SceneCandidate> pieces, int first_cluster) {
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    pieces[k].support = apart.mug.support;
    pieces[k].cluster = first_cluster + static_cast<int>(k);
    apart.segments.candidates.push_back(mergedCandidate(cloud, {&pieces[k]}));
  }
  return apart.segments;
}

// The first mug's points cut into image quadrants, each a cluster of its own (as a depth jump
// where an object hides part of itself separates its parts), the rest segmented as usual.
SceneSegments firstMugInQuadrants(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                  const Eigen::Isometry3d& world_from_camera) {
  const FirstMugApart apart = firstMugApart(cloud, world_from_camera);
  std::vector<int> rows, columns;
  for (int index : apart.mug.indices) {
    rows.push_back(index / static_cast<int>(cloud.width));
    columns.push_back(index % static_cast<int>(cloud.width));
  }
  std::nth_element(rows.begin(), rows.begin() + rows.size() / 2, rows.end());
  std::nth_element(columns.begin(), columns.begin() + columns.size() / 2, columns.end());
  const int row = rows[rows.size() / 2], column = columns[columns.size() / 2];
  std::vector<SceneCandidate> quadrants(4);
  for (int index : apart.mug.indices) {
    const int q = (index / static_cast<int>(cloud.width) < row ? 0 : 2) +
                  (index % static_cast<int>(cloud.width) < column ? 0 : 1);
    quadrants[q].indices.push_back(index);
  }
  return withMugPieces(cloud, apart, quadrants, 100);
}

// Alone no quadrant is explained by the mug better than by "unknown" (checked: without the
// groups of adjacentCandidateGroups none becomes an instance); two beside each other are.
TEST(SceneEstimatorPieces, PartsOfAMugInDifferentClustersAreIdentifiedTogether) {
  SceneEstimator estimator = makeEstimator();
  const Eigen::Isometry3d pose = worldFromCamera(kFirstView);
  const pcl::PointCloud<pcl::PointXYZ> cloud = render(pose, 1);
  const SceneSegments segments = firstMugInQuadrants(cloud, pose);
  const std::size_t first_quadrant = segments.candidates.size() - 4;
  const SceneUpdate update = estimator.update(cloud, segments, pose, 0.0);
  const ObjectInstance* first = instanceAt(estimator, kFirstMug.translation());
  ASSERT_NE(first, nullptr) << describe(estimator, update);
  for (std::size_t q = first_quadrant; q < update.candidates.size(); ++q) {
    EXPECT_EQ(update.candidates[q].instance, first->id) << describe(estimator, update);
  }
}

}  // namespace
}  // namespace vdc

namespace vdc {
namespace {

// A detector's label image of tableScene(): the first mug instance 1 of class 1, the second
// instance 1 of class 2 (the Cityscapes convention, divisor 1000), everything else background.
// The mask starts 1 cm above the table. From 3 mm it took in points of the mug's foot and of the
// noisy table beside it, and on one machine (2026-12-06) 11 of them more than the mask from 1 cm
// took the first mug's identity score from 0.975 to below unknown's 0.8, though the same tests
// had passed on the machine before: a mask's edge on the table is a robustness question of its
// own (doc/evaluation.md, "Scenes with several objects"); these tests are of the label routing.
LabelImage labelBothMugs(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                         const Eigen::Isometry3d& world_from_camera) {
  LabelImage labels{static_cast<int>(cloud.width), static_cast<int>(cloud.height),
                    std::vector<std::uint32_t>(cloud.size(), 0)};
  const double table = test::tableTop();
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!std::isfinite(cloud[i].z)) continue;
    const Eigen::Vector3d p = world_from_camera * cloud[i].getVector3fMap().cast<double>();
    if (p.z() < table + 0.01 || p.z() > table + 0.11) continue;
    if ((p - kFirstMug.translation()).head<2>().norm() < 0.075) labels.labels[i] = 1001;
    if ((p - kSecondMug.translation()).head<2>().norm() < 0.075) labels.labels[i] = 2001;
  }
  return labels;
}

// Two models of the same mug: a candidate tried against both is either (their scores tie).
ModelLibrary twoNamesOfTheMug() {
  return ModelLibrary({{"mug", test::quickMugModel()}, {"cup", test::quickMugModel()}});
}

SceneUpdate updateFromLabels(SceneEstimator& estimator,
                             const SceneEstimatorParameters& parameters) {
  const Eigen::Isometry3d pose = worldFromCamera(kFirstView);
  const pcl::PointCloud<pcl::PointXYZ> cloud = render(pose, 1);
  const SceneSegments segments =
      segmentLabels(cloud, labelBothMugs(cloud, pose), parameters.segmentation);
  EXPECT_EQ(segments.candidates.size(), 2u) << segments.note;
  return estimator.update(cloud, segments, pose, 0.0);
}

TEST(SceneEstimatorLabels, WithLabelModelsACandidateIsTriedOnlyAgainstItsClassModel) {
  SceneEstimatorParameters parameters;
  parameters.label_models = {{1, "cup"}};
  SceneEstimator estimator(twoNamesOfTheMug(), parameters);
  const SceneUpdate update = updateFromLabels(estimator, parameters);
  ASSERT_TRUE(update.segmented);
  // Class 1 (the first mug): tried against `cup` alone, so `mug` has no probability at all.
  ASSERT_EQ(estimator.instances().size(), 1u) << describe(estimator, update);
  const ObjectInstance& cup = estimator.instances().front();
  EXPECT_EQ(cup.name, "cup_1");
  EXPECT_EQ(cup.identity[0], 0.0) << "the mug model was tried";
  EXPECT_NE(instanceAt(estimator, kFirstMug.translation()), nullptr);
  // Class 2 (the second mug) has no entry: ignored, with the reason.
  int ignored = 0;
  for (const CandidateOutcome& candidate : update.candidates) {
    if (candidate.note.find("ignored: its class 2") == std::string::npos) continue;
    ++ignored;
    EXPECT_EQ(candidate.instance, -1);
  }
  EXPECT_EQ(ignored, 1) << describe(estimator, update);
}

// The contrast: without the map both names of the mug are tried for each candidate, their
// scores tie, neither reaches identity_min_probability (0.5), and both mugs stay unknown.
TEST(SceneEstimatorLabels, WithoutLabelModelsEveryFittingModelIsTried) {
  SceneEstimatorParameters parameters;
  SceneEstimator estimator(twoNamesOfTheMug(), parameters);
  const SceneUpdate update = updateFromLabels(estimator, parameters);
  ASSERT_TRUE(update.segmented);
  ASSERT_EQ(update.candidates.size(), 2u);
  EXPECT_TRUE(estimator.instances().empty()) << describe(estimator, update);
  for (const CandidateOutcome& candidate : update.candidates) {
    EXPECT_EQ(candidate.note, "no model is probable enough") << describe(estimator, update);
    EXPECT_GT(candidate.probability, 0.3) << describe(estimator, update);
    EXPECT_LT(candidate.probability, 0.5) << describe(estimator, update);
  }
}

// A candidate whose most probable model reaches track_probability but not min_probability is a
// tentative instance: it fuses the next views, but it is not reported until they confirm it.
TEST(SceneEstimatorLabels, AnInstanceBelowMinProbabilityIsTrackedButNotReported) {
  SceneEstimatorParameters parameters;
  parameters.identification.track_probability = 0.3;  // below the tied names' ~0.45
  SceneEstimator estimator(twoNamesOfTheMug(), parameters);
  const SceneUpdate update = updateFromLabels(estimator, parameters);
  ASSERT_EQ(estimator.instances().size(), 2u) << describe(estimator, update);
  for (const ObjectInstance& instance : estimator.instances()) {
    EXPECT_LT(instance.identity_probability, parameters.identification.min_probability);
    EXPECT_FALSE(estimator.identified(instance)) << describe(estimator, update);
    EXPECT_FALSE(estimator.confirmed(instance)) << describe(estimator, update);
  }
}

TEST(IdentificationParameters, TrackProbabilityIsCheckedAgainstTheDropProbability) {
  IdentificationParameters bad;
  bad.track_probability = 1.5;
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
  bad = {};
  bad.track_probability = 0.1;  // below drop_probability (0.2): a new instance would be dropped
  EXPECT_THROW(checkIdentificationParameters(bad), Error);
}

TEST(SceneEstimatorLabels, ALabelModelNamingNoModelOfTheLibraryIsAStartUpError) {
  SceneEstimatorParameters parameters;
  parameters.label_models = {{1, "mug"}, {41, "bowl"}};
  try {
    SceneEstimator estimator(ModelLibrary({{"mug", test::quickMugModel()}}), parameters);
    FAIL() << "an unknown model name was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("'bowl'"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("class 41"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace vdc

namespace vdc {
namespace {

// The first mug's points cut in two candidates of two clusters (a depth jump between them, as
// where a helmet's dome hides the top of its brim) by the plane x = 0 of the mug's frame.
SceneSegments firstMugCutInTwo(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                               const Eigen::Isometry3d& world_from_camera) {
  const FirstMugApart apart = firstMugApart(cloud, world_from_camera);
  std::vector<SceneCandidate> halves(2);
  for (int index : apart.mug.indices) {
    const Eigen::Vector3d p = world_from_camera * cloud[index].getVector3fMap().cast<double>();
    halves[(kFirstMug.inverse() * p).x() > 0.0 ? 0 : 1].indices.push_back(index);
  }
  return withMugPieces(cloud, apart, halves, 200);
}

// With a part tolerance too tight for the depth noise no piece is a part of an instance by its
// explanation: the half identified alone is tried with the half beside it, and the union, which
// verifies more surely, takes its place under the same id. Without the growth the other half
// stays apart from the instance.
TEST(SceneEstimatorGrowth, AnInstanceFoundOnOnePieceTakesThePieceBesideItThatFitsItBetterToo) {
  const Eigen::Isometry3d pose = worldFromCamera(kFirstView);
  const pcl::PointCloud<pcl::PointXYZ> cloud = render(pose, 1);
  const SceneSegments segments = firstMugCutInTwo(cloud, pose);
  const std::size_t first_half = segments.candidates.size() - 2;
  for (int tries : {0, 4}) {
    SceneEstimatorParameters parameters;
    parameters.part_tolerance = 0.0003;
    parameters.max_growth_tries = tries;
    SceneEstimator estimator(ModelLibrary({{"mug", test::quickMugModel()}}), parameters);
    const SceneUpdate update = estimator.update(cloud, segments, pose, 0.0);
    const ObjectInstance* mug = instanceAt(estimator, kFirstMug.translation());
    ASSERT_NE(mug, nullptr) << "tries " << tries << ": " << describe(estimator, update);
    int halves_of_it = 0, new_instances = 0;
    for (std::size_t h = first_half; h < first_half + 2; ++h) {
      if (update.candidates[h].instance == mug->id) ++halves_of_it;
      if (update.candidates[h].new_instance) ++new_instances;
    }
    EXPECT_EQ(halves_of_it, tries == 0 ? 1 : 2)
        << "tries " << tries << ": " << describe(estimator, update);
    EXPECT_EQ(new_instances, 1) << "tries " << tries << ": " << describe(estimator, update);
    EXPECT_LT(rotationErrorDeg(mug->estimator->mapOrientation(),
                               quaternionFromRotationMatrix(kFirstMug.linear())),
              5.0)
        << "tries " << tries;
  }
}

TEST(SceneEstimatorGrowth, ANegativeNumberOfTriesIsRefused) {
  SceneEstimatorParameters parameters;
  parameters.max_growth_tries = -1;
  EXPECT_THROW(checkSceneEstimatorParameters(parameters), Error);
}

}  // namespace
}  // namespace vdc
