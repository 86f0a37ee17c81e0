#include "scene_evaluation_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <sstream>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc::tools {

namespace {

// "a,b,c" as `count` (to `most`, when more than `count`) positive finite numbers; throws
// vdc::Error quoting `text` otherwise.
std::vector<double> positiveNumbers(const std::string& list, std::size_t count,
                                    const std::string& text, std::size_t most = 0) {
  std::vector<double> numbers;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(value) || value <= 0.0) break;
    numbers.push_back(value);
  }
  most = std::max(most, count);
  if (numbers.size() < count || numbers.size() > most || !stream.eof()) {
    throw Error("--distractor " + text + ": needs " + std::to_string(count) +
                (most > count ? " or " + std::to_string(most) : std::string()) +
                " positive sizes in metres, comma-separated");
  }
  return numbers;
}

}  // namespace

SceneModelSpec parseSceneModelSpec(const std::string& text) {
  const std::size_t equals = text.find('=');
  // The last ':' separates the mesh, so a bundle path may hold one (the mesh path then may not).
  const std::size_t colon = text.rfind(':');
  if (equals == std::string::npos || colon == std::string::npos || colon < equals) {
    throw Error("--model " + text + ": expected NAME=BUNDLE.h5:MESH");
  }
  SceneModelSpec spec{text.substr(0, equals), text.substr(equals + 1, colon - equals - 1),
                      text.substr(colon + 1)};
  if (spec.name.empty() || spec.bundle_path.empty() || spec.mesh_path.empty()) {
    throw Error("--model " + text + ": expected NAME=BUNDLE.h5:MESH, none of them empty");
  }
  return spec;
}

SceneEvaluationModel loadSceneModel(const SceneModelSpec& spec) {
  return {spec.name, std::make_shared<const ModelBundle>(loadModelBundle(spec.bundle_path)),
          loadMesh(spec.mesh_path)};
}

std::vector<SceneEvaluationModel> loadSceneModels(const std::vector<std::string>& specs) {
  std::vector<SceneEvaluationModel> models;
  for (const std::string& spec : specs) models.push_back(loadSceneModel(parseSceneModelSpec(spec)));
  return models;
}

TriangleMesh distractorMesh(const std::string& text) {
  if (text.rfind("box:", 0) == 0) {
    const auto sizes = positiveNumbers(text.substr(4), 3, text);
    return makeBoxMesh(Eigen::Vector3d(sizes[0], sizes[1], sizes[2]));
  }
  if (text.rfind("cylinder:", 0) == 0) {
    const auto sizes = positiveNumbers(text.substr(9), 2, text);
    return makeCylinderMesh(sizes[0], sizes[1]);
  }
  if (text.rfind("carton:", 0) == 0) {
    const auto sizes = positiveNumbers(text.substr(7), 4, text, 5);
    return makeCartonMesh(Eigen::Vector3d(sizes[0], sizes[1], sizes[2]), sizes[3],
                          sizes.size() > 4 ? sizes[4] : 0.0);
  }
  return loadMesh(text);
}

std::vector<std::string> defaultDistractors() {
  return {"box:0.09,0.08,0.10", "box:0.16,0.06,0.05", "box:0.06,0.06,0.18", "cylinder:0.035,0.11",
          "cylinder:0.025,0.20"};
}

std::vector<TriangleMesh> loadDistractorMeshes(const std::vector<std::string>& specs) {
  std::vector<TriangleMesh> meshes;
  for (const std::string& spec : specs.empty() ? defaultDistractors() : specs) {
    meshes.push_back(distractorMesh(spec));
  }
  return meshes;
}

}  // namespace vdc::tools
