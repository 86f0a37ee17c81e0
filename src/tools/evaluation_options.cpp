#include "evaluation_options.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "evaluation_labels.h"
#include "sensor_option.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/estimation/refinement_mode.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc::tools {

namespace {

// The paper's settings: all visible and r_vis = 8 .. 3 cm.
constexpr const char* kDefaultVisibility = "all,0.08,0.07,0.06,0.05,0.04,0.03";
constexpr const char* kDefaultPlanners = "random";

std::vector<std::string> splitList(const std::string& text, char separator) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, separator);) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

// "x,y,z;x,y,z" in metres, object frame.
std::vector<Eigen::Vector3d> parseAnchors(const std::string& text) {
  std::vector<Eigen::Vector3d> anchors;
  for (const std::string& point : splitList(text, ';')) {
    const std::vector<std::string> coordinates = splitList(point, ',');
    Eigen::Vector3d anchor;
    bool valid = coordinates.size() == 3;
    for (std::size_t k = 0; valid && k < 3; ++k) {
      char* end = nullptr;
      anchor(static_cast<Eigen::Index>(k)) = std::strtod(coordinates[k].c_str(), &end);
      valid = end == coordinates[k].c_str() + coordinates[k].size() && std::isfinite(anchor(k));
    }
    if (!valid) {
      throw Error("--anchors: '" + point +
                  "' is not a point x,y,z in metres (points separated by ;)");
    }
    anchors.push_back(anchor);
  }
  if (anchors.empty()) throw Error("--anchors: no anchor point given");
  return anchors;
}

// A CLI validator for a comma-separated list, so a malformed list is a usage error (exit code 2)
// reported before any work.
template <typename Parse>
CLI::Validator listValidator(Parse parse, const std::string& empty_message) {
  return CLI::Validator(
      [parse, empty_message](const std::string& text) -> std::string {
        try {
          for (const std::string& item : splitList(text, ',')) parse(item);
        } catch (const Error& error) {
          return error.what();
        }
        return splitList(text, ',').empty() ? empty_message : "";
      },
      "LIST");
}

// Declares option `flag` on the settings field that `field` selects (a lambda returning a
// reference to it, for const and non-const settings) and records the value a run used under
// `summary_key` in summary.json (empty: not recorded).
template <typename Field>
CLI::Option* addSetting(CLI::App& command, EvaluateOptions& options, const std::string& flag,
                        Field field, const std::string& summary_key, const std::string& help) {
  if (!summary_key.empty()) {
    options.recorded.push_back({nlohmann::json::json_pointer(summary_key),
                                [field](const EvaluationSettings& s) { return field(s); }});
  }
  return command.add_option(flag, field(options.settings), help);
}

// A CLI validator for a number >= 0 that is finite (CLI::Range lets NaN through).
CLI::Validator nonNegativeFinite() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || value < 0.0) {
          return "must be a finite number >= 0, got '" + text + "'";
        }
        return "";
      },
      "");
}

// A sharpness ratio (bingham.h): 0, or a finite number >= 1.
CLI::Validator zeroOrAtLeastOne() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool number = end != text.c_str() && *end == '\0';
        if (!number || !(value == 0.0 || (std::isfinite(value) && value >= 1.0))) {
          return "must be 0 or a finite number >= 1, got '" + text + "'";
        }
        return "";
      },
      "0 or >= 1");
}

// A CLI validator for a finite number (CLI's own conversion accepts "nan" and "inf").
CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) {
          return "must be a finite number, got '" + text + "'";
        }
        return "";
      },
      "");
}

// Exactly `count` comma-separated finite numbers >= 0 (empty items count: "1,,2" is three).
std::vector<double> parseNonNegativeNumbers(const std::string& text, std::size_t count,
                                            const std::string& flag, const std::string& form) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) items.push_back(item);
  if (!text.empty() && text.back() == ',') items.emplace_back();
  if (items.size() != count) {
    throw Error(flag + ": expected " + form + " (" + std::to_string(count) +
                " comma-separated numbers), got '" + text + "'");
  }
  std::vector<double> values;
  for (const std::string& item : items) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(value) || value < 0.0) {
      throw Error(flag + ": '" + item + "' in '" + text +
                  "' is not a finite number >= 0 (expected " + form + ")");
    }
    values.push_back(value);
  }
  return values;
}

// A CLI validator that runs `parse` on a scratch value, so a bad value is a usage error (exit
// code 2) reported before any work, with the parser's message.
template <typename Value, typename Parse>
CLI::Validator parsedBy(Parse parse) {
  return CLI::Validator(
      [parse](const std::string& text) -> std::string {
        Value scratch;
        try {
          parse(text, scratch);
        } catch (const Error& error) {
          // CLI names the option itself: drop the message's own "--flag: ".
          const std::string message = error.what();
          const std::size_t colon = message.find(": ");
          return message.rfind("--", 0) == 0 && colon != std::string::npos
                     ? message.substr(colon + 2)
                     : message;
        }
        return "";
      },
      "");
}

// Declares a "A,B[,C]" option that `parse` reads into the settings' `part`, recorded as `record`
// under `summary_key`.
template <typename Part, typename Parse, typename Record>
void addPartOption(CLI::App& command, EvaluateOptions& options, const std::string& flag, Part part,
                   Parse parse, Record record, const std::string& summary_key,
                   const std::string& help) {
  using Value = std::decay_t<decltype(part(options.settings))>;
  command
      .add_option_function<std::string>(
          flag,
          [&options, part, parse](const std::string& text) { parse(text, part(options.settings)); },
          help)
      ->check(parsedBy<Value>(parse));
  options.recorded.push_back(
      {nlohmann::json::json_pointer(summary_key),
       [part, record](const EvaluationSettings& s) { return record(part(s)); }});
}

// The robot-realism options: the camera pose the estimator believes, the object it sees.
void addRealismOptions(CLI::App& command, EvaluateOptions& options) {
  const auto pose_error = [](auto& s) -> auto& { return s.camera_pose_error; };
  addPartOption(
      command, options, "--camera-pose-noise", pose_error, parseCameraPoseNoise,
      [](const CameraPoseError& e) {
        return nlohmann::json{{"deg", e.noise_deg}, {"mm", e.noise_mm}};
      },
      "/camera_pose_noise",
      "DEG,MM: the camera pose the estimator is given is off by a random rotation and shift per "
      "view, RMS DEG degrees and MM mm (per-axis Gaussians, camera frame); default 0,0");
  addPartOption(
      command, options, "--hand-eye-bias", pose_error, parseHandEyeBias,
      [](const CameraPoseError& e) {
        return nlohmann::json{{"deg", e.bias_deg}, {"mm", e.bias_mm}};
      },
      "/hand_eye_bias",
      "DEG,MM: and by a constant rotation of DEG degrees and shift of MM mm per sequence "
      "(directions drawn per sequence, camera frame); default 0,0");
  const auto perturbation = [](auto& s) -> auto& { return s.mesh_perturbation; };
  addPartOption(
      command, options, "--mesh-scale", perturbation, parseMeshScale,
      [](const MeshPerturbation& p) {
        return nlohmann::json::array({p.scale.x(), p.scale.y(), p.scale.z()});
      },
      "/mesh_scale",
      "SX,SY,SZ: render the views from the mesh scaled per axis (object frame), while the model "
      "stays the clean mesh's; default 1,1,1");
  addPartOption(
      command, options, "--mesh-dents", perturbation, parseMeshDents,
      [](const MeshPerturbation& p) {
        return nlohmann::json{{"dents", p.dents}, {"depth_mm", 1000.0 * p.dent_depth}};
      },
      "/mesh_dents",
      "N,DEPTH_MM: and with N smooth dents of DEPTH_MM mm pushed inward (radius a tenth of the "
      "mesh's diagonal, placed from the seed); default 0,0");
}

}  // namespace

void parseCameraPoseNoise(const std::string& text, CameraPoseError& error) {
  const auto values = parseNonNegativeNumbers(text, 2, "--camera-pose-noise", "DEG,MM");
  error.noise_deg = values[0];
  error.noise_mm = values[1];
}

void parseHandEyeBias(const std::string& text, CameraPoseError& error) {
  const auto values = parseNonNegativeNumbers(text, 2, "--hand-eye-bias", "DEG,MM");
  error.bias_deg = values[0];
  error.bias_mm = values[1];
}

void parseMeshScale(const std::string& text, MeshPerturbation& perturbation) {
  const auto values = parseNonNegativeNumbers(text, 3, "--mesh-scale", "SX,SY,SZ");
  for (std::size_t k = 0; k < 3; ++k) {
    if (!(values[k] > 0.0)) {
      throw Error("--mesh-scale: every scale must be above 0, got '" + text + "'");
    }
  }
  perturbation.scale = Eigen::Vector3d(values[0], values[1], values[2]);
}

void parseMeshDents(const std::string& text, MeshPerturbation& perturbation) {
  const auto values = parseNonNegativeNumbers(text, 2, "--mesh-dents", "N,DEPTH_MM");
  if (values[0] != std::floor(values[0]) || values[0] > 10000.0) {
    throw Error("--mesh-dents: the number of dents must be a whole number up to 10000, got '" +
                text + "'");
  }
  perturbation.dents = static_cast<int>(values[0]);
  perturbation.dent_depth = values[1] / 1000.0;
}

void addEvaluateOptions(CLI::App& command, EvaluateOptions& options) {
  options.visibility = kDefaultVisibility;
  options.planners = kDefaultPlanners;
  command.add_option("--model", options.model_path, "model bundle (HDF5)")->required();
  command.add_option("--mesh", options.mesh_path, "the object's mesh (the model's object)")
      ->required();
  command.add_option("--out", options.out_dir, "output directory")->required();
  addSetting(
      command, options, "--sequences", [](auto& s) -> auto& { return s.sequences; }, "/sequences",
      "random view sequences")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  addSetting(
      command, options, "--views", [](auto& s) -> auto& { return s.views; }, "/views",
      "views per sequence")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  command
      .add_option("--visibility", options.visibility,
                  "comma-separated settings: 'all' or a radius [m] around the anchors")
      ->capture_default_str()
      ->check(listValidator(parseVisibility, "no visibility setting given"));
  command
      .add_option("--planner", options.planners,
                  "comma-separated: random, informativeness, information_gain")
      ->capture_default_str()
      ->check(listValidator(parseEvaluationPlanner, "no planner given"));
  addSetting(
      command, options, "--candidates", [](auto& s) -> auto& { return s.candidates; },
      "/candidates", "random candidate views per sequence the planners choose from")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  command.add_option("--anchors", options.anchors,
                     "visibility anchors 'x,y,z;x,y,z' [m, object frame]; default: the mug's "
                     "two handle points");
  addSetting(
      command, options, "--seed", [](auto& s) -> auto& { return s.seed; }, "/seed",
      "seed of sequences, orientations and noise")
      ->capture_default_str();
  addSetting(
      command, options, "--distance", [](auto& s) -> auto& { return s.distance; }, "/distance_m",
      "camera distance [m]; default: the model's")
      ->each([&options](const std::string&) { options.distance_given = true; });
  addSetting(
      command, options, "--threads", [](auto& s) -> auto& { return s.threads; }, "",
      "OpenMP threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  // The estimator's tuning knobs (every default was tuned with this evaluation: doc/method.md,
  // "Defaults").
  addSetting(
      command, options, "--n-feat", [](auto& s) -> auto& { return s.estimator.n_feat; },
      "/estimator/n_feat", "most certain features summed per view; 0: the model's value")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  addSetting(
      command, options, "--kappa", [](auto& s) -> auto& { return s.estimator.kappa; },
      "/estimator/kappa", "girdle concentration; 0: the default for the model's view spacing")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  addSetting(
      command, options, "--max-components",
      [](auto& s) -> auto& { return s.estimator.max_components; }, "/estimator/max_components",
      "K_max of the belief")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  addSetting(
      command, options, "--min-weight", [](auto& s) -> auto& { return s.estimator.min_weight; },
      "/estimator/min_weight", "measurement components below this p_sum are dropped")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.5));
  addSetting(
      command, options, "--psum-exponent",
      [](auto& s) -> auto& { return s.estimator.psum_exponent; }, "/estimator/psum_exponent",
      "exponent on the summed view distribution before it weights the girdles (1: unchanged)")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 100.0));
  addSetting(
      command, options, "--refinement-views",
      [](auto& s) -> auto& { return s.estimator.refinement_views; }, "/estimator/refinement_views",
      "views refinement aligns together: this one and the latest fused before it")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  addSetting(
      command, options, "--search-below-score",
      [](auto& s) -> auto& { return s.estimator.belief_check.search_below_score; },
      "/estimator/search_below_score",
      "a poorer best refined fit starts a search beyond the belief (0: never)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  addSetting(
      command, options, "--belief-weight-floor",
      [](auto& s) -> auto& { return s.estimator.belief_weight_floor; },
      "/estimator/belief_weight_floor",
      "belief components below this fraction of the heaviest are dropped")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.5));
  addSetting(
      command, options, "--sharpness-ratio",
      [](auto& s) -> auto& { return s.estimator.sharpness_ratio; }, "/estimator/sharpness_ratio",
      "a belief component this many times sharper than the other factor keeps its mode (0: "
      "every product exact)")
      ->capture_default_str()
      ->check(zeroOrAtLeastOne());
  addSetting(
      command, options, "--camera-pose-uncertainty",
      [](auto& s) -> auto& { return s.estimator.refined_fusion.camera_pose_uncertainty_deg; },
      "/estimator/camera_pose_uncertainty_deg",
      "[deg] RMS rotation error of the camera pose each view's evidence allows for (0: exact "
      "poses)")
      ->capture_default_str()
      ->check(nonNegativeFinite());
  addSetting(
      command, options, "--camera-pose-uncertainty-mm",
      [](auto& s) -> auto& { return s.estimator.refined_fusion.camera_pose_uncertainty_mm; },
      "/estimator/camera_pose_uncertainty_mm",
      "[mm] RMS shift error of the camera pose that each view's position covariance allows for "
      "(0: exact poses)")
      ->capture_default_str()
      ->check(nonNegativeFinite());
  addSetting(
      command, options, "--model-error",
      [](auto& s) -> auto& { return s.estimator.refined_fusion.model_error_mm; },
      "/estimator/model_error_mm",
      "[mm] RMS difference between the object and its mesh that each view's position covariance "
      "allows for (0: the mesh is the object)")
      ->capture_default_str()
      ->check(nonNegativeFinite());
  // Frame selection (estimation/frame_selection.h), in radians as config/estimator.yaml.
  addSetting(
      command, options, "--min-view-separation",
      [](auto& s) -> auto& { return s.estimator.selection.min_view_separation; },
      "/estimator/min_view_separation",
      "[rad] a frame is a new view this far from every fused one; < 0: half the view spacing")
      ->capture_default_str()
      ->check(finiteNumber());
  addSetting(
      command, options, "--independent-view-separation",
      [](auto& s) -> auto& { return s.estimator.selection.independent_view_separation; },
      "/estimator/independent_view_separation",
      "[rad] views this far apart are independent evidence (nearer: tempered); < 0: the view "
      "spacing; 0: no tempering")
      ->capture_default_str()
      ->check(finiteNumber());
  // Camera streams (evaluation/stream_evaluation.h).
  addSetting(
      command, options, "--stream-rate", [](auto& s) -> auto& { return s.stream_rate_hz; },
      "/stream_rate_hz",
      "[Hz] also run each sequence's views as a camera stream at this frame rate; 0: no stream")
      ->capture_default_str()
      ->check(nonNegativeFinite());
  addSetting(
      command, options, "--dwell", [](auto& s) -> auto& { return s.stream_dwell_s; },
      "/stream_dwell_s", "[s] the stream's camera stays this long at each view")
      ->capture_default_str()
      ->check(nonNegativeFinite());
  // Refinement (doc/method.md, "Refinement"): by name only, recorded by name. (CLI11's
  // CheckedTransformer would also take the enum's number, "--refinement 1".)
  std::vector<std::string> refinement_names;
  for (const auto& choice : refinementModeChoices()) refinement_names.push_back(choice.first);
  command
      .add_option_function<std::string>(
          "--refinement",
          [&options](const std::string& name) {
            options.settings.estimator.refinement = parseRefinementMode(name);
          },
          "geometric refinement after each view: none or icp (default: the estimator's, " +
              refinementModeName(EstimatorParameters{}.refinement) + ")")
      ->check(CLI::IsMember(refinement_names));
  options.recorded.push_back(
      {nlohmann::json::json_pointer("/estimator/refinement"),
       [](const EvaluationSettings& s) { return refinementModeName(s.estimator.refinement); }});
  addRealismOptions(command, options);
  command.add_flag(
      "--baseline", options.baseline,
      "also run the single-view baselines on the random planner's views: PCL's PPF, and "
      "PPF followed by point-to-plane ICP");
  command.add_flag("--no-noise", options.no_noise, "render the views without sensor noise");
  options.recorded.push_back({nlohmann::json::json_pointer("/noise"),
                              [](const EvaluationSettings& s) { return s.noise; }});
  addSensorOption(command, &options.sensor);
  options.recorded.push_back(
      {nlohmann::json::json_pointer("/sensor"),
       [](const EvaluationSettings& s) { return selectionName(s.noise, s.sensor); }});
  command.add_flag("--no-figure", options.no_figure, "no plots (no matplotlib needed)");
}

EvaluationRequest parseEvaluateOptions(const EvaluateOptions& options) {
  EvaluationRequest request;
  request.settings = options.settings;
  request.settings.visibility_radii.clear();
  for (const std::string& label : splitList(options.visibility, ',')) {
    request.settings.visibility_radii.push_back(parseVisibility(label));
  }
  if (request.settings.visibility_radii.empty()) throw Error("--visibility: no setting given");
  for (const std::string& name : splitList(options.planners, ',')) {
    request.planners.push_back(parseEvaluationPlanner(name));
  }
  if (request.planners.empty()) throw Error("--planner: no planner given");
  request.anchors = options.anchors.empty() ? mugHandleAnchors() : parseAnchors(options.anchors);
  return request;
}

EvaluationSettings resolveSettings(EvaluationSettings settings, const EvaluateOptions& options,
                                   const ModelBundle& model) {
  // Evaluate at the distance the model was trained for unless told otherwise.
  if (!options.distance_given) settings.distance = model.parameters.distance;
  const SensorSelection sensor = selectSensor(options.sensor, options.no_noise);
  settings.noise = sensor.noise;
  settings.sensor = sensor.sensor;
  checkEvaluationSettings(settings);
  return settings;
}

nlohmann::json recordedSettings(const EvaluateOptions& options, const EvaluationSettings& used) {
  nlohmann::json record = nlohmann::json::object();
  for (const RecordedSetting& setting : options.recorded) record[setting.key] = setting.value(used);
  return record;
}

}  // namespace vdc::tools
