#pragma once

#include <memory>

#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/training/model_training.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc::test {

// A small mug model (12 directions x 3 clouds, coarse surface set) trained once per test binary
// and shared by every test that needs a real bundle: the estimator's and the evaluation's.
inline std::shared_ptr<const ModelBundle> quickMugModel() {
  static const std::shared_ptr<const ModelBundle> model = [] {
    TrainingParameters parameters = quickTrainingParameters();
    parameters.mesh_name = "mug";
    parameters.clouds_per_view = 3;
    parameters.surface_spacing = 0.006;
    parameters.seed = 5;
    return std::make_shared<const ModelBundle>(trainModel(makeMug(), parameters));
  }();
  return model;
}

}  // namespace vdc::test
