#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// One rigid part of a scene: a mesh in its own frame and its pose in the fixed frame.
struct ScenePart {
  TriangleMesh mesh;
  Eigen::Isometry3d world_from_part = Eigen::Isometry3d::Identity();
};

// A table-top scene as a depth camera sees it: the object at its pose in the fixed frame (z up,
// REP 103), optionally standing on a table, and other objects (distractors) at their own poses.
// The table is a horizontal rectangle at the height of the object's lowest point, centred under
// the object, so the object stands on it whatever its orientation.
struct Scene {
  ScenePart object;
  std::optional<Eigen::Vector2d> table_size;  // [m] along the fixed frame's x and y; empty: none
  std::vector<ScenePart> distractors;
};

// Height [m] of the table top in the fixed frame: the lowest z of the object's vertices there.
// Throws vdc::Error for an object without vertices.
double tableHeight(const Scene& scene);

// The table as a part of its own (a rectangle of table_size at tableHeight, centred under the
// object's origin), so that it can stay where it is while the object moves. Throws vdc::Error for
// a scene without a table or an object without vertices.
ScenePart tablePart(const Scene& scene);

// Every part, and the table if any, in the fixed frame as one mesh (for DepthRenderer with
// camera_from_world poses). Throws vdc::Error for a non-finite pose or an invalid table size.
TriangleMesh sceneMesh(const Scene& scene);

// A distractor's mesh from its description: "box SX SY SZ" (full sizes [m]), "cylinder R H"
// (radius, height [m]), "carton SX SY SZ GABLE [FIN]" (makeCartonMesh: whole sizes, the roof's
// rise and the fin's height [m], no fin when left out), all standing on z = 0 of their frame
// (primitive_meshes.h), or else the path of a mesh file (loadMesh). Throws vdc::Error naming the
// description if it cannot be parsed or loaded.
TriangleMesh distractorMesh(const std::string& description);

// The parts in the fixed frame as one mesh. Throws vdc::Error for a non-finite pose.
TriangleMesh partsMesh(const std::vector<ScenePart>& parts);

}  // namespace vdc
