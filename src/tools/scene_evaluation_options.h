#pragma once

#include <string>
#include <vector>

#include "view_direction_classification/evaluation/scene_evaluation.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc::tools {

// `--model NAME=BUNDLE:MESH`: a library entry as given on the command line.
struct SceneModelSpec {
  std::string name, bundle_path, mesh_path;
};
// Throws vdc::Error quoting the text when it has no '=', no ':' after it, or an empty part.
SceneModelSpec parseSceneModelSpec(const std::string& text);
// Loads the bundle and the mesh; throws vdc::Error naming the file that cannot be loaded.
SceneEvaluationModel loadSceneModel(const SceneModelSpec& spec);

// Every `--model` spec loaded, in order.
std::vector<SceneEvaluationModel> loadSceneModels(const std::vector<std::string>& specs);

// `--distractor`: "box:X,Y,Z" (full sizes [m]), "cylinder:R,H" ([m]), "carton:X,Y,Z,GABLE[,FIN]"
// (makeCartonMesh [m]) or a mesh file (metres).
// Throws vdc::Error quoting the text for a malformed primitive or a mesh that cannot be loaded.
TriangleMesh distractorMesh(const std::string& text);
// The distractors when none is given: boxes and cylinders of household sizes, some of a mug's
// size so that they fit the models' extents and must be told apart by shape.
std::vector<std::string> defaultDistractors();
// Every `--distractor` spec's mesh, or the default distractors' when there is none.
std::vector<TriangleMesh> loadDistractorMeshes(const std::vector<std::string>& specs);

}  // namespace vdc::tools
