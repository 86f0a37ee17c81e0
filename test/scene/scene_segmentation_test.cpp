#include "view_direction_classification/scene/scene_segmentation.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support/milk_scene.h"
#include "support/mug_scene.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/geometry/scene.h"

namespace vdc {
namespace {

using test::cameraFromWorld;
using test::placed;

// The table top of every rendered scene [m] (fixed frame, z up).
constexpr double kTable = 0.7;
// Where the camera looks: the middle of the objects on the table.
const Eigen::Vector3d kTarget(0.4, 0.0, kTable + 0.06);

// A rendered scene and which of its parts each object is.
struct RenderedScene {
  Scene scene;
  Eigen::Isometry3d camera_from_world = Eigen::Isometry3d::Identity();
  pcl::PointCloud<pcl::PointXYZ> cloud;  // organised 640 x 480, NaN where nothing is hit
};

ScenePart part(const TriangleMesh& mesh, double x, double y, double yaw = 0.0) {
  return {mesh, placed(Eigen::Vector3d(x, y, kTable), yaw)};
}

// The parts as objects on a 1.4 x 1 m table (or none), seen from `direction` at 0.8 m with a
// Kinect's depth noise (fixed seed). The first part is the scene's object, which sets the table
// height: all parts stand on z = kTable.
RenderedScene render(const std::vector<ScenePart>& parts, bool table,
                     const Eigen::Vector3d& direction = Eigen::Vector3d(1, 0.25, 0.8)) {
  RenderedScene rendered;
  rendered.scene.object = parts.front();
  rendered.scene.distractors.assign(parts.begin() + 1, parts.end());
  if (table) rendered.scene.table_size = Eigen::Vector2d(1.4, 1.0);
  rendered.camera_from_world = cameraFromWorld(direction, 0.8, kTarget);
  std::mt19937 rng(11);
  rendered.cloud = DepthRenderer(sceneMesh(rendered.scene))
                       .render(rendered.camera_from_world, DepthNoiseModel{}, &rng);
  return rendered;
}

std::vector<ScenePart> objectsOf(const RenderedScene& rendered) {
  std::vector<ScenePart> objects{rendered.scene.object};
  objects.insert(objects.end(), rendered.scene.distractors.begin(),
                 rendered.scene.distractors.end());
  return objects;
}

// Whether a point (camera frame) lies on the part: inside its box, grown by 3 mm for the noise,
// and above the 8 mm band over the table (if any) that segmentation leaves to the table.
bool onPart(const RenderedScene& rendered, const ScenePart& object, const pcl::PointXYZ& p) {
  const Eigen::Vector3d local =
      object.world_from_part.inverse() *
      (rendered.camera_from_world.inverse() * p.getVector3fMap().cast<double>());
  Eigen::AlignedBox3d box = object.mesh.bounds().cast<double>();
  box.min() -= Eigen::Vector3d::Constant(0.003);
  box.max() += Eigen::Vector3d::Constant(0.003);
  // Without a table nothing is cut off at the bottom.
  const double lowest = rendered.scene.table_size ? 0.008 : -1.0;
  return box.contains(local) && local.z() > lowest;
}

// The truth: the centroid of the part's visible points (camera frame).
Eigen::Vector3d visibleCentroid(const RenderedScene& rendered, const ScenePart& object) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (const pcl::PointXYZ& p : rendered.cloud) {
    if (std::isfinite(p.z) && onPart(rendered, object, p)) {
      sum += p.getVector3fMap().cast<double>();
      ++count;
    }
  }
  return count ? Eigen::Vector3d(sum / count) : Eigen::Vector3d::Constant(NAN);
}

// Checks that the candidates are the objects, one each: the same number, every object's visible
// centroid within `tolerance` of one candidate's, and every candidate's points on its object.
void expectOneCandidatePerObject(const RenderedScene& rendered, const SceneSegments& segments,
                                 double tolerance = 0.01) {
  const std::vector<ScenePart> objects = objectsOf(rendered);
  ASSERT_EQ(segments.candidates.size(), objects.size()) << segments.note;
  std::vector<bool> taken(segments.candidates.size(), false);
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const Eigen::Vector3d truth = visibleCentroid(rendered, objects[o]);
    double nearest = std::numeric_limits<double>::infinity();
    std::size_t match = 0;
    for (std::size_t c = 0; c < segments.candidates.size(); ++c) {
      const double distance = (segments.candidates[c].centroid - truth).norm();
      if (distance < nearest) {
        nearest = distance;
        match = c;
      }
    }
    EXPECT_LT(nearest, tolerance) << "object " << o << " has no candidate at its centroid";
    EXPECT_FALSE(taken[match]) << "object " << o << " shares candidate " << match;
    taken[match] = true;
    int on = 0;
    const SceneCandidate& candidate = segments.candidates[match];
    for (const int i : candidate.indices) on += onPart(rendered, objects[o], rendered.cloud[i]);
    // Not a piece of the table, nor a merge with a neighbour.
    EXPECT_GT(on, 0.97 * candidate.pointCount()) << "candidate " << match << " of object " << o;
  }
}

// Four objects at least 12 cm apart: a milk-carton-like box, a can, a small cube, a flat box.
std::vector<ScenePart> objectsApart() {
  return {part(makeBoxMesh(Eigen::Vector3d(0.07, 0.07, 0.2)), 0.45, -0.12, 0.4),
          part(makeCylinderMesh(0.035, 0.12), 0.42, 0.1),
          part(makeBoxMesh(Eigen::Vector3d(0.05, 0.05, 0.05)), 0.28, -0.02, 0.2),
          part(makeBoxMesh(Eigen::Vector3d(0.12, 0.08, 0.04)), 0.6, 0.02, -0.3)};
}

pcl::PointCloud<pcl::PointXYZ> shuffledFinitePoints(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  pcl::PointCloud<pcl::PointXYZ> points;
  for (const pcl::PointXYZ& p : cloud) {
    if (std::isfinite(p.z)) points.push_back(p);
  }
  std::mt19937 rng(7);
  std::shuffle(points.begin(), points.end(), rng);
  return points;
}

double millisecondsOf(const std::chrono::steady_clock::time_point& start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

TEST(SceneSegmentation, FindsEachObjectOnTheTableAndNotTheTable) {
  const RenderedScene rendered = render(objectsApart(), true);
  const auto start = std::chrono::steady_clock::now();
  const SceneSegments segments = segmentScene(rendered.cloud, {});
  std::cout << "segmentScene on the rendered 640 x 480 scene: " << millisecondsOf(start) << " ms\n";
  EXPECT_TRUE(segments.organised);
  ASSERT_EQ(segments.planes.size(), 1u);
  const Eigen::Vector3d up = rendered.camera_from_world.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_GT(segments.planes[0].coefficients.head<3>().dot(up), 0.999);
  expectOneCandidatePerObject(rendered, segments);
  for (const SceneCandidate& candidate : segments.candidates) EXPECT_EQ(candidate.support, 0);
  EXPECT_EQ(segments.dropped_clusters, 0);
}

TEST(SceneSegmentation, DescribesACandidatesCentroidAndSidesLargestFirst) {
  // The carton-like box alone: its visible sides are its 20 cm height (less the band left to
  // the table) and its 7 cm faces seen at an angle (up to the 9.9 cm diagonal).
  const RenderedScene rendered = render({objectsApart().front()}, true);
  const SceneSegments segments = segmentScene(rendered.cloud, {});
  ASSERT_EQ(segments.candidates.size(), 1u) << segments.note;
  const SceneCandidate& box = segments.candidates[0];
  // Along the box's height, less the band, a little more where the axis leans into the diagonal.
  EXPECT_GT(box.extent(0), 0.185);
  EXPECT_LT(box.extent(0), 0.215);
  EXPECT_GE(box.extent(0), box.extent(1));
  EXPECT_GE(box.extent(1), box.extent(2));
  EXPECT_GT(box.extent(1), 0.05);
  EXPECT_LT(box.extent(1), 0.105);
  const Eigen::Vector3d up = rendered.camera_from_world.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_GT(std::abs(box.axes.col(0).dot(up)), 0.98);  // the longest side is the upright one
  EXPECT_NEAR(box.axes.determinant(), 1.0, 1e-9);
  EXPECT_TRUE(std::is_sorted(box.indices.begin(), box.indices.end()));
}

// Two boxes side by side, faces touching, different sizes and turned against each other: one
// cluster of points that only the concave edges between them separate.
std::vector<ScenePart> twoTouchingBoxes() {
  return {part(makeBoxMesh(Eigen::Vector3d(0.1, 0.08, 0.12)), 0.4, -0.04),
          part(makeBoxMesh(Eigen::Vector3d(0.08, 0.08, 0.18)), 0.39, 0.04)};
}

// A can touching a box's side.
std::vector<ScenePart> canTouchingABox() {
  return {part(makeBoxMesh(Eigen::Vector3d(0.1, 0.08, 0.12)), 0.4, -0.04),
          part(makeCylinderMesh(0.04, 0.15), 0.4, 0.04)};
}

TEST(SceneSegmentation, SeparatesTouchingObjectsAtTheirConcaveEdges) {
  for (const auto& [name, parts] : {std::pair{"two boxes", twoTouchingBoxes()},
                                    std::pair{"a can and a box", canTouchingABox()}}) {
    SCOPED_TRACE(name);
    const RenderedScene rendered = render(parts, true);
    SceneSegmentationParameters parameters;
    parameters.split_touching = false;
    // Without splitting they are one cluster: the scene does test the split.
    EXPECT_EQ(segmentScene(rendered.cloud, parameters).candidates.size(), 1u);
    parameters.split_touching = true;
    const SceneSegments split = segmentScene(rendered.cloud, parameters);
    expectOneCandidatePerObject(rendered, split);
    // The two parts remember that they touch: one cluster, and together its points.
    ASSERT_EQ(split.candidates.size(), 2u);
    EXPECT_GE(split.candidates[0].cluster, 0);
    EXPECT_EQ(split.candidates[0].cluster, split.candidates[1].cluster);
    const SceneCandidate whole =
        mergedCandidate(rendered.cloud, {&split.candidates[0], &split.candidates[1]});
    EXPECT_EQ(whole.pointCount(),
              split.candidates[0].pointCount() + split.candidates[1].pointCount());
    EXPECT_TRUE(std::is_sorted(whole.indices.begin(), whole.indices.end()));
    EXPECT_GT(whole.extent(0), split.candidates[0].extent(0));
  }
}

TEST(SceneSegmentation, ObjectsApartAreClustersOfTheirOwn) {
  const SceneSegments segments = segmentScene(render(objectsApart(), true).cloud, {});
  std::vector<int> clusters;
  for (const SceneCandidate& candidate : segments.candidates) clusters.push_back(candidate.cluster);
  std::sort(clusters.begin(), clusters.end());
  EXPECT_EQ(std::adjacent_find(clusters.begin(), clusters.end()), clusters.end());
  EXPECT_GE(clusters.front(), 0);
}

TEST(SceneSegmentation, ATableSplitByALongBoxIsStillOneSupport) {
  // A long low box across the table cuts the table's image into a strip before it and one
  // behind it, each narrower than min_plane_width here though the table is not: joined as one
  // plane, they are the support, and the box and the can beside it are found on it.
  const RenderedScene rendered =
      render({part(makeBoxMesh(Eigen::Vector3d(0.06, 1.4, 0.12)), 0.4, 0.0),
              part(makeCylinderMesh(0.04, 0.15), 0.55, 0.2)},
             true);
  SceneSegmentationParameters parameters;
  parameters.min_plane_width = 0.45;
  const SceneSegments segments = segmentScene(rendered.cloud, parameters);
  ASSERT_EQ(segments.planes.size(), 1u) << segments.note;
  const Eigen::Vector3d up = rendered.camera_from_world.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_GT(segments.planes[0].coefficients.head<3>().dot(up), 0.999);
  EXPECT_EQ(segments.dropped_clusters, 0) << segments.note;
  EXPECT_EQ(segments.candidates.size(), 2u) << segments.note;
}

TEST(SceneSegmentation, AnUnorganisedCloudGivesTheSameCandidates) {
  for (const auto& parts : {objectsApart(), canTouchingABox()}) {
    const RenderedScene rendered = render(parts, true);
    const SceneSegments organised = segmentScene(rendered.cloud, {});
    const pcl::PointCloud<pcl::PointXYZ> points = shuffledFinitePoints(rendered.cloud);
    const SceneSegments unorganised = segmentScene(points, {});
    EXPECT_FALSE(unorganised.organised);
    ASSERT_EQ(unorganised.planes.size(), 1u);
    EXPECT_GT(unorganised.planes[0].coefficients.head<3>().dot(
                  organised.planes.at(0).coefficients.head<3>()),
              0.9999);
    ASSERT_EQ(unorganised.candidates.size(), organised.candidates.size()) << unorganised.note;
    for (const SceneCandidate& candidate : organised.candidates) {
      double nearest = std::numeric_limits<double>::infinity();
      const SceneCandidate* match = nullptr;
      for (const SceneCandidate& other : unorganised.candidates) {
        if ((other.centroid - candidate.centroid).norm() < nearest) {
          nearest = (other.centroid - candidate.centroid).norm();
          match = &other;
        }
      }
      EXPECT_LT(nearest, 0.005);
      EXPECT_NEAR(match->pointCount(), candidate.pointCount(), 0.05 * candidate.pointCount());
      EXPECT_EQ(match->support, 0);
    }
  }
}

TEST(SceneSegmentation, WithoutATableInViewTheObjectsAreStillFound) {
  const RenderedScene rendered = render(objectsApart(), false);
  const SceneSegments segments = segmentScene(rendered.cloud, {});
  EXPECT_TRUE(segments.planes.empty());
  expectOneCandidatePerObject(rendered, segments);
  for (const SceneCandidate& candidate : segments.candidates) EXPECT_EQ(candidate.support, -1);
}

TEST(SceneSegmentation, CloudsWithoutObjectsGiveNoCandidatesAndDoNotThrow) {
  pcl::PointCloud<pcl::PointXYZ> empty;
  pcl::PointCloud<pcl::PointXYZ> all_nan(640, 480, pcl::PointXYZ(NAN, NAN, NAN));
  pcl::PointCloud<pcl::PointXYZ> one_point;
  one_point.push_back(pcl::PointXYZ(0.1f, 0.2f, 0.8f));
  pcl::PointCloud<pcl::PointXYZ> small_organised(3, 2, pcl::PointXYZ(0.1f, 0.2f, 0.8f));
  for (const auto* cloud : {&empty, &all_nan, &one_point, &small_organised}) {
    SceneSegments segments;
    EXPECT_NO_THROW(segments = segmentScene(*cloud, {}));
    EXPECT_TRUE(segments.candidates.empty());
    EXPECT_FALSE(segments.note.empty());
  }
  // The table alone: a support plane and nothing on it.
  const RenderedScene table_only = render(
      {{makeRectangleMesh(Eigen::Vector2d(1.4, 1.0)), placed(Eigen::Vector3d(0.4, 0, kTable))}},
      false);
  const SceneSegments segments = segmentScene(table_only.cloud, {});
  EXPECT_EQ(segments.planes.size(), 1u);
  EXPECT_TRUE(segments.candidates.empty());
  EXPECT_NE(segments.note.find("stands on the support plane"), std::string::npos) << segments.note;
}

TEST(SceneSegmentation, InvalidParametersThrowNamingTheFirstBadOne) {
  const auto expectRejected = [](const char* name, auto change) {
    SceneSegmentationParameters parameters;
    change(parameters);
    try {
      segmentScene(pcl::PointCloud<pcl::PointXYZ>(), parameters);
      ADD_FAILURE() << name << " was accepted";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
    }
  };
  expectRejected("depth_tolerance_growth", [](auto& p) { p.depth_tolerance_growth = -0.001; });
  expectRejected("depth_tolerance_growth", [](auto& p) { p.depth_tolerance_growth = NAN; });
  expectRejected("plane_distance", [](auto& p) { p.plane_distance = -0.01; });
  expectRejected("plane_distance", [](auto& p) { p.plane_distance = NAN; });
  expectRejected("min_plane_points", [](auto& p) { p.min_plane_points = 0; });
  expectRejected("plane_angle_deg", [](auto& p) { p.plane_angle_deg = 95; });
  expectRejected("max_height_above_plane", [](auto& p) { p.max_height_above_plane = 0.005; });
  expectRejected("cluster_tolerance", [](auto& p) { p.cluster_tolerance = 0; });
  expectRejected("min_cluster_points", [](auto& p) { p.min_cluster_points = 0; });
  expectRejected("max_cluster_points", [](auto& p) { p.max_cluster_points = 10; });
  expectRejected("max_candidates", [](auto& p) { p.max_candidates = 0; });
  expectRejected("supervoxel_seed", [](auto& p) { p.supervoxel_seed = 0.001; });
  expectRejected("concavity_tolerance_deg", [](auto& p) { p.concavity_tolerance_deg = -1; });
  expectRejected("min_part_fraction", [](auto& p) { p.min_part_fraction = 0.8; });
  // The first bad one is named when several are.
  expectRejected("plane_distance", [](auto& p) {
    p.plane_distance = 0;
    p.max_candidates = 0;
  });
  EXPECT_NO_THROW(checkSceneSegmentationParameters({}));
}

TEST(SceneSegmentation, KeepsTheLargestCandidatesUpToTheCapAndCountsTheRest) {
  const RenderedScene rendered = render(objectsApart(), true);
  const SceneSegments all = segmentScene(rendered.cloud, {});
  ASSERT_EQ(all.candidates.size(), 4u) << all.note;
  SceneSegmentationParameters parameters;
  parameters.max_candidates = 2;
  const SceneSegments capped = segmentScene(rendered.cloud, parameters);
  ASSERT_EQ(capped.candidates.size(), 2u);
  EXPECT_EQ(capped.dropped_clusters, 2);
  EXPECT_NE(capped.note.find("max_candidates"), std::string::npos) << capped.note;
  for (std::size_t c = 0; c < 2; ++c)
    EXPECT_EQ(capped.candidates[c].indices, all.candidates[c].indices);
  // A cap on the points per cluster drops the large ones.
  parameters = {};
  parameters.max_cluster_points = all.candidates[1].pointCount() - 1;
  const SceneSegments small_only = segmentScene(rendered.cloud, parameters);
  EXPECT_EQ(small_only.candidates.size(), 2u);
  EXPECT_EQ(small_only.dropped_clusters, 2);
  EXPECT_NE(small_only.note.find("max_cluster_points"), std::string::npos) << small_only.note;
}

// The sides of the points' box along their principal axes, largest first.
Eigen::Vector3d principalSides(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  SceneSegmentationParameters everything;
  everything.max_support_planes = 0;
  everything.split_touching = false;
  everything.cluster_tolerance = 0.05;
  everything.max_cluster_points = std::numeric_limits<int>::max();
  const SceneSegments segments = segmentScene(cloud, everything);
  return segments.candidates.empty() ? Eigen::Vector3d::Zero() : segments.candidates[0].extent;
}

// The index of each point's nearest scene point (KdTreeFLANN skips the scene's NaNs and returns
// indices into the whole organised cloud); *farthest is the largest of those distances [m].
std::vector<int> nearestSceneIndices(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& scene,
                                     const pcl::PointCloud<pcl::PointXYZ>& points,
                                     double* farthest) {
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(scene);
  std::vector<int> nearest(points.size(), -1), found(1);
  std::vector<float> squared(1);
  *farthest = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (tree.nearestKSearch(points[k], 1, found, squared) != 1) continue;
    nearest[k] = found[0];
    *farthest = std::max(*farthest, std::sqrt(static_cast<double>(squared[0])));
  }
  return nearest;
}

// The candidate holding most of the scene points at `indices` (-1: none holds any), and how many.
std::pair<int, int> candidateHoldingMost(const SceneSegments& segments,
                                         const std::vector<int>& indices) {
  std::pair<int, int> best{-1, 0};
  for (std::size_t c = 0; c < segments.candidates.size(); ++c) {
    const std::vector<int>& held = segments.candidates[c].indices;  // ascending
    const auto count = std::count_if(indices.begin(), indices.end(), [&](int i) {
      return std::binary_search(held.begin(), held.end(), i);
    });
    if (count > best.second) best = {static_cast<int>(c), static_cast<int>(count)};
  }
  return best;
}

// segmentScene with the defaults (not tolerances tuned to the scene), its time printed and
// recorded under `name` (not asserted: machines differ).
SceneSegments segmentTimed(const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::string& name) {
  const auto start = std::chrono::steady_clock::now();
  const SceneSegments segments = segmentScene(cloud, {});
  const double milliseconds = millisecondsOf(start);
  std::string key = "segment_scene_" + name + "_ms";
  std::replace(key.begin(), key.end(), ' ', '_');
  ::testing::Test::RecordProperty(key, std::to_string(milliseconds));
  std::cout << "segmentScene on the " << name << " (" << cloud.width << " x " << cloud.height
            << ", defaults): " << milliseconds << " ms, " << segments.planes.size() << " plane(s), "
            << segments.candidates.size() << " candidates\n";
  for (const SupportPlane& plane : segments.planes) {
    std::cout << "  plane " << plane.coefficients.transpose() << " with " << plane.inliers
              << " points\n";
  }
  for (const SceneCandidate& candidate : segments.candidates) {
    std::cout << "  " << candidate.pointCount() << " points at " << candidate.centroid.transpose()
              << ", sides " << candidate.extent.transpose() << ", support " << candidate.support
              << "\n";
  }
  return segments;
}

// The candidate holding most of the carton's points holds at least 80 % of them, at most 20 % of
// its points are others, and its sides are the carton's.
void expectOneCandidateHoldsTheCarton(const SceneSegments& segments,
                                      const std::vector<int>& carton_indices,
                                      const Eigen::Vector3d& carton_sides) {
  const auto [match, held] = candidateHoldingMost(segments, carton_indices);
  ASSERT_GE(match, 0) << "no candidate holds a carton point";
  const SceneCandidate& candidate = segments.candidates[static_cast<std::size_t>(match)];
  const int others = candidate.pointCount() - held;
  std::cout << "  the carton's candidate " << match << " holds " << held << " of its "
            << carton_indices.size() << " points, and " << others << " others\n";
  EXPECT_GE(held, 0.8 * static_cast<double>(carton_indices.size()));
  // The others (8-9 %) lie 22-25 cm above the table, over the carton and above most of
  // milk.pcd's points: most likely the carton's own top, which the tutorial's cut left out. No
  // neighbour is merged in.
  EXPECT_LE(others, 0.2 * candidate.pointCount());
  // The longest side may be a little longer for that top.
  EXPECT_LT((candidate.extent - carton_sides).cwiseAbs().maxCoeff(), 0.03)
      << candidate.extent.transpose() << " vs the carton's " << carton_sides.transpose();
}

// The cloud's finite points, unorganised, and where each of the cloud's points went (-1: NaN).
pcl::PointCloud<pcl::PointXYZ> finitePoints(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                            std::vector<int>* moved_to) {
  pcl::PointCloud<pcl::PointXYZ> points;
  moved_to->assign(cloud.size(), -1);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!std::isfinite(cloud[i].z)) continue;
    (*moved_to)[i] = static_cast<int>(points.size());
    points.push_back(cloud[i]);
  }
  return points;
}

TEST(SceneSegmentation, RealKinectSceneWithDefaultsHasTheCartonAsOneCandidate) {
  const std::string scene_path = test::milkScenePath(), carton_path = test::milkCartonPath();
  if (!std::filesystem::exists(scene_path) || !std::filesystem::exists(carton_path)) {
    GTEST_SKIP() << "PCL's milk scene is not at " << scene_path
                 << " (with milk.pcd): " << test::kMilkSceneMissing;
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr scene(new pcl::PointCloud<pcl::PointXYZ>);
  pcl::PointCloud<pcl::PointXYZ> carton;
  ASSERT_EQ(pcl::io::loadPCDFile(scene_path, *scene), 0) << scene_path;
  ASSERT_EQ(pcl::io::loadPCDFile(carton_path, carton), 0) << carton_path;
  double farthest = 0.0;
  const std::vector<int> carton_indices =
      nearestSceneIndices(scene, test::cartonInSceneFrame(carton), &farthest);
  ASSERT_LT(farthest, 1e-4) << "milk.pcd, moved, is not made of the scene's points";
  const Eigen::Vector3d carton_sides = principalSides(carton);

  // A Kinect 0.6 to 2 m away: the depth-dependent tolerances must hold the table and the carton.
  const SceneSegments segments = segmentTimed(*scene, "milk scene");
  ASSERT_TRUE(segments.organised);
  ASSERT_GE(segments.planes.size(), 1u);
  EXPECT_GE(segments.candidates.size(), 3u);
  expectOneCandidateHoldsTheCarton(segments, carton_indices, carton_sides);

  // The same points unorganised (RANSAC, Euclidean clusters). RANSAC's second support is a plane
  // 2.4 degrees off the table through the feet of the near objects (1-5 cm up) and the far
  // table; its band takes ~1100 of the carton's lowest points, so the candidate holds ~86 % of
  // the carton here, not ~99 %.
  std::vector<int> moved_to;
  const pcl::PointCloud<pcl::PointXYZ> points = finitePoints(*scene, &moved_to);
  std::vector<int> moved_carton;
  for (const int i : carton_indices) moved_carton.push_back(moved_to[static_cast<std::size_t>(i)]);
  const SceneSegments unorganised = segmentTimed(points, "milk scene unorganised");
  EXPECT_FALSE(unorganised.organised);
  expectOneCandidateHoldsTheCarton(unorganised, moved_carton, carton_sides);
}

// The candidates' point counts and centroids, in order: what tells one cut of a scene from another.
std::vector<std::pair<int, Eigen::Vector3d>> cutOf(const SceneSegments& segments) {
  std::vector<std::pair<int, Eigen::Vector3d>> cut;
  for (const SceneCandidate& candidate : segments.candidates) {
    cut.emplace_back(candidate.pointCount(), candidate.centroid);
  }
  return cut;
}

// PCL's LCCP walks its graph in the order of its vertices' heap addresses (boost setS) when it
// merges small segments and numbers them: the same cloud was cut differently depending on what
// the process had allocated before (one scene of the scene evaluation had 17 or 18 candidates
// depending on the scenes run before it). Blocks of seeded random sizes, every other one freed,
// lay the heap out differently before each cut. With LCCP's own merging, two of these four cuts
// of this crowd of touching objects had 6 candidates instead of 5.
TEST(SceneSegmentation, TheSameCloudIsCutTheSameWhateverWasAllocatedBefore) {
  const std::vector<ScenePart> crowd = {
      part(makeMug(), 0.4, 0.0, 0.3),
      part(makeBoxMesh(Eigen::Vector3d(0.1, 0.08, 0.12)), 0.4, -0.085, 0.1),
      part(makeCylinderMesh(0.035, 0.15), 0.4, 0.08), part(makeMug(), 0.48, 0.03, 2.0),
      part(makeBoxMesh(Eigen::Vector3d(0.06, 0.06, 0.05)), 0.33, 0.05, 0.7)};
  const RenderedScene rendered = render(crowd, true, Eigen::Vector3d(1, -0.4, 0.6));
  const auto first = cutOf(segmentScene(rendered.cloud, {}));
  ASSERT_GE(first.size(), 4u);
  std::mt19937 rng(3);
  std::vector<std::vector<char>> kept;
  for (int round = 0; round < 4; ++round) {
    for (int block = 0; block < 20000; ++block) {
      kept.emplace_back(std::uniform_int_distribution<std::size_t>(8, 600)(rng));
      if (block % 2 == 1) kept[kept.size() - 2] = std::vector<char>();
    }
    const auto again = cutOf(segmentScene(rendered.cloud, {}));
    ASSERT_EQ(again.size(), first.size()) << "round " << round;
    for (std::size_t c = 0; c < first.size(); ++c) {
      EXPECT_EQ(again[c].first, first[c].first) << "round " << round << ", candidate " << c;
      EXPECT_TRUE(again[c].second.isApprox(first[c].second)) << "round " << round;
    }
  }
}

}  // namespace
}  // namespace vdc

namespace vdc {
namespace {

// Found by the fuzz target: a finite point at 1e38 m overflowed the voxel keys (undefined
// behaviour). A coordinate no depth camera measures is no point.
TEST(SceneSegmentationFarPoints, APointFarBeyondAnyCameraIsNoPoint) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) cloud.push_back(pcl::PointXYZ(0.003f * i, 0.003f * j, 0.8f));
  }
  cloud.push_back(pcl::PointXYZ(1e38f, 0.0f, 1.0f));
  cloud.push_back(pcl::PointXYZ(0.0f, -3e37f, 2000.0f));
  SceneSegmentationParameters parameters;
  parameters.split_touching = false;
  const SceneSegments segments = segmentScene(cloud, parameters);
  ASSERT_EQ(segments.candidates.size(), 1u) << segments.note;
  EXPECT_EQ(segments.candidates[0].indices.size(), 100u);
  EXPECT_LT(segments.candidates[0].indices.back(), 100);
  // Counted as points, the two far ones would make 102 finite points, enough for clusters of
  // 101: the cloud has 100.
  parameters.min_cluster_points = 101;
  const SceneSegments too_few = segmentScene(cloud, parameters);
  EXPECT_TRUE(too_few.candidates.empty());
  EXPECT_NE(too_few.note.find("fewer finite points (100)"), std::string::npos) << too_few.note;
}

}  // namespace
}  // namespace vdc
