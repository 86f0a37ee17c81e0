#include "model_library_parameter.h"

#include <XmlRpcValue.h>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/ros/parameter_reader.h"

namespace vdc {
namespace {

Error modelsError(const std::string& got) {
  return parameterError("models", "a non-empty map from a name to a model bundle's path", got);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> readModelsParameter(
    const ros::NodeHandle& private_node) {
  XmlRpc::XmlRpcValue value;
  if (!private_node.getParam("models", value)) throw modelsError("nothing");
  if (value.getType() != XmlRpc::XmlRpcValue::TypeStruct || value.size() == 0) {
    throw modelsError("'" + value.toXml() + "'");
  }
  std::vector<std::pair<std::string, std::string>> models;
  for (auto& [name, path] : value) {
    if (path.getType() != XmlRpc::XmlRpcValue::TypeString ||
        static_cast<std::string>(path).empty()) {
      throw modelsError("an entry '" + name + "' that is not a non-empty path");
    }
    models.emplace_back(name, static_cast<std::string>(path));
  }
  return models;
}

}  // namespace vdc
