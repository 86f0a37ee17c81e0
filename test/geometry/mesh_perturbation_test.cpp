#include "view_direction_classification/geometry/mesh_perturbation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

MeshPerturbation dents(int count, double depth, std::uint32_t seed = 3) {
  MeshPerturbation perturbation;
  perturbation.dents = count;
  perturbation.dent_depth = depth;
  perturbation.seed = seed;
  return perturbation;
}

// The largest distance any vertex moved.
double largestShift(const TriangleMesh& before, const TriangleMesh& after) {
  double largest = 0.0;
  for (std::size_t v = 0; v < before.vertices.size(); ++v) {
    largest = std::max(largest, double((after.vertices[v] - before.vertices[v]).norm()));
  }
  return largest;
}

TEST(MeshPerturbationTest, TheIdentityLeavesEveryVertexExactlyWhereItWas) {
  const TriangleMesh mug = makeMug();
  const MeshPerturbation identity;
  EXPECT_FALSE(identity.any());
  const TriangleMesh same = perturbMesh(mug, identity);
  ASSERT_EQ(same.vertices.size(), mug.vertices.size());
  for (std::size_t v = 0; v < mug.vertices.size(); ++v) {
    EXPECT_EQ(same.vertices[v], mug.vertices[v]);
  }
  EXPECT_EQ(same.triangles, mug.triangles);
  // Dents of depth 0 are no perturbation either.
  EXPECT_FALSE(dents(4, 0.0).any());
}

TEST(MeshPerturbationTest, AScaledMeshHasTheRequestedExtentsPerAxis) {
  const TriangleMesh mug = makeMug();
  MeshPerturbation perturbation;
  perturbation.scale = Eigen::Vector3d(1.0, 0.9, 1.03);
  const TriangleMesh scaled = perturbMesh(mug, perturbation);
  const Eigen::AlignedBox3f before = mug.bounds();
  const Eigen::AlignedBox3f after = scaled.bounds();
  for (int k = 0; k < 3; ++k) {
    const double s = perturbation.scale(k);
    EXPECT_NEAR(after.min()(k), s * before.min()(k), 1e-6) << "axis " << k;
    EXPECT_NEAR(after.max()(k), s * before.max()(k), 1e-6) << "axis " << k;
  }
  EXPECT_EQ(scaled.triangles, mug.triangles);
}

TEST(MeshPerturbationTest, DentsMoveVerticesInwardByAtMostTheDepth) {
  const TriangleMesh mug = makeMug();
  const double depth = 0.002;
  const TriangleMesh dented = perturbMesh(mug, dents(6, depth));
  const double largest = largestShift(mug, dented);
  EXPECT_LE(largest, depth + 1e-6);
  // The dents are there: some vertex moved by most of the depth.
  EXPECT_GT(largest, 0.5 * depth);
  // Inward: the enclosed volume shrinks.
  EXPECT_LT(dented.signedVolume(), mug.signedVolume());
}

TEST(MeshPerturbationTest, DentsAreDeterministicPerSeedAndPlacedDifferentlyForAnother) {
  const TriangleMesh mug = makeMug();
  const TriangleMesh a = perturbMesh(mug, dents(3, 0.002, 1));
  const TriangleMesh again = perturbMesh(mug, dents(3, 0.002, 1));
  const TriangleMesh b = perturbMesh(mug, dents(3, 0.002, 2));
  EXPECT_EQ(largestShift(a, again), 0.0);
  EXPECT_GT(largestShift(a, b), 0.0);
}

TEST(MeshPerturbationTest, BadValuesAreRefusedWithTheirName) {
  const TriangleMesh mug = makeMug();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto expectRefused = [&mug](const MeshPerturbation& p, const std::string& words) {
    try {
      perturbMesh(mug, p);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
    }
  };
  MeshPerturbation p;
  p.scale = Eigen::Vector3d(1.0, 0.0, 1.0);
  expectRefused(p, "scale");
  p.scale = Eigen::Vector3d(1.0, -1.0, 1.0);
  expectRefused(p, "scale");
  p.scale = Eigen::Vector3d(nan, 1.0, 1.0);
  expectRefused(p, "scale");
  p.scale = Eigen::Vector3d(1.0, 1.0, 1e30);
  expectRefused(p, "scale");
  expectRefused(dents(-1, 0.001), "number of mesh dents");
  expectRefused(dents(2, -0.001), "depth");
  expectRefused(dents(2, nan), "depth");
  MeshPerturbation radius = dents(2, 0.001);
  radius.dent_radius = std::numeric_limits<double>::infinity();
  expectRefused(radius, "radius");
}

}  // namespace
}  // namespace vdc
