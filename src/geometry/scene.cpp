#include "view_direction_classification/geometry/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/primitive_meshes.h"

namespace vdc {
namespace {

TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  if (!pose.matrix().allFinite()) throw Error("a scene part's pose is not finite");
  TriangleMesh result = mesh;
  const Eigen::Isometry3f pose_f = pose.cast<float>();
  for (Eigen::Vector3f& v : result.vertices) v = pose_f * v;
  return result;
}

// The numbers after a primitive's keyword; throws unless there are `count` (to `most`, when
// more than `count`).
std::vector<double> primitiveSizes(std::istringstream& stream, std::size_t count,
                                   std::size_t most = 0) {
  std::vector<double> sizes;
  for (double value; stream >> value;) sizes.push_back(value);
  most = std::max(most, count);
  if (!stream.eof() || sizes.size() < count || sizes.size() > most) {
    throw Error("expected " +
                (most > count ? std::to_string(count) + " or " + std::to_string(most)
                              : std::to_string(count)) +
                " sizes in metres after the shape's name");
  }
  return sizes;
}

}  // namespace

double tableHeight(const Scene& scene) {
  if (scene.object.mesh.vertices.empty()) throw Error("the scene's object has no vertices");
  double lowest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3f& v : scene.object.mesh.vertices) {
    lowest = std::min(lowest, (scene.object.world_from_part * v.cast<double>()).z());
  }
  return lowest;
}

ScenePart tablePart(const Scene& scene) {
  if (!scene.table_size) throw Error("the scene has no table");
  Eigen::Isometry3d world_from_table = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d object_origin = scene.object.world_from_part.translation();
  world_from_table.translation() =
      Eigen::Vector3d(object_origin.x(), object_origin.y(), tableHeight(scene));
  return {makeRectangleMesh(*scene.table_size), world_from_table};
}

TriangleMesh sceneMesh(const Scene& scene) {
  std::vector<ScenePart> parts = {scene.object};
  if (scene.table_size) parts.push_back(tablePart(scene));
  parts.insert(parts.end(), scene.distractors.begin(), scene.distractors.end());
  return partsMesh(parts);
}

TriangleMesh partsMesh(const std::vector<ScenePart>& parts) {
  TriangleMesh mesh;
  for (const ScenePart& part : parts) mesh.append(transformed(part.mesh, part.world_from_part));
  return mesh;
}

TriangleMesh distractorMesh(const std::string& description) {
  std::istringstream stream(description);
  std::string shape;
  stream >> shape;
  try {
    if (shape == "box") {
      const std::vector<double> s = primitiveSizes(stream, 3);
      return makeBoxMesh(Eigen::Vector3d(s[0], s[1], s[2]));
    }
    if (shape == "cylinder") {
      const std::vector<double> s = primitiveSizes(stream, 2);
      return makeCylinderMesh(s[0], s[1]);
    }
    if (shape == "carton") {
      const std::vector<double> s = primitiveSizes(stream, 4, 5);
      return makeCartonMesh(Eigen::Vector3d(s[0], s[1], s[2]), s[3], s.size() > 4 ? s[4] : 0.0);
    }
  } catch (const Error& error) {
    throw Error("distractor '" + description + "': " + error.what());
  }
  if (description.empty()) {
    throw Error(
        "a distractor needs a description: box SX SY SZ, cylinder R H, carton SX SY SZ GABLE "
        "[FIN] or a mesh file");
  }
  try {
    return loadMesh(description);
  } catch (const Error& error) {
    throw Error("distractor '" + description +
                "' is neither 'box SX SY SZ', 'cylinder R H', 'carton SX SY SZ GABLE [FIN]' nor a "
                "readable mesh file: " +
                error.what());
  }
}

}  // namespace vdc
