#include "informativeness_server_ros_parameters.h"

#include "model_library_parameter.h"

namespace vdc {
namespace {

ParameterTable<InformativenessServerRosParameters> makeTable() {
  using P = InformativenessServerRosParameters;
  ParameterTable<P> table;
  // ADDING A PARAMETER: a field in InformativenessServerRosParameters, one line below and its
  // entry in config/informativeness_server.yaml; to tune it live, also a line with the same
  // name and type in cfg/InformativenessServer.cfg. (`models`, a map, is read outside it.)
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

std::vector<std::string> informativenessServerParameterNames() {
  std::vector<std::string> names = informativenessServerParameterTable().names();
  names.push_back("models");
  return names;
}

InformativenessServerRosParameters readInformativenessServerRosParameters(
    const ros::NodeHandle& node) {
  InformativenessServerRosParameters p;
  const ParameterReader reader(node);
  // With a library the server may serve instances only, so its one ~model becomes optional.
  const bool with_library = node.hasParam("models");
  informativenessServerParameterTable().read(reader, p, with_library);
  if (with_library) p.models = readModelsParameter(node);
  reader.warnAboutUnknownParameters(informativenessServerParameterNames());
  return p;
}

}  // namespace vdc
