#pragma once

// A scene update's candidates and the estimator's instances as text: what a failing scene test
// prints.

#include <string>

#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc::test {

inline std::string describeSceneUpdate(const SceneEstimator& estimator, const SceneUpdate& update) {
  std::string text = std::to_string(update.candidates.size()) + " candidates:";
  for (const CandidateOutcome& c : update.candidates) {
    text += "\n  at (" + std::to_string(c.centroid_world.x()) + ", " +
            std::to_string(c.centroid_world.y()) + ") " + std::to_string(c.points) +
            " points, instance " + std::to_string(c.instance) + " p " +
            std::to_string(c.probability) + " " + c.note;
  }
  for (const ObjectInstance& instance : estimator.instances()) {
    const auto position = instance.estimator->positionEstimate();
    if (!position) continue;
    text += "\n  " + instance.name + " at (" + std::to_string(position->x()) + ", " +
            std::to_string(position->y()) + ", " + std::to_string(position->z()) + ")";
  }
  return text;
}

}  // namespace vdc::test
