#pragma once

#include <string>
#include <vector>

#include "view_direction_classification/training/model_bundle.h"
#include "view_direction_classification/common/progress.h"
#include "view_direction_classification/training/training_set.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// What the pipeline noticed on the way, for the user (degenerate views, mesh warnings).
struct TrainingReport {
  std::vector<std::string> warnings;
  std::size_t training_features = 0;
  std::size_t held_out_features = 0;
  double seconds_rendering = 0, seconds_training = 0, seconds_scoring = 0;
};

// Parameters of a small model that trains in seconds (tests, CI, `vdc train --quick`).
TrainingParameters quickTrainingParameters(TrainingParameters parameters = {});

// The whole offline pipeline of doc/method.md sections 2-7 and 10 (centroid offsets): render the
// training and held-out clouds, compute features, train the classifier, evaluate it on the
// held-out clouds, score view and surface informativeness on the training clouds (as the paper
// does), and assemble the model bundle. Throws vdc::Error on unusable input.
ModelBundle trainModel(const TriangleMesh& mesh, const TrainingParameters& parameters,
                       TrainingReport* report = nullptr, const ProgressCallback& progress = {});

// Helpers shared with the evaluation and the estimator: the settings stored in a bundle turned
// back into the types the stages take.
FeatureParameters featureParametersOf(const TrainingParameters& parameters);
CameraIntrinsics intrinsicsOf(const TrainingParameters& parameters);
ViewSimulation simulationOf(const TrainingParameters& parameters);

}  // namespace vdc
