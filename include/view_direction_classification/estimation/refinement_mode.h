#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vdc {

// What follows the fusion of each view (doc/method.md, "Refinement").
enum class RefinementMode {
  kNone,  // the belief alone
  kIcp,   // its leading hypotheses refined by ICP, verified, and the verified poses fused
};

// The modes by their names in parameters and on the command line: "none", "icp".
const std::vector<std::pair<std::string, RefinementMode>>& refinementModeChoices();
std::string refinementModeName(RefinementMode mode);
// Throws vdc::Error naming the choices for an unknown name.
RefinementMode parseRefinementMode(const std::string& name);

}  // namespace vdc
