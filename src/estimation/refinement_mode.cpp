#include "view_direction_classification/estimation/refinement_mode.h"

#include "view_direction_classification/common/error.h"

namespace vdc {

const std::vector<std::pair<std::string, RefinementMode>>& refinementModeChoices() {
  static const std::vector<std::pair<std::string, RefinementMode>> choices = {
      {"none", RefinementMode::kNone}, {"icp", RefinementMode::kIcp}};
  return choices;
}

std::string refinementModeName(RefinementMode mode) {
  for (const auto& [name, value] : refinementModeChoices()) {
    if (value == mode) return name;
  }
  return "unknown";
}

RefinementMode parseRefinementMode(const std::string& name) {
  for (const auto& [choice, value] : refinementModeChoices()) {
    if (choice == name) return value;
  }
  throw Error("unknown refinement '" + name + "' (none or icp)");
}

}  // namespace vdc
