#include "scene_ros_parameters.h"

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
      .add("identity_min_probability", identification(&IdentificationParameters::min_probability),
           numberIn(0.0, 1.0, true))
      .add("identity_drop_probability", identification(&IdentificationParameters::drop_probability),
           numberIn(0.0, 1.0, true))
      .add("identity_unknown_score", identification(&IdentificationParameters::unknown_score),
           numberIn(-1.0, 1.0, true))
      .add("min_camera_translation", scene(&S::min_camera_translation), numberAtLeast(0.0))
      .add("min_camera_rotation", scene(&S::min_camera_rotation), numberAtLeast(0.0));
  return table;
}

}  // namespace

const ParameterTable<SceneRosParameters>& sceneParameterTable() {
  static const ParameterTable<SceneRosParameters> table = makeTable();
  return table;
}

std::vector<std::string> sceneParameterNames() {
  std::vector<std::string> names = sceneParameterTable().names();
  names.push_back("models");
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
  checkSceneEstimatorParameters(p.scene);
  return p;
}

}  // namespace vdc
