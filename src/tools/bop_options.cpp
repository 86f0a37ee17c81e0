#include "bop_options.h"

#include "view_direction_classification/common/error.h"

namespace vdc::tools {
namespace {

// BOP ids are small positive integers (obj_000001); nine digits keep stoi in range.
bool isObjectId(const std::string& text) {
  return !text.empty() && text.size() <= 9 &&
         text.find_first_not_of("0123456789") == std::string::npos && std::stoi(text) > 0;
}

}  // namespace

std::map<int, std::string> parseObjectPaths(const std::vector<std::string>& specs,
                                            const std::string& option) {
  std::map<int, std::string> paths;
  for (const std::string& spec : specs) {
    const std::size_t equals = spec.find('=');
    const std::string id = spec.substr(0, equals);
    if (equals == std::string::npos || !isObjectId(id) || equals + 1 == spec.size()) {
      throw Error(option + " " + spec + ": expected OBJ_ID=PATH with a positive integer id");
    }
    if (!paths.emplace(std::stoi(id), spec.substr(equals + 1)).second) {
      throw Error(option + " " + spec + ": object " + id + " is given twice");
    }
  }
  return paths;
}

}  // namespace vdc::tools
