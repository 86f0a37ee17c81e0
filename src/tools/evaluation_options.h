#pragma once

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

#include "view_direction_classification/evaluation/evaluation.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc::tools {

// A setting summary.json records: where (a JSON pointer such as "/estimator/kappa") and how to
// read its value off the settings a run used.
struct RecordedSetting {
  nlohmann::json::json_pointer key;
  std::function<nlohmann::json(const EvaluationSettings&)> value;
};

// The options of `vdc evaluate` as given on the command line.
struct EvaluateOptions {
  std::string model_path, mesh_path, out_dir;
  std::string visibility;  // comma-separated visibility labels
  std::string planners;    // comma-separated planner names
  std::string anchors;     // "x,y,z;x,y,z"; empty: the built-in mug's two handle points
  bool baseline = false;
  bool no_noise = false;
  std::string sensor;  // --sensor; empty: not given
  bool no_figure = false;
  bool distance_given = false;            // --distance; otherwise the model's training distance
  EvaluationSettings settings;            // the options that set a field directly
  std::vector<RecordedSetting> recorded;  // filled by addEvaluateOptions
};

// Declares every option of `vdc evaluate` on `command`, bound to `options` (which must outlive
// the parse). Each option is declared once, in evaluation_options.cpp, with its flag, help, range
// and the key summary.json records it under: a new option is one declaration there (and its
// field in EvaluationSettings).
void addEvaluateOptions(CLI::App& command, EvaluateOptions& options);

// The values of the robot-realism options, each throwing vdc::Error that names the option for a
// wrong count, a value that is not a number, negative or not finite:
// --camera-pose-noise and --hand-eye-bias "DEG,MM" into `error` (noise or bias part).
void parseCameraPoseNoise(const std::string& text, CameraPoseError& error);
void parseHandEyeBias(const std::string& text, CameraPoseError& error);
// --mesh-scale "SX,SY,SZ" (each > 0) and --mesh-dents "N,DEPTH_MM" (N an integer >= 0).
void parseMeshScale(const std::string& text, MeshPerturbation& perturbation);
void parseMeshDents(const std::string& text, MeshPerturbation& perturbation);

// What the options ask for, parsed.
struct EvaluationRequest {
  EvaluationSettings settings;  // with the visibility radii; distance and noise: resolveSettings
  std::vector<EvaluationPlanner> planners;
  std::vector<Eigen::Vector3d> anchors;  // object frame [m]
};
// Throws vdc::Error naming the option for an empty or malformed list.
EvaluationRequest parseEvaluateOptions(const EvaluateOptions& options);

// The settings completed for `model`: its training distance unless --distance was given, and the
// noise and sensor; throws vdc::Error for a bad setting (checkEvaluationSettings).
EvaluationSettings resolveSettings(EvaluationSettings settings, const EvaluateOptions& options,
                                   const ModelBundle& model);

// summary.json's record of the settings a run used: every RecordedSetting under its key.
nlohmann::json recordedSettings(const EvaluateOptions& options, const EvaluationSettings& used);

}  // namespace vdc::tools
