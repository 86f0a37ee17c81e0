#include "python_script.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "view_direction_classification/core/error.h"

#ifndef VDC_SCRIPTS_DIR
#define VDC_SCRIPTS_DIR "scripts"
#endif

namespace vdc::tools {

void runPythonScript(const std::string& name, const std::vector<std::string>& arguments,
                     const std::string& what, const std::string& hint) {
  const std::filesystem::path script = std::filesystem::path(VDC_SCRIPTS_DIR) / name;
  std::string command = "/usr/bin/python3 '" + script.string() + "'";
  for (const std::string& argument : arguments) command += " '" + argument + "'";
  std::fflush(stdout);
  if (std::system(command.c_str()) != 0) {
    throw Error(what + " failed (" + command + "); " + hint);
  }
}

}  // namespace vdc::tools
