#include "view_direction_classification/geometry/surface_sampling.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/geometry_test_meshes.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

TEST(SurfaceSampling, SampleCountIsAreaOverSpacingSquared) {
  const TriangleMesh mug = makeMug();
  const double spacing = 0.002;
  const SurfaceSamples samples = sampleSurface(mug, spacing, 1);
  EXPECT_EQ(samples.size(), static_cast<std::size_t>(std::llround(mug.area() / 4e-6)));
  EXPECT_EQ(samples.normals.size(), samples.size());
}

TEST(SurfaceSampling, LocalDensityMatchesOneOverSpacingSquared) {
  // A 20 cm square sampled at 2 mm: every 4 x 4 cm window should hold 400 points.
  const SurfaceSamples samples = sampleSurface(test::makeSquare(0.2f, 0.0f), 0.002, 3);
  int counts[5][5] = {};
  for (const auto& p : samples.points) {
    const int i = std::min(4, static_cast<int>((p.x() + 0.1) / 0.04));
    const int j = std::min(4, static_cast<int>((p.y() + 0.1) / 0.04));
    counts[i][j]++;
  }
  for (const auto& row : counts) {
    for (int count : row) EXPECT_NEAR(count, 400, 0.04 * 400);
  }
}

TEST(SurfaceSampling, DensityIsUniformAcrossFacesOfDifferentSizes) {
  // Faces of 4, 8 and 16 cm^2 (times two): each pair must get its share of the samples.
  const TriangleMesh box = test::makeBox({0.01f, 0.02f, 0.04f});
  const SurfaceSamples samples = sampleSurface(box, 0.001, 5);
  double on_x = 0, on_y = 0, on_z = 0;
  for (const auto& n : samples.normals) {
    on_x += std::abs(n.x()) > 0.5;
    on_y += std::abs(n.y()) > 0.5;
    on_z += std::abs(n.z()) > 0.5;
  }
  const double per_area = samples.size() / box.area();
  EXPECT_NEAR(on_x / per_area, 2 * 0.04 * 0.08, 0.02 * 2 * 0.04 * 0.08);
  EXPECT_NEAR(on_y / per_area, 2 * 0.02 * 0.08, 0.02 * 2 * 0.02 * 0.08);
  EXPECT_NEAR(on_z / per_area, 2 * 0.02 * 0.04, 0.02 * 2 * 0.02 * 0.04);
}

TEST(SurfaceSampling, EverySampleLiesOnATriangleWhoseNormalItCarries) {
  const TriangleMesh mug = makeMug();
  const SurfaceSamples samples = sampleSurface(mug, 0.004, 7);
  for (std::size_t i = 0; i < samples.size(); i += 25) {
    const Eigen::Vector3d p = samples.points[i].cast<double>();
    const Eigen::Vector3f& n = samples.normals[i];
    EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
    // A sample on an edge touches several triangles: one of them must carry its normal.
    bool on_matching_triangle = false;
    for (std::size_t t = 0; t < mug.triangles.size() && !on_matching_triangle; ++t) {
      const auto& tri = mug.triangles[t];
      const double distance = test::pointTriangleDistance(p, mug.vertices[tri[0]].cast<double>(),
                                                          mug.vertices[tri[1]].cast<double>(),
                                                          mug.vertices[tri[2]].cast<double>());
      on_matching_triangle = distance < 1e-6 && n.isApprox(mug.triangleNormal(t), 1e-4f);
    }
    EXPECT_TRUE(on_matching_triangle) << "sample " << i << " at " << p.transpose();
  }
}

TEST(SurfaceSampling, NormalsAreUnitAndPointOutOfAClosedSphere) {
  const SurfaceSamples samples = sampleSurface(test::makeSphere(0.05f, 3), 0.002, 11);
  ASSERT_GT(samples.size(), 1000u);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_NEAR(samples.normals[i].norm(), 1.0f, 1e-5f);
    EXPECT_GT(samples.normals[i].dot(samples.points[i].normalized()), 0.98f);
  }
}

TEST(SurfaceSampling, SameSeedGivesSameSamplesAndOtherSeedDiffers) {
  const TriangleMesh mug = makeMug();
  const SurfaceSamples a = sampleSurface(mug, 0.003, 42);
  const SurfaceSamples b = sampleSurface(mug, 0.003, 42);
  const SurfaceSamples c = sampleSurface(mug, 0.003, 43);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), c.size());
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, c.points);
}

TEST(SurfaceSampling, StratificationKeepsNeighboursApart) {
  // Independent uniform draws put many pairs of points almost on top of each other; strata of
  // about one spacing squared hold one point each and keep such pairs rare.
  const SurfaceSamples samples = sampleSurface(test::makeSquare(0.06f, 0.0f), 0.002, 9);
  std::size_t close_pairs = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    for (std::size_t j = i + 1; j < samples.size(); ++j) {
      if ((samples.points[i] - samples.points[j]).norm() < 0.0002f) ++close_pairs;
    }
  }
  // For a Poisson process: expected close pairs = N^2 / 2 * pi r^2 / A = N * pi * 0.01 / 2.
  const double poisson = samples.size() * M_PI * 0.01 / 2.0;
  EXPECT_LT(close_pairs, 0.6 * poisson);
}

TEST(SurfaceSampling, BadInputsThrow) {
  const TriangleMesh square = test::makeSquare(0.1f, 0.0f);
  EXPECT_THROW(sampleSurface(square, 0.0, 1), Error);
  EXPECT_THROW(sampleSurface(square, -0.002, 1), Error);
  EXPECT_THROW(sampleSurface(square, std::nan(""), 1), Error);
  EXPECT_THROW(sampleSurface(TriangleMesh(), 0.002, 1), Error);
  EXPECT_THROW(sampleSurface(test::makeSquare(1000.0f, 0.0f), 1e-4, 1), Error);  // 1e14 points
  TriangleMesh broken = square;
  broken.triangles.emplace_back(0, 1, 5);
  EXPECT_THROW(sampleSurface(broken, 0.002, 1), Error);
}

}  // namespace
}  // namespace vdc
