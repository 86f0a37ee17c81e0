#pragma once

#include <map>
#include <string>
#include <vector>

namespace vdc::tools {

// `--model ID=MESH` (vdc write-bop) and `--bop-model ID=BUNDLE` (vdc evaluate-bop): a file per
// BOP obj_id. Throws vdc::Error quoting the option and the text for a missing '=', an id that is
// no positive integer, an empty path or an id given twice.
std::map<int, std::string> parseObjectPaths(const std::vector<std::string>& specs,
                                            const std::string& option);

}  // namespace vdc::tools
