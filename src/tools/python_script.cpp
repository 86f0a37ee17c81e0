#include "python_script.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "view_direction_classification/common/error.h"

#ifndef VDC_SOURCE_SCRIPTS_DIR
#define VDC_SOURCE_SCRIPTS_DIR "scripts"
#endif
#ifndef VDC_DEVEL_BIN_DIR
#define VDC_DEVEL_BIN_DIR ""
#endif

namespace vdc::tools {
namespace {

namespace fs = std::filesystem;

// Where the plot scripts are: $VDC_SCRIPTS_DIR if set; for the vdc of a devel space (which has no
// copy of them) the source tree's; else, for an installed vdc, its install tree's
// (<prefix>/lib/<package>/vdc -> <prefix>/share/<package>/scripts), so that an installed tool
// never depends on a source tree that may be gone.
fs::path scriptsDirectory() {
  if (const char* from_environment = std::getenv("VDC_SCRIPTS_DIR")) return from_environment;
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (error) return VDC_SOURCE_SCRIPTS_DIR;
  const fs::path package_lib_dir = executable.parent_path();
  if (package_lib_dir == fs::weakly_canonical(VDC_DEVEL_BIN_DIR, error))
    return VDC_SOURCE_SCRIPTS_DIR;
  return package_lib_dir.parent_path().parent_path() / "share" / package_lib_dir.filename() /
         "scripts";
}

}  // namespace

void runPythonScript(const std::string& name, const std::vector<std::string>& arguments,
                     const std::string& what, const std::string& hint) {
  const fs::path script = scriptsDirectory() / name;
  if (!fs::is_regular_file(script)) {
    throw Error(what + " failed: the plot script " + script.string() +
                " is missing (an installed vdc runs the scripts installed beside it; "
                "VDC_SCRIPTS_DIR overrides); " +
                hint);
  }
  std::string command = "/usr/bin/python3 '" + script.string() + "'";
  for (const std::string& argument : arguments) command += " '" + argument + "'";
  std::fflush(stdout);
  if (std::system(command.c_str()) != 0) {
    throw Error(what + " failed (" + command + "); " + hint);
  }
}

}  // namespace vdc::tools
