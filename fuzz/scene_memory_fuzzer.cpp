// libFuzzer target: the object memory loader (vdc::readSceneMemoryFile, an HDF5 file), as the
// scene node reads ~memory_file at start-up, a file a crash, a full disk or a user may have
// damaged. Everything the loader checks is reached without a model library (restoreMemory only
// adds the library's own check of model names). The bytes are written to a temporary file
// because HDF5 reads from one. A damaged memory must throw vdc::Error.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/recognition/scene_memory_file.h"

namespace {

// One file per fuzzing process (libFuzzer's -jobs/-fork run several), removed at exit. Never
// destroyed, so the exit handler can still read it.
const std::string& memoryPath() {
  static const std::string* path = [] {
    const char* directory = std::getenv("TMPDIR");
    auto* p = new std::string(std::string(directory ? directory : "/tmp") +
                              "/vdc_scene_memory_fuzzer_" + std::to_string(getpid()) + ".h5");
    std::atexit([] { std::remove(memoryPath().c_str()); });
    return p;
  }();
  return *path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  std::FILE* file = std::fopen(memoryPath().c_str(), "wb");
  if (file == nullptr) std::abort();
  if (size > 0 && std::fwrite(bytes, 1, size, file) != size) std::abort();
  std::fclose(file);
  try {
    const vdc::SceneMemory memory = vdc::readSceneMemoryFile(memoryPath());
    // What the node publishes first of a restored instance: its belief's MAP orientation.
    for (const vdc::InstanceMemory& instance : memory.instances) {
      vdc::mapEstimate(instance.estimator.belief, vdc::MapOptions{});
    }
  } catch (const vdc::Error&) {
    // refused with one line naming the file and the problem
  }
  return 0;
}
