#include "informativeness_server_ros_parameters.h"

namespace vdc {
namespace {

ParameterTable<InformativenessServerRosParameters> makeTable() {
  using P = InformativenessServerRosParameters;
  ParameterTable<P> table;
  // ADDING A PARAMETER: a field in InformativenessServerRosParameters, one line below and its
  // entry in config/informativeness_server.yaml; to tune it live, also a line with the same
  // name and type in cfg/InformativenessServer.cfg.
  table.addRequired("model", &P::model_path, nonEmptyString(), kModelMissing)
      .add("fixed_frame", &P::fixed_frame, frameName())
      .add("object_frame", &P::object_frame, frameName())
      .add("label_best", &P::label_best, integerAtLeast(0))
      .add("view_marker_distance", &P::view_marker_distance, numberAbove(0.0))
      .add("occluder_radius", &P::occluder_radius, numberAbove(0.0))
      .add("belief_samples_per_component", &P::belief_samples_per_component,
           integerBetween(0, 1000, "0: the components' modes only"))
      .addChoice("default_utility", &P::default_utility,
                 std::vector<std::pair<std::string, ViewUtility>>{
                     {"informativeness", ViewUtility::kInformativeness},
                     {"information_gain", ViewUtility::kInformationGain}})
      .add("tf_timeout", &P::tf_timeout, numberAtLeast(0.0))
      .add("republish_period", &P::republish_period, numberAtLeast(0.0, "0: latched once"));
  return table;
}

}  // namespace

const ParameterTable<InformativenessServerRosParameters>& informativenessServerParameterTable() {
  static const ParameterTable<InformativenessServerRosParameters> table = makeTable();
  return table;
}

InformativenessServerRosParameters readInformativenessServerRosParameters(
    const ros::NodeHandle& node) {
  InformativenessServerRosParameters p;
  const ParameterReader reader(node);
  informativenessServerParameterTable().read(reader, p);
  reader.warnAboutUnknownParameters(informativenessServerParameterTable().names());
  return p;
}

}  // namespace vdc
