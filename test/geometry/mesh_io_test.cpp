#include "view_direction_classification/geometry/mesh_io.h"

#include <gtest/gtest.h>
#include <pcl/PolygonMesh.h>
#include <pcl/io/ply_io.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/geometry_test_meshes.h"
#include "support/temporary_directory_test.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_check.h"

namespace vdc {
namespace {

namespace fs = std::filesystem;

class MeshIoTest : public test::TemporaryDirectoryTest {
 protected:
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path(name), std::ios::binary) << content;
    return path(name);
  }

  static std::string errorOf(const std::string& file) {
    try {
      loadMesh(file);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
};

// Unit cube as six quads: exercises triangulation and vertex joining.
constexpr const char* kCubeObj =
    "# unit cube\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 1 5 8 4\nf 2 3 7 6\n";

constexpr const char* kCubeOff =
    "OFF\n8 6 0\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 0 4 7 3\n4 1 2 6 5\n";

// Tetrahedron in ASCII STL: every facet repeats its vertices, as STL always does.
constexpr const char* kTetraStl =
    "solid tetra\n"
    "facet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n"
    " endloop\nendfacet\n"
    "facet normal 0 -1 0\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 0 1\n"
    " endloop\nendfacet\n"
    "facet normal -1 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0 1\n  vertex 0 1 0\n"
    " endloop\nendfacet\n"
    "facet normal 1 1 1\n outer loop\n  vertex 1 0 0\n  vertex 0 1 0\n  vertex 0 0 1\n"
    " endloop\nendfacet\n"
    "endsolid tetra\n";

void expectClosedUnitCube(const TriangleMesh& mesh) {
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_NEAR(mesh.area(), 6.0, 1e-6);
  EXPECT_NEAR(mesh.signedVolume(), 1.0, 1e-6);  // winding preserved: outward
  EXPECT_TRUE(checkMesh(mesh).watertight);
}

TEST_F(MeshIoTest, LoadsObjQuadsAsAClosedTriangleMesh) {
  expectClosedUnitCube(loadMesh(write("cube.obj", kCubeObj)));
}

TEST_F(MeshIoTest, LoadsOffQuadsAsAClosedTriangleMesh) {
  expectClosedUnitCube(loadMesh(write("cube.off", kCubeOff)));
}

TEST_F(MeshIoTest, LoadsStlAndJoinsItsRepeatedVertices) {
  const TriangleMesh mesh = loadMesh(write("tetra.stl", kTetraStl));
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_NEAR(mesh.signedVolume(), 1.0 / 6.0, 1e-6);
  EXPECT_TRUE(checkMesh(mesh).watertight);
}

// One triangle (normal +z) in a Z-up Collada scene, under a translated parent node and a mirrored
// child node.
constexpr const char* kTransformedTriangleDae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="tri"><mesh>
      <source id="pos"><float_array id="pos-array" count="9">0 0 0 1 0 0 0 1 0</float_array>
        <technique_common><accessor source="#pos-array" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="verts"><input semantic="POSITION" source="#pos"/></vertices>
      <triangles count="1"><input semantic="VERTEX" source="#verts" offset="0"/><p>0 1 2</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene">
      <node id="parent"><translate>0 0 2</translate>
        <node id="child"><scale>-1 1 1</scale><instance_geometry url="#tri"/></node>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";

TEST_F(MeshIoTest, AppliesNodeTransformsKeepsFileAxesAndMirroredFacesOutward) {
  const TriangleMesh mesh = loadMesh(write("triangle.dae", kTransformedTriangleDae));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  const Eigen::AlignedBox3f box = mesh.bounds();
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector3f(-1, 0, 2)));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector3f(0, 1, 2)));
  // A mirror image of a face with normal +z (mirrored in x) still faces +z.
  EXPECT_TRUE(mesh.triangleNormal(0).isApprox(Eigen::Vector3f::UnitZ()));
}

void expectSameMesh(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  // assimp may reorder vertices: compare each triangle's corner positions.
  for (std::size_t t = 0; t < a.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a.vertices[a.triangles[t][k]], b.vertices[b.triangles[t][k]])
          << "triangle " << t << " corner " << k;
    }
  }
}

TEST_F(MeshIoTest, BinaryPlyRoundTripPreservesEveryCornerExactly) {
  const TriangleMesh sphere = test::makeSphere(0.05f, 2);
  saveMeshPly(sphere, path("sphere.ply"));
  expectSameMesh(sphere, loadMesh(path("sphere.ply")));
}

TEST_F(MeshIoTest, AsciiPlyRoundTripPreservesEveryCornerExactly) {
  const TriangleMesh sphere = test::makeSphere(0.05f, 2);
  saveMeshPly(sphere, path("sphere_ascii.ply"), PlyEncoding::kAscii);
  std::ifstream in(path("sphere_ascii.ply"));
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(second, "format ascii 1.0");
  expectSameMesh(sphere, loadMesh(path("sphere_ascii.ply")));
}

TEST_F(MeshIoTest, WrittenPlyIsReadableByPcl) {
  const TriangleMesh sphere = test::makeSphere(0.05f, 1);
  for (const auto encoding : {PlyEncoding::kBinaryLittleEndian, PlyEncoding::kAscii}) {
    saveMeshPly(sphere, path("for_pcl.ply"), encoding);
    pcl::PolygonMesh loaded;
    ASSERT_EQ(pcl::io::loadPLYFile(path("for_pcl.ply"), loaded), 0);
    EXPECT_EQ(loaded.cloud.width * loaded.cloud.height, sphere.vertices.size());
    ASSERT_EQ(loaded.polygons.size(), sphere.triangles.size());
    for (std::size_t t = 0; t < sphere.triangles.size(); ++t) {
      ASSERT_EQ(loaded.polygons[t].vertices.size(), 3u);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(static_cast<int>(loaded.polygons[t].vertices[k]), sphere.triangles[t][k]);
      }
    }
  }
}

TEST_F(MeshIoTest, MissingFileIsRefusedNamingIt) {
  const std::string message = errorOf(path("nowhere.ply"));
  EXPECT_NE(message.find("nowhere.ply"), std::string::npos);
  EXPECT_NE(message.find("does not exist"), std::string::npos);
}

TEST_F(MeshIoTest, EmptyFileIsRefusedNamingIt) {
  const std::string message = errorOf(write("empty.stl", ""));
  EXPECT_NE(message.find("empty.stl"), std::string::npos);
  EXPECT_NE(message.find("empty"), std::string::npos);
}

TEST_F(MeshIoTest, GarbageFileIsRefusedNamingIt) {
  const std::string message = errorOf(write("garbage.ply", "this is not a mesh at all\n"));
  EXPECT_NE(message.find("garbage.ply"), std::string::npos);
}

TEST_F(MeshIoTest, DirectoryIsRefusedNamingIt) {
  fs::create_directories(directory() / "folder.obj");
  EXPECT_NE(errorOf(path("folder.obj")).find("folder.obj"), std::string::npos);
}

TEST_F(MeshIoTest, PointCloudWithoutFacesIsRefusedAsHavingNoTriangles) {
  const std::string cloud =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  const std::string message = errorOf(write("cloud.ply", cloud));
  EXPECT_NE(message.find("cloud.ply"), std::string::npos);
  EXPECT_NE(message.find("no triangles"), std::string::npos) << message;
}

TEST_F(MeshIoTest, ObjWithOnlyLinesIsRefusedAsHavingNoTriangles) {
  const std::string message = errorOf(write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n"));
  EXPECT_NE(message.find("lines.obj"), std::string::npos);
  EXPECT_NE(message.find("triangles"), std::string::npos) << message;
}

TEST_F(MeshIoTest, WritingIntoAMissingDirectoryThrowsNamingTheFile) {
  try {
    saveMeshPly(test::makeSquare(1.0f, 0.0f), path("no_such_dir/out.ply"));
    FAIL() << "expected vdc::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("out.ply"), std::string::npos);
  }
}

TEST_F(MeshIoTest, WritingAMeshWithInvalidIndicesThrows) {
  TriangleMesh mesh = test::makeSquare(1.0f, 0.0f);
  mesh.triangles.emplace_back(0, 1, 9);
  EXPECT_THROW(saveMeshPly(mesh, path("bad.ply")), Error);
}

}  // namespace
}  // namespace vdc
