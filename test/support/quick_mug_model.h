#pragma once

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc::test {

inline TrainingParameters quickMugTrainingParameters() {
  TrainingParameters parameters = quickTrainingParameters();
  parameters.mesh_name = "mug";
  parameters.clouds_per_view = 3;
  parameters.surface_spacing = 0.006;
  parameters.seed = 5;
  return parameters;
}

// The quick model from `directory`'s cache, trained and saved there by the first process that
// finds none (under a lock, so two gtest shards started together train it once). The sanitizer
// suite sets VDC_QUICK_MODEL_CACHE: training takes about 50 s per process under ASan, and its
// script empties the cache whenever the libraries that train it were rebuilt.
inline ModelBundle cachedQuickMugModel(const std::string& directory) {
  const std::string path = directory + "/quick_mug_model.h5";
  // Closing the file releases the lock, also when training throws.
  struct LockFile {
    int fd;
    ~LockFile() {
      if (fd >= 0) ::close(fd);
    }
  } const lock{::open((path + ".lock").c_str(), O_CREAT | O_RDWR, 0644)};
  if (lock.fd < 0 || ::flock(lock.fd, LOCK_EX) != 0) {
    throw Error("quick model cache: cannot lock " + path + ".lock");
  }
  try {
    return loadModelBundle(path);
  } catch (const Error&) {  // none yet, or a damaged one: train it again
    saveModelBundle(trainModel(makeMug(), quickMugTrainingParameters()), path);  // atomic
    return loadModelBundle(path);  // every process then tests the same, loaded, model
  }
}

// A small mug model (12 directions x 3 clouds, coarse surface set) trained once per test binary
// and shared by every test that needs a real bundle: the estimator's and the evaluation's.
inline std::shared_ptr<const ModelBundle> quickMugModel() {
  static const std::shared_ptr<const ModelBundle> model = [] {
    const char* cache = std::getenv("VDC_QUICK_MODEL_CACHE");
    return std::make_shared<const ModelBundle>(
        cache != nullptr && *cache != '\0' ? cachedQuickMugModel(cache)
                                           : trainModel(makeMug(), quickMugTrainingParameters()));
  }();
  return model;
}

}  // namespace vdc::test
