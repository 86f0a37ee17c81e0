#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "view_direction_classification/evaluation/scene_generation.h"

namespace vdc {

// Per-view metrics of recognising every known object in a cluttered scene: which visible known
// objects an estimator identified, how well it posed them, and what it claimed wrongly.
// Symmetric objects are out of scope for now: rotation errors are plain rotationErrorDeg, so an
// estimate of a symmetric object that is right up to its symmetry is charged the full angle.

// One estimated instance.
struct InstanceEstimate {
  std::string model;
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  double cone90_deg = 180.0;          // BeliefSpread::cone90 of its orientation belief [deg]
  double identity_probability = 1.0;  // that it is `model` at all
};

// A known object in one view: its pose and how much of it the camera sees.
struct KnownObjectTruth {
  std::string model;
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  double visible_fraction = 1.0;  // SceneView's
};

// An unknown object, to tell which false identifications sit on a distractor.
struct DistractorTruth {
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  Eigen::AlignedBox3d bounds;  // of its mesh, in its own frame
};

struct ViewTruth {
  std::vector<KnownObjectTruth> known;
  std::vector<DistractorTruth> distractors;
};

// The truth of one rendered view of a generated scene.
ViewTruth viewTruth(const TableScene& scene, const SceneView& view);

struct SceneMetricSettings {
  double visible_fraction = 0.3;  // a known object counts as visible above this
  double match_distance = 0.02;   // [m] between estimated and true object origins
};

struct IdentifiedInstance {
  int truth = -1;     // index into ViewTruth::known
  int estimate = -1;  // index into the estimates
  double rotation_error_deg = 180.0;
  double position_error = 0.0;  // [m]
  bool inside_cone90 = false;   // the rotation error is at most the estimate's cone90
};

struct FalseIdentification {
  int estimate = -1;
  bool on_distractor = false;  // within match_distance of a distractor's bounds
};

struct SceneViewMetrics {
  int visible_known = 0;
  std::vector<IdentifiedInstance> identified;
  std::vector<FalseIdentification> false_identifications;
  // Estimates matched to a known object that is not visible enough to count: neither
  // identified nor false (the estimator may remember an object it saw in an earlier view).
  int matched_hidden = 0;
};

// Matches estimates to known objects one to one, nearest pair first, among pairs of the same
// model within match_distance (visible or not); an estimate matched to a visible object
// identifies it, an unmatched estimate (a wrong model, too far, or a duplicate) is a false
// identification. Throws vdc::Error for a negative threshold or distance.
SceneViewMetrics sceneViewMetrics(const ViewTruth& truth,
                                  const std::vector<InstanceEstimate>& estimates,
                                  const SceneMetricSettings& settings = {});

}  // namespace vdc
