#include "scene_ros_parameters.h"

#include <XmlRpcValue.h>

#include <cstdint>
#include <map>
#include <string>

#include "model_library_parameter.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

ParameterTable<SceneRosParameters> makeTable() {
  using P = SceneRosParameters;
  using S = SceneEstimatorParameters;
  const auto scene = [](auto member) { return fieldPath(&P::scene, member); };
  const auto segmentation = [](auto member) {
    return fieldPath(&P::scene, &S::segmentation, member);
  };
  const auto identification = [](auto member) {
    return fieldPath(&P::scene, &S::identification, member);
  };
  ParameterTable<P> table;
  // ADDING A PARAMETER: a field of SceneEstimatorParameters (core), one line here, its row in
  // doc/nodes.md ("Several objects") and, if the shipped config sets it, config/estimator.yaml.
  table
      .add("scene_plane_distance", segmentation(&SceneSegmentationParameters::plane_distance),
           numberAbove(0.0))
      .add("scene_depth_tolerance_growth",
           segmentation(&SceneSegmentationParameters::depth_tolerance_growth),
           numberAtLeast(0.0, "0: fixed tolerances"))
      .add("scene_cluster_tolerance", segmentation(&SceneSegmentationParameters::cluster_tolerance),
           numberAbove(0.0))
      .add("scene_min_cluster_points",
           segmentation(&SceneSegmentationParameters::min_cluster_points), integerAtLeast(1))
      .add("scene_max_candidates", segmentation(&SceneSegmentationParameters::max_candidates),
           integerAtLeast(1))
      .add("scene_split_touching", segmentation(&SceneSegmentationParameters::split_touching),
           anyBoolean())
      .add("association_distance", scene(&S::association_distance), numberAbove(0.0))
      .add("max_identifications", scene(&S::max_identifications),
           integerAtLeast(0, "0: no new instances"))
      .add("max_growth_tries", scene(&S::max_growth_tries), integerAtLeast(0, "0: none"))
      .add("part_search_candidates",
           fieldPath(&P::scene, &S::part_search, &PartSearchParameters::max_candidates),
           integerAtLeast(0, "0: no part search"))
      .add("identity_min_probability", identification(&IdentificationParameters::min_probability),
           numberIn(0.0, 1.0, true))
      .add("identity_track_probability",
           identification(&IdentificationParameters::track_probability), numberIn(0.0, 1.0, true))
      .add("identity_drop_probability", identification(&IdentificationParameters::drop_probability),
           numberIn(0.0, 1.0, true))
      .add("identity_unknown_score", identification(&IdentificationParameters::unknown_score),
           numberIn(-1.0, 1.0, true))
      .add("identification_threads", identification(&IdentificationParameters::threads),
           integerAtLeast(1))
      .add("absent_views", scene(&S::absent_views), integerAtLeast(1))
      .add("forget_gone_after", scene(&S::forget_gone_after),
           numberAtLeast(0.0, "0: gone instances are kept"))
      .add("min_camera_translation", scene(&S::min_camera_translation), numberAtLeast(0.0))
      .add("min_camera_rotation", scene(&S::min_camera_rotation), numberAtLeast(0.0))
      .add("label_class_divisor", segmentation(&SceneSegmentationParameters::label_class_divisor),
           integerAtLeast(1, "1: the label value is the class"))
      .add("labels_stamp_tolerance", &P::labels_stamp_tolerance,
           numberAtLeast(0.0, "0: the cloud's stamp exactly"))
      .add("labels_timeout", &P::labels_timeout, numberAtLeast(0.0))
      .add("memory_file", &P::memory_file, anyString())
      .add("memory_fade_age", &P::memory_fade_age, numberAbove(0.0));
  return table;
}

Error labelModelsError(const std::string& got) {
  return parameterError("label_models",
                        "a map from a class id (a non-negative integer, quoted: '41') to a model "
                        "name of the library",
                        got);
}

// A class id written as a map key (XmlRpc maps have string keys): digits only.
std::int64_t classIdOf(const std::string& key) {
  const bool digits =
      !key.empty() && key.size() <= 18 && key.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) throw labelModelsError("a key '" + key + "' that is no class id");
  return std::stoll(key);
}

// ~label_models: unset is empty (every model may be any class). Whether each name is a model of
// the library the SceneEstimator checks.
std::map<std::int64_t, std::string> readLabelModels(const ros::NodeHandle& node) {
  XmlRpc::XmlRpcValue value;
  if (!node.getParam("label_models", value)) return {};
  if (value.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
    throw labelModelsError("'" + value.toXml() + "'");
  }
  std::map<std::int64_t, std::string> label_models;
  for (auto& [key, name] : value) {
    if (name.getType() != XmlRpc::XmlRpcValue::TypeString ||
        static_cast<std::string>(name).empty()) {
      throw labelModelsError("an entry '" + key + "' that is not a model name");
    }
    label_models[classIdOf(key)] = static_cast<std::string>(name);
  }
  return label_models;
}

}  // namespace

const ParameterTable<SceneRosParameters>& sceneParameterTable() {
  static const ParameterTable<SceneRosParameters> table = makeTable();
  return table;
}

std::vector<std::string> sceneParameterNames() {
  std::vector<std::string> names = sceneParameterTable().names();
  names.push_back("models");
  names.push_back("label_models");
  return names;
}

SceneRosParameters readSceneRosParameters(const ros::NodeHandle& node,
                                          const EstimatorRosParameters& estimator) {
  SceneRosParameters p;
  if (node.hasParam("models")) {
    p.models = readModelsParameter(node);
  } else if (estimator.model_path.empty()) {
    throw Error(kModelMissing);
  } else {
    p.models = {{estimator.object_id, estimator.model_path}};
  }
  sceneParameterTable().read(ParameterReader(node), p);
  p.scene.label_models = readLabelModels(node);
  checkSceneEstimatorParameters(p.scene);
  return p;
}

}  // namespace vdc
