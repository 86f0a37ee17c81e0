#pragma once

#include <string>
#include <vector>

namespace vdc::tools {

// Runs one of the package's plotting scripts (scripts/<name>) with Debian's python3, which has
// matplotlib. stdout is flushed first so the tool's lines stay before the script's in a
// redirected log. Throws vdc::Error "<what> failed (<command>); <hint>" if the script fails.
void runPythonScript(const std::string& name, const std::vector<std::string>& arguments,
                     const std::string& what, const std::string& hint);

}  // namespace vdc::tools
