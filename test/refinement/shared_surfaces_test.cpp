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
