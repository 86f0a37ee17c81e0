#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "distance_field.h"
#include "shared_surfaces.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/surface_sampling.h"

namespace vdc {
namespace {

// A bundle with the built-in mug's surface samples (nothing trained: refinement reads only
// these).
ModelBundle mugSurfaceBundle() {
  const TriangleMesh mesh = makeMug();
  const SurfaceSamples samples = sampleSurface(mesh, 0.002, 1);
  ModelBundle bundle;
  bundle.surface_points = samples.points;
  bundle.surface_normals = samples.normals;
  bundle.parameters.surface_spacing = 0.002;
  const Eigen::AlignedBox3f box = mesh.bounds();
  bundle.bounds = Eigen::AlignedBox3d(box.min().cast<double>(), box.max().cast<double>());
  return bundle;
}

TEST(TruncatedDistanceField, AgreesWithTheNearestSampleWithinOneAndAHalfMillimetresAndTruncates) {
  const ModelBundle bundle = mugSurfaceBundle();
  const ModelSurface surface(bundle.surface_points, bundle.surface_normals, bundle.bounds, 0.002,
                             0.004);
  const double truncation = 0.015;
  const TruncatedDistanceField& field = surface.distanceField(truncation);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> offset(-0.03f, 0.03f);
  const Eigen::Vector3f centre = bundle.bounds.center().cast<float>();
  int near = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3f p = centre + Eigen::Vector3f(offset(rng), offset(rng), offset(rng)) * 3;
    double exact = std::numeric_limits<double>::infinity();
    for (const auto& s : surface.cloud()->points) {
      exact = std::min(exact, static_cast<double>((s.getVector3fMap() - p).norm()));
    }
    exact = std::min(exact, truncation);
    EXPECT_NEAR(field.distance(p), exact, 0.0015) << p.transpose();
    if (exact < truncation) ++near;
  }
  EXPECT_GT(near, 200);  // the points did probe the surface's neighbourhood
  // Far off the grid: the truncation; the same truncation asked again: the same field.
  EXPECT_EQ(field.distance(Eigen::Vector3f(5.0f, 5.0f, 5.0f)), truncation);
  EXPECT_EQ(&surface.distanceField(truncation), &field);
}

// ICP's correspondences read the field's nodes' nearest samples instead of the k-d tree: nearly
// always the same sample, never one more than a cell's diagonal (2 mm cells here) farther, none
// reported beyond the distance and none missed but within a cell's diagonal of it.
TEST(TruncatedDistanceField, FindsTheKdTreesNearestSampleOrOneAtMostACellDiagonalFarther) {
  const ModelBundle bundle = mugSurfaceBundle();
  const ModelSurface surface(bundle.surface_points, bundle.surface_normals, bundle.bounds, 0.002,
                             0.004);
  const double max_distance = 0.015, cell_diagonal = 0.002 * std::sqrt(3.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> offset(-0.09f, 0.09f);
  const Eigen::Vector3f centre = bundle.bounds.center().cast<float>();
  std::vector<Eigen::Vector3f> queries;
  for (int i = 0; i < 20000; ++i) {
    queries.push_back(centre + Eigen::Vector3f(offset(rng), offset(rng), offset(rng)));
  }
  queries.push_back(Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN()));
  std::vector<int> exact, from_field;
  std::vector<float> exact_squared, field_squared;
  surface.nearest().search(queries, &exact, &exact_squared, max_distance);
  surface.nearestWithin(queries, &from_field, &field_squared, max_distance);
  ASSERT_EQ(from_field.size(), queries.size());
  int within = 0, same = 0;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    if (exact[q] < 0) {  // nothing within the distance: nothing from the field either
      EXPECT_LT(from_field[q], 0) << queries[q].transpose();
      continue;
    }
    ++within;
    if (from_field[q] < 0) {  // missed only at the edge, where a node's sample lies beyond it
      EXPECT_GT(std::sqrt(exact_squared[q]), max_distance - cell_diagonal);
      continue;
    }
    if (from_field[q] == exact[q]) ++same;
    EXPECT_LE(std::sqrt(field_squared[q]), max_distance);
    EXPECT_LE(std::sqrt(field_squared[q]), std::sqrt(exact_squared[q]) + cell_diagonal);
    const Eigen::Vector3f sample = surface.cloud()->points[from_field[q]].getVector3fMap();
    EXPECT_FLOAT_EQ((sample - queries[q]).squaredNorm(), field_squared[q]);
  }
  EXPECT_GT(within, 2000);  // the queries did probe the surface's neighbourhood
  EXPECT_GT(same, 0.97 * within);
  // A surface that keeps to its k-d tree answers exactly.
  const ModelSurface tree_only(bundle.surface_points, bundle.surface_normals, bundle.bounds, 0.002,
                               0.004, /*fields_for_nearest=*/false);
  std::vector<int> from_tree;
  std::vector<float> tree_squared;
  tree_only.nearestWithin(queries, &from_tree, &tree_squared, max_distance);
  EXPECT_EQ(from_tree, exact);
}

TEST(SharedModelSurface, RefinersOfOneBundleShareItsSurfaceWhileOneHoldsIt) {
  const ModelBundle bundle = mugSurfaceBundle();
  std::shared_ptr<const ModelSurface> first = sharedModelSurface(bundle, 0.004);
  EXPECT_EQ(sharedModelSurface(bundle, 0.004), first);
  EXPECT_NE(sharedModelSurface(bundle, 0.002), first);  // another spacing: another surface
  // Another bundle with other samples is not taken for this one.
  ModelBundle other = bundle;
  other.surface_points.pop_back();
  other.surface_normals.pop_back();
  EXPECT_NE(sharedModelSurface(other, 0.004), first);
  // Released by every holder, it is freed, and built anew when asked again.
  const std::weak_ptr<const ModelSurface> released = first;
  first.reset();
  EXPECT_TRUE(released.expired());
  const std::shared_ptr<const ModelSurface> again = sharedModelSurface(bundle, 0.004);
  ASSERT_NE(again, nullptr);
  EXPECT_EQ(again->size(), (bundle.surface_points.size() + 3) / 4);  // 2 mm thinned to 4 mm
}

}  // namespace
}  // namespace vdc
