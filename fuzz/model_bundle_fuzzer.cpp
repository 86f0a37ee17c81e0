// libFuzzer target: the model bundle loader (vdc::loadModelBundle, an HDF5 file), as the server
// and the estimator load ~model and `vdc inspect` a user's file, followed by what the server does
// first with a loaded bundle (its view utility scorer checks the parts agree). The bytes are
// written to a temporary file because HDF5 reads from one. A damaged bundle must throw
// vdc::Error.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/planning/view_utility_scorer.h"
#include "view_direction_classification/training/model_bundle.h"

namespace {

// One file per fuzzing process (libFuzzer's -jobs/-fork run several), removed at exit. Never
// destroyed, so the exit handler can still read it.
const std::string& bundlePath() {
  static const std::string* path = [] {
    const char* directory = std::getenv("TMPDIR");
    auto* p = new std::string(std::string(directory ? directory : "/tmp") +
                              "/vdc_model_bundle_fuzzer_" + std::to_string(getpid()) + ".h5");
    std::atexit([] { std::remove(bundlePath().c_str()); });
    return p;
  }();
  return *path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  std::FILE* file = std::fopen(bundlePath().c_str(), "wb");
  if (file == nullptr) std::abort();
  if (size > 0 && std::fwrite(bytes, 1, size, file) != size) std::abort();
  std::fclose(file);
  try {
    auto bundle = std::make_shared<const vdc::ModelBundle>(vdc::loadModelBundle(bundlePath()));
    const vdc::ViewUtilityScorer scorer(bundle);
  } catch (const vdc::Error&) {
    // refused with one line naming the file and the problem
  }
  return 0;
}
