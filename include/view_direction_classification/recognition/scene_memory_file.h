#pragma once

#include <string>

#include "view_direction_classification/recognition/scene_estimator.h"
#include "view_direction_classification/recognition/scene_memory.h"

namespace vdc {

// The object memory file (doc/method.md, "Object memory"): a SceneEstimator's instances saved
// in HDF5 so that a restarted node knows its objects again. Every message of a vdc::Error
// starts with the file's path.

// Writes `memory` to a temporary file beside `path` and renames it over `path`, so a failure
// (unwritable directory, full disk, crash) never leaves a damaged file where the previous
// memory was. Throws vdc::Error for a non-finite value or a failed write.
void writeSceneMemoryFile(const SceneMemory& memory, const std::string& path);

// Reads and checks a memory file: throws vdc::Error for a file that is damaged or foreign (not
// HDF5, another format tag or version, a missing dataset or attribute, a wrong shape, NaN). It
// does not know the library: restoreMemory refuses models it lacks.
SceneMemory readSceneMemoryFile(const std::string& path);

// The two above on an estimator. loadSceneMemory leaves the estimator unchanged when it throws.
void saveSceneMemory(const SceneEstimator& estimator, const std::string& path);
void loadSceneMemory(const std::string& path, SceneEstimator* estimator);

}  // namespace vdc
