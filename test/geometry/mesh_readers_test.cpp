// The mesh readers (PLY, OFF, OBJ, STL) on good files of every variant and on damaged ones: a
// damaged file is refused with one message naming the file, never a crash or a hang.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <random>
#include <string>

#include "support/mesh_file_formats.h"
#include "support/temporary_directory_test.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_check.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

constexpr const char* kName = "mesh_under_test";

// The message parseMesh refuses `bytes` with, or "" if it loads them.
std::string refusal(const std::string& bytes, MeshFormat format) {
  try {
    parseMesh(bytes, format, kName);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string plyWithBody(const std::string& header_lines, const std::string& body,
                        const char* encoding = "ascii") {
  return std::string("ply\nformat ") + encoding + " 1.0\n" + header_lines + "end_header\n" + body;
}

// The vertex and triangle lines of a unit right triangle in the z = 0 plane.
const std::string kTriangleHeader =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\n";
const std::string kTriangleBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

TEST(MeshReadersTest, EveryFormatReadsTheMugAsWritten) {
  const TriangleMesh mug = makeMug();
  for (const auto& format : test::meshFileFormats()) {
    SCOPED_TRACE(format.name);
    const TriangleMesh loaded =
        parseMesh(test::meshFileBytes(mug, format.name), format.format, kName);
    ASSERT_EQ(loaded.triangles.size(), mug.triangles.size());
    EXPECT_EQ(loaded.vertices.size(), mug.vertices.size());
    EXPECT_NEAR(loaded.area(), mug.area(), 1e-9);
    EXPECT_NEAR(loaded.signedVolume(), mug.signedVolume(), 1e-12);  // still facing outwards
    EXPECT_TRUE(checkMesh(loaded).watertight);
    for (std::size_t t = 0; t < mug.triangles.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(loaded.vertices[loaded.triangles[t][k]], mug.vertices[mug.triangles[t][k]]);
      }
    }
  }
}

// The case: `vdc mesh mug` output cut to 22000 bytes made assimp crash (exit 139).
class CutMugTest : public test::TemporaryDirectoryTest {};

TEST_F(CutMugTest, HalfABinaryPlyIsRefusedAsCut) {
  saveMeshPly(makeMug(), path("mug.ply"));
  std::ifstream in(path("mug.ply"), std::ios::binary);
  std::string bytes(22000, '\0');
  ASSERT_TRUE(in.read(bytes.data(), 22000));
  std::ofstream(path("cut.ply"), std::ios::binary) << bytes;
  try {
    loadMesh(path("cut.ply"));
    FAIL() << "a cut file loaded";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cut.ply"), std::string::npos) << message;
    EXPECT_NE(message.find("the file ends in face"), std::string::npos) << message;
  }
}

// 150 damaged copies per format (the experiment, in-process and for every format): each
// loads or is refused naming the file. A crash ends this test binary; a hang times it out.
TEST(MeshReadersTest, DamagedCopiesOfEveryFormatAreRefusedOrLoaded) {
  const TriangleMesh mug = makeMug();
  for (const auto& format : test::meshFileFormats()) {
    SCOPED_TRACE(format.name);
    const std::string original = test::meshFileBytes(mug, format.name);
    std::mt19937 rng(7);
    int refused = 0;
    for (int copy = 0; copy < 150; ++copy) {
      const std::string message = refusal(test::damagedCopy(original, &rng), format.format);
      if (message.empty()) continue;
      ++refused;
      EXPECT_EQ(message.rfind(std::string("Mesh file '") + kName + "'", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_GT(refused, 75);  // the damage is real: most copies must be refused
  }
}

TEST(MeshReadersTest, BigEndianPlyWithDoublesAndExtraPropertiesLoads) {
  std::string body;
  auto put = [&body](auto value) {
    char raw[sizeof(value)];
    std::memcpy(raw, &value, sizeof(value));
    for (std::size_t i = sizeof(value); i > 0; --i) body.push_back(raw[i - 1]);
  };
  const double corners[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (const auto& c : corners) {
    put(std::uint8_t(7));  // a colour before the position
    for (double v : c) put(v);
  }
  put(std::uint16_t(3));
  for (std::uint16_t i : {0, 1, 2}) put(i);
  put(std::uint8_t(2));  // a texture-coordinate list after the indices
  put(0.5f);
  put(0.25f);
  const std::string file = plyWithBody(
      "element vertex 3\nproperty uchar red\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list ushort ushort vertex_indices\n"
      "property list uchar float texcoord\n",
      body, "binary_big_endian");
  const TriangleMesh mesh = parseMesh(file, MeshFormat::kPly, kName);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_TRUE(mesh.triangleNormal(0).isApprox(Eigen::Vector3f::UnitZ()));
  EXPECT_NEAR(mesh.area(), 0.5, 1e-9);
}

TEST(MeshReadersTest, PlyCountsTheFileCannotHoldAreRefusedBeforeReading) {
  // Two billion vertices in a few bytes: refused from the header, without allocating.
  const auto start = std::chrono::steady_clock::now();
  const std::string message =
      refusal(plyWithBody("element vertex 2000000000\nproperty float x\nproperty float y\n"
                          "property float z\n",
                          "0 0 0\n"),
              MeshFormat::kPly);
  EXPECT_NE(message.find("declares 2000000000 vertex elements"), std::string::npos) << message;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_NE(
      refusal(plyWithBody("element vertex 5000000000\nproperty float x\n", ""), MeshFormat::kPly)
          .find("more than this loader supports"),
      std::string::npos);
}

TEST(MeshReadersTest, PlyElementsWithoutPropertiesCostNothingHoweverMany) {
  const std::string file =
      plyWithBody("element nothing 4000000000000\n" + kTriangleHeader, kTriangleBody);
  EXPECT_EQ(parseMesh(file, MeshFormat::kPly, kName).triangles.size(), 1u);
}

TEST(MeshReadersTest, PlyFaceErrorsNameTheFace) {
  EXPECT_NE(
      refusal(plyWithBody(kTriangleHeader, "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), MeshFormat::kPly)
          .find("referring to vertex 3, but only 3 vertices"),
      std::string::npos);
  EXPECT_NE(
      refusal(plyWithBody(kTriangleHeader, "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"), MeshFormat::kPly)
          .find("face 0 refers to vertex -1"),
      std::string::npos);
  EXPECT_NE(
      refusal(plyWithBody(kTriangleHeader, "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n"), MeshFormat::kPly)
          .find("line 13: '1.5' is not an integer"),
      std::string::npos);
  EXPECT_NE(refusal(plyWithBody(kTriangleHeader, "0 0 0\n1 0 0\n0 1 0\n3 0 1\n"), MeshFormat::kPly)
                .find("the file ends in face 0 of 1"),
            std::string::npos);
  // A polygon larger than the supported 1024 corners.
  const std::string big = plyWithBody(
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list int int vertex_indices\n",
      "0 0 0\n1 0 0\n0 1 0\n2000000 0 1 2\n");
  EXPECT_NE(refusal(big, MeshFormat::kPly).find("of 2000000 items, more than the 1024"),
            std::string::npos);
}

TEST(MeshReadersTest, MalformedPlyHeadersAreRefusedSayingWhy) {
  const auto header_refusal = [](const std::string& file) {
    return refusal(file, MeshFormat::kPly);
  };
  EXPECT_NE(header_refusal("ply\nformat ascii 1.0\n" + kTriangleHeader).find("no end_header"),
            std::string::npos);
  EXPECT_NE(header_refusal(plyWithBody(kTriangleHeader, kTriangleBody, "binary_middle_endian"))
                .find("unknown format 'binary_middle_endian'"),
            std::string::npos);
  EXPECT_NE(header_refusal(plyWithBody("element vertex 3\nproperty float x\nproperty float y\n",
                                       "0 0\n1 0\n0 1\n"))
                .find("no property 'z'"),
            std::string::npos);
  EXPECT_NE(header_refusal(plyWithBody("element vertex 1\nproperty list float float x\n", ""))
                .find("count type must be an integer"),
            std::string::npos);
  EXPECT_NE(header_refusal(plyWithBody("element vertex 0\nelement vertex 0\n", ""))
                .find("declared twice"),
            std::string::npos);
  EXPECT_NE(header_refusal(plyWithBody("property float x\n", "")).find("before any element"),
            std::string::npos);
}

TEST(MeshReadersTest, NonFiniteAndHugeCoordinatesAreRefused) {
  for (const char* value : {"nan", "inf", "1e39", "1e999"}) {
    SCOPED_TRACE(value);
    const std::string body = std::string(value) + " 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const std::string message = refusal(plyWithBody(kTriangleHeader, body), MeshFormat::kPly);
    // 1e999 is no double at all: not a number; the others are not finite as float.
    EXPECT_TRUE(message.find("non-finite") != std::string::npos ||
                message.find("is not a number") != std::string::npos)
        << message;
  }
}

TEST(MeshReadersTest, ObjConcavePolygonIsCutIntoEarsFacingItsWay) {
  // An L-shaped hexagon (area 3) in the z = 0 plane, counter-clockwise seen from +z, with
  // negative (relative) and slash-separated indices. A fan from its first corner would leave the
  // shape.
  const std::string obj =
      "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nvt 0 0\nvn 0 0 1\n"
      "f 2/1/1 3//1 -3 -2 -1 1\n";
  const TriangleMesh mesh = parseMesh(obj, MeshFormat::kObj, kName);
  ASSERT_EQ(mesh.triangles.size(), 4u);
  EXPECT_NEAR(mesh.area(), 3.0, 1e-6);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    EXPECT_TRUE(mesh.triangleNormal(t).isApprox(Eigen::Vector3f::UnitZ())) << "triangle " << t;
  }
}

TEST(MeshReadersTest, ObjBadIndicesAreRefusedNamingTheLine) {
  EXPECT_NE(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", MeshFormat::kObj)
                .find("line 4: '0' is not a vertex index"),
            std::string::npos);
  EXPECT_NE(refusal("v 0 0 0\nf -1 -2 -3\n", MeshFormat::kObj).find("before the first"),
            std::string::npos);
  EXPECT_NE(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", MeshFormat::kObj)
                .find("referring to vertex 3, but only 3 vertices"),
            std::string::npos);
}

TEST(MeshReadersTest, OffVariantsLoadAndCutOnesAreRefused) {
  // Counts on the keyword's line, comments, colours after vertices and faces.
  const std::string off =
      "COFF 3 1 0 # a coloured triangle\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
      "0 1 0 0 0 255 255\n\n3 0 1 2 9 9 9\n";
  EXPECT_EQ(parseMesh(off, MeshFormat::kOff, kName).triangles.size(), 1u);
  EXPECT_NE(
      refusal("OFF\n3 1 0\n0 0 0\n1 0 0\n", MeshFormat::kOff).find("ends after 2 of 3 vertices"),
      std::string::npos);
  EXPECT_NE(refusal("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", MeshFormat::kOff)
                .find("fewer than its 3 corners"),
            std::string::npos);
  EXPECT_NE(refusal("4OFF\n3 1 0\n", MeshFormat::kOff).find("does not start with 'OFF'"),
            std::string::npos);
}

TEST(MeshReadersTest, BinaryStlWhoseHeaderSaysSolidIsReadAsBinary) {
  const TriangleMesh mug = makeMug();
  std::string binary = test::meshFileBytes(mug, "binary_stl");
  binary.replace(0, 11, "solid mug  ");
  EXPECT_EQ(parseMesh(binary, MeshFormat::kStl, kName).triangles.size(), mug.triangles.size());
  binary += std::string(100, '\0');  // padded by its writer
  EXPECT_EQ(parseMesh(binary, MeshFormat::kStl, kName).triangles.size(), mug.triangles.size());
  const std::string message = refusal(binary.substr(0, 5000), MeshFormat::kStl);
  EXPECT_NE(message.find("as binary STL its header declares 2400 triangles"), std::string::npos)
      << message;
}

TEST(MeshReadersTest, CutStlIsRefused) {
  const TriangleMesh mug = makeMug();
  EXPECT_NE(refusal(test::meshFileBytes(mug, "binary_stl").substr(0, 3000), MeshFormat::kStl)
                .find("declares 2400 triangles (120084 bytes), but it has 3000 bytes"),
            std::string::npos);
  EXPECT_NE(refusal(test::meshFileBytes(mug, "ascii_stl").substr(0, 3000), MeshFormat::kStl)
                .find("a cut file"),
            std::string::npos);
}

TEST(MeshReadersTest, FormatIsThePlyMagicElseTheExtension) {
  EXPECT_EQ(meshFormatOf("mesh.bin", "ply\nformat ascii 1.0\n"), MeshFormat::kPly);
  EXPECT_EQ(meshFormatOf("MESH.STL", "solid x"), MeshFormat::kStl);
  EXPECT_EQ(meshFormatOf("a.Off", "OFF"), MeshFormat::kOff);
  EXPECT_EQ(meshFormatOf("a.obj", "v 0 0 0"), MeshFormat::kObj);
  EXPECT_EQ(meshFormatOf("a.dae", "<?xml"), std::nullopt);
}

}  // namespace
}  // namespace vdc
