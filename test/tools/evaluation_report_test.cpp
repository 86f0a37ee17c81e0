// `vdc evaluate`'s own business, without running the tool: its option lists and labels, what
// summary.json records of the settings, and the errors.csv contract.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "evaluation_csv.h"
#include "evaluation_labels.h"
#include "evaluation_options.h"
#include "evaluation_summary.h"
#include "sensor_option.h"
#include "view_direction_classification/common/error.h"

namespace vdc::tools {
namespace {

TEST(EvaluationReportTest,
     ErrorsCsvHasTheContractColumnsAndOneRowPerPlannerSettingSequenceAndView) {
  EvaluationResult result;
  result.planner = "random";
  for (const double radius : {kAllVisible, 0.08}) {
    SettingErrors setting;
    setting.radius = radius;
    setting.errors_deg = Eigen::MatrixXd::Constant(2, 3, 12.5);
    setting.position_errors_mm = Eigen::MatrixXd::Constant(2, 3, 3.25);
    result.settings.push_back(setting);
  }
  EvaluationResult baseline = result;
  baseline.planner = "ppf_baseline";
  std::ostringstream csv;
  writeErrorsCsv(csv, {result, baseline});

  std::istringstream lines(csv.str());
  std::string line;
  ASSERT_TRUE(std::getline(lines, line));
  EXPECT_EQ(line,
            "planner,visibility,sequence,view,map_error_deg,event,time_s,views_fused,cone90_deg,"
            "inside_cone90,position_error_mm");
  int rows = 0;
  std::set<std::string> visibilities, planners;
  while (std::getline(lines, line)) {
    ++rows;
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    if (line.back() == ',') fields.push_back("");  // getline drops a last empty field
    ASSERT_EQ(fields.size(), 11u) << line;
    planners.insert(fields[0]);
    visibilities.insert(fields[1]);
    EXPECT_GE(std::stoi(fields[3]), 1);
    EXPECT_LE(std::stoi(fields[3]), 3);
    EXPECT_DOUBLE_EQ(std::stod(fields[4]), 12.5);
    EXPECT_DOUBLE_EQ(std::stod(fields[10]), 3.25);
  }
  EXPECT_EQ(rows, 2 * 2 * 2 * 3);
  EXPECT_EQ(planners, (std::set<std::string>{"random", "ppf_baseline"}));
  EXPECT_EQ(visibilities, (std::set<std::string>{"all", "0.08"}));
}

TEST(EvaluationReportTest, ErrorsCsvRowsNameTheirSequenceFromZeroAndViewFromOne) {
  EvaluationResult result;
  result.planner = "random";
  SettingErrors setting;
  setting.radius = 0.05;
  setting.errors_deg.resize(2, 1);
  setting.errors_deg << 1.23456, 90.0;
  // No position estimate for the first (NaN): an empty cell.
  setting.position_errors_mm.resize(2, 1);
  setting.position_errors_mm << std::numeric_limits<double>::quiet_NaN(), 4.5;
  result.settings.push_back(setting);
  std::ostringstream csv;
  writeErrorsCsv(csv, {result});
  // Without trust signals (a single-view method) their cells are empty.
  EXPECT_EQ(csv.str(),
            "planner,visibility,sequence,view,map_error_deg,event,time_s,views_fused,cone90_deg,"
            "inside_cone90,position_error_mm\n"
            "random,0.05,0,1,1.2346,view,,,,,\n"
            "random,0.05,1,1,90.0000,view,,,,,4.5000\n");
}

TEST(EvaluationReportTest, ErrorsCsvGivesTheEstimatorsTrustSignalsAndWhetherTheTruthIsInside) {
  EvaluationResult result;
  result.planner = "random";
  SettingErrors setting;
  setting.errors_deg.resize(1, 2);
  setting.errors_deg << 100.0, 8.0;
  setting.views_fused.resize(1, 2);
  setting.views_fused << 1, 2;
  setting.cone90_deg.resize(1, 2);
  setting.cone90_deg << 150.0, 7.5;
  result.settings.push_back(setting);
  std::ostringstream csv;
  writeErrorsCsv(csv, {result});
  EXPECT_EQ(csv.str().substr(csv.str().find('\n') + 1),
            "random,all,0,1,100.0000,view,,1,150.0000,1,\n"
            "random,all,0,2,8.0000,view,,2,7.5000,0,\n");
}

TEST(EvaluationReportTest, ErrorsCsvGivesAStreamsFusionsThenItsViewEndsWithTheirTimes) {
  StreamEvaluationResult stream;
  stream.name = "stream_30hz";
  StreamSettingResult setting;
  setting.radius = 0.06;
  StreamSequenceResult sequence;
  sequence.fusions = {{0.0, 1, 1, 120.0, 160.0}, {3.1, 1, 2, 20.0, 25.0}};
  sequence.view_ends = {{2.0, 1, 1, 120.0, 160.0}, {6.5, 2, 2, 20.0, 25.0}};
  setting.sequences = {sequence};
  stream.settings = {setting};
  std::ostringstream csv;
  writeErrorsCsv(csv, {}, {stream});
  EXPECT_EQ(csv.str().substr(csv.str().find('\n') + 1),
            "stream_30hz,0.06,0,1,120.0000,fused,0.0000,1,160.0000,1,\n"
            "stream_30hz,0.06,0,1,20.0000,fused,3.1000,2,25.0000,1,\n"
            "stream_30hz,0.06,0,1,120.0000,dwell_end,2.0000,1,160.0000,1,\n"
            "stream_30hz,0.06,0,2,20.0000,dwell_end,6.5000,2,25.0000,1,\n");
}

TEST(EvaluationReportTest, SummaryGivesMedianPositionErrorsPerViewIgnoringViewsWithoutOne) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  SettingErrors setting;
  setting.errors_deg = Eigen::MatrixXd::Constant(3, 2, 10.0);
  setting.position_errors_mm.resize(3, 2);
  setting.position_errors_mm << none, 3.0, none, none, none, 5.0;
  EvaluationReport report;
  report.settings.views = 2;
  report.results.push_back({});
  report.results.back().planner = "random";
  report.results.back().settings.push_back(setting);
  report.baseline.emplace();
  report.baseline->result.planner = "ppf_baseline";
  report.baseline->result.settings.push_back(setting);
  const nlohmann::json summary = evaluationSummary(report);
  const nlohmann::json& planned = summary["planners"][0]["settings"][0];
  // After view 1 no sequence has a position: null, not 0 or NaN.
  EXPECT_EQ(planned["median_position_error_mm"], nlohmann::json::parse("[null, 4.0]"));
  EXPECT_EQ(planned["median_position_error_mm_after_views"],
            nlohmann::json::parse(R"({"1": null, "2": 4.0})"));
  EXPECT_EQ(summary["baseline"]["settings"][0]["median_position_error_mm"], 4.0);
}

// A report with one planner, the PPF baseline and PPF followed by ICP, each with its own errors.
EvaluationReport reportWithBothBaselines() {
  EvaluationReport report;
  report.settings.views = 2;
  const std::pair<const char*, double> methods[] = {
      {"random", 10.0}, {"ppf_baseline", 90.0}, {"ppf_icp_baseline", 45.0}};
  std::vector<EvaluationResult> results;
  for (const auto& [name, error] : methods) {
    SettingErrors setting;
    setting.errors_deg = Eigen::MatrixXd::Constant(3, 2, error);
    setting.position_errors_mm = Eigen::MatrixXd::Constant(3, 2, error / 10.0);
    results.push_back({});
    results.back().planner = name;
    results.back().settings.push_back(setting);
  }
  report.results.push_back(results[0]);
  report.baseline = BaselineResult{results[1], 2.5, {{"angle_step_deg", 12.41}}};
  report.baseline_icp = BaselineResult{results[2], 2.6, {{"icp_max_iterations", 50}}};
  return report;
}

TEST(EvaluationReportTest, ErrorsCsvCarriesBothBaselinesAfterThePlanners) {
  std::ostringstream csv;
  writeErrorsCsv(csv, reportWithBothBaselines());
  std::istringstream lines(csv.str());
  std::string line;
  ASSERT_TRUE(std::getline(lines, line));  // the header
  std::vector<std::string> order;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    ASSERT_EQ(fields.size(), 11u) << line;
    if (order.empty() || order.back() != fields[0]) order.push_back(fields[0]);
    // Each method's rows carry its own errors: map_error_deg and position_error_mm.
    const double expected = fields[0] == "random"         ? 10.0
                            : fields[0] == "ppf_baseline" ? 90.0
                                                          : 45.0;
    EXPECT_DOUBLE_EQ(std::stod(fields[4]), expected) << line;
    EXPECT_DOUBLE_EQ(std::stod(fields[10]), expected / 10.0) << line;
  }
  EXPECT_EQ(order, (std::vector<std::string>{"random", "ppf_baseline", "ppf_icp_baseline"}));
}

TEST(EvaluationReportTest, SummaryGivesBothBaselinesWithTheirSettings) {
  const nlohmann::json summary = evaluationSummary(reportWithBothBaselines());
  EXPECT_EQ(summary["baseline"]["name"], "ppf_baseline");
  EXPECT_EQ(summary["baseline"]["settings"][0]["median_error_deg"], 90.0);
  EXPECT_EQ(summary["baseline"]["parameters"]["angle_step_deg"], 12.41);
  EXPECT_EQ(summary["baseline_icp"]["name"], "ppf_icp_baseline");
  EXPECT_EQ(summary["baseline_icp"]["settings"][0]["median_error_deg"], 45.0);
  EXPECT_EQ(summary["baseline_icp"]["settings"][0]["median_position_error_mm"], 4.5);
  EXPECT_EQ(summary["baseline_icp"]["training_seconds"], 2.6);
  EXPECT_EQ(summary["baseline_icp"]["parameters"]["icp_max_iterations"], 50);
  // Without --baseline both are null.
  const nlohmann::json without = evaluationSummary(EvaluationReport{});
  EXPECT_TRUE(without["baseline"].is_null());
  EXPECT_TRUE(without["baseline_icp"].is_null());
}

TEST(EvaluationReportTest, VisibilityLabelsRoundTripAndBadOnesAreRefused) {
  EXPECT_EQ(visibilityLabel(kAllVisible), "all");
  EXPECT_EQ(visibilityLabel(0.08), "0.08");
  EXPECT_EQ(visibilityLabel(0.035), "0.035");
  for (const double r : {0.08, 0.03, 0.055, 1.0 / 3.0}) {
    EXPECT_EQ(parseVisibility(visibilityLabel(r)), r);
  }
  EXPECT_EQ(parseVisibility("all"), kAllVisible);
  for (const char* bad : {"", "none", "-0.05", "0", "0.05cm", "nan", "inf"}) {
    EXPECT_THROW(parseVisibility(bad), Error) << bad;
  }
}

TEST(EvaluationReportTest, PlannerNamesParseBackAndUnknownOnesAreRefused) {
  EXPECT_THROW(parseEvaluationPlanner("greedy"), Error);
  EXPECT_EQ(parseEvaluationPlanner("information_gain"), EvaluationPlanner::kInformationGain);
  for (const EvaluationPlanner planner :
       {EvaluationPlanner::kRandom, EvaluationPlanner::kInformativeness,
        EvaluationPlanner::kInformationGain}) {
    EXPECT_EQ(parseEvaluationPlanner(evaluationPlannerName(planner)), planner);
  }
}

// The options parsed from `arguments` (after "evaluate --model m.h5 --mesh m.ply --out out").
class EvaluateOptionsTest : public ::testing::Test {
 protected:
  void parse(const std::string& arguments) {
    addEvaluateOptions(command_, options_);
    command_.parse("--model m.h5 --mesh m.ply --out out " + arguments, false);
  }
  CLI::App command_{"evaluate"};
  EvaluateOptions options_;
};

TEST_F(EvaluateOptionsTest, SummaryRecordsEverySettingARunUsedUnderItsKey) {
  parse(
      "--sequences 3 --views 4 --candidates 9 --seed 5 --distance 0.5 --kappa 2.5 --n-feat 7 "
      "--max-components 11 --min-weight 0.01 --psum-exponent 2.5 --belief-weight-floor 0.001 "
      "--sharpness-ratio 20 "
      "--refinement-views 3 --search-below-score 0.5 --no-noise "
      "--min-view-separation 0.2 --independent-view-separation 0.5 --stream-rate 15 --dwell 3 "
      "--refinement icp --camera-pose-noise 1,5 --hand-eye-bias 2,4 --mesh-scale 1,1,1.03 "
      "--mesh-dents 3,1.5 --camera-pose-uncertainty 2.5 --camera-pose-uncertainty-mm 7 "
      "--model-error 4");
  ModelBundle model;
  model.parameters.distance = 0.7;
  const EvaluationSettings used =
      resolveSettings(parseEvaluateOptions(options_).settings, options_, model);
  const nlohmann::json expected = {{"sequences", 3},
                                   {"views", 4},
                                   {"candidates", 9},
                                   {"seed", 5u},
                                   {"distance_m", 0.5},
                                   {"noise", false},
                                   {"sensor", "none"},
                                   {"stream_rate_hz", 15.0},
                                   {"stream_dwell_s", 3.0},
                                   {"camera_pose_noise", {{"deg", 1.0}, {"mm", 5.0}}},
                                   {"hand_eye_bias", {{"deg", 2.0}, {"mm", 4.0}}},
                                   {"mesh_scale", {1.0, 1.0, 1.03}},
                                   {"mesh_dents", {{"dents", 3}, {"depth_mm", 1.5}}},
                                   {"estimator",
                                    {{"n_feat", 7},
                                     {"kappa", 2.5},
                                     {"max_components", 11},
                                     {"min_weight", 0.01},
                                     {"psum_exponent", 2.5},
                                     {"refinement_views", 3},
                                     {"search_below_score", 0.5},
                                     {"belief_weight_floor", 0.001},
                                     {"sharpness_ratio", 20.0},
                                     {"min_view_separation", 0.2},
                                     {"independent_view_separation", 0.5},
                                     {"refinement", "icp"},
                                     {"camera_pose_uncertainty_deg", 2.5},
                                     {"camera_pose_uncertainty_mm", 7.0},
                                     {"model_error_mm", 4.0}}}};
  EXPECT_EQ(recordedSettings(options_, used), expected);
}

TEST_F(EvaluateOptionsTest, RefinementIsTheEstimatorsUnlessGivenAndUnknownNamesAreRefused) {
  parse("");
  EXPECT_EQ(parseEvaluateOptions(options_).settings.estimator.refinement,
            EstimatorParameters{}.refinement);
  CLI::App other{"evaluate"};
  EvaluateOptions other_options;
  addEvaluateOptions(other, other_options);
  other.parse("--model m.h5 --mesh m.ply --out out --refinement none", false);
  EXPECT_EQ(other_options.settings.estimator.refinement, RefinementMode::kNone);
  CLI::App bad{"evaluate"};
  EvaluateOptions bad_options;
  addEvaluateOptions(bad, bad_options);
  EXPECT_THROW(bad.parse("--model m.h5 --mesh m.ply --out out --refinement gicp", false),
               CLI::ValidationError);
  // The enum's number is not a name.
  CLI::App numbered{"evaluate"};
  EvaluateOptions numbered_options;
  addEvaluateOptions(numbered, numbered_options);
  EXPECT_THROW(numbered.parse("--model m.h5 --mesh m.ply --out out --refinement 1", false),
               CLI::ValidationError);
}

TEST_F(EvaluateOptionsTest, DistanceIsTheModelsUnlessGiven) {
  parse("");
  ModelBundle model;
  model.parameters.distance = 0.7;
  const EvaluationRequest request = parseEvaluateOptions(options_);
  EXPECT_EQ(resolveSettings(request.settings, options_, model).distance, 0.7);
  EXPECT_TRUE(resolveSettings(request.settings, options_, model).noise);
}

TEST_F(EvaluateOptionsTest, SensorIsTheDefaultGaussianUnlessGivenAndIsRecorded) {
  parse("");
  const ModelBundle model;
  const EvaluationSettings by_default =
      resolveSettings(parseEvaluateOptions(options_).settings, options_, model);
  EXPECT_TRUE(by_default.noise);
  EXPECT_EQ(by_default.sensor, DepthSensor::kKinectGaussian);
  EXPECT_EQ(recordedSettings(options_, by_default)["sensor"], "kinect_gaussian");

  CLI::App command{"evaluate"};
  EvaluateOptions options;
  addEvaluateOptions(command, options);
  command.parse("--model m --mesh m --out o --sensor tof", false);
  const EvaluationSettings tof =
      resolveSettings(parseEvaluateOptions(options).settings, options, model);
  EXPECT_TRUE(tof.noise);
  EXPECT_EQ(tof.sensor, DepthSensor::kTimeOfFlight);
  EXPECT_EQ(recordedSettings(options, tof)["sensor"], "tof");
}

TEST_F(EvaluateOptionsTest, SensorNoneIsNoNoiseAndAnUnknownOrContradictorySensorIsRefused) {
  EXPECT_FALSE(selectSensor("none", false).noise);
  EXPECT_EQ(selectSensor("", false).sensor, DepthSensor::kKinectGaussian);
  EXPECT_FALSE(selectSensor("", true).noise);
  EXPECT_EQ(selectSensor("structured_light", false).sensor, DepthSensor::kStructuredLight);
  try {
    selectSensor("active_stereo", true);
    ADD_FAILURE() << "--no-noise with --sensor active_stereo was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--no-noise contradicts --sensor active_stereo"),
              std::string::npos);
  }
  CLI::App command{"evaluate"};
  EvaluateOptions options;
  addEvaluateOptions(command, options);
  EXPECT_THROW(command.parse("--model m --mesh m --out o --sensor kinect2", false),
               CLI::ValidationError);
}

TEST_F(EvaluateOptionsTest, ListsParseIntoRadiiPlannersAndAnchors) {
  parse("--visibility all,0.05 --planner random,information_gain --anchors '0,0,0.1;0.02,0,0'");
  const EvaluationRequest request = parseEvaluateOptions(options_);
  EXPECT_EQ(request.settings.visibility_radii, (std::vector<double>{kAllVisible, 0.05}));
  EXPECT_EQ(request.planners,
            (std::vector<EvaluationPlanner>{EvaluationPlanner::kRandom,
                                            EvaluationPlanner::kInformationGain}));
  ASSERT_EQ(request.anchors.size(), 2u);
  EXPECT_EQ(request.anchors[1], Eigen::Vector3d(0.02, 0, 0));
}

TEST_F(EvaluateOptionsTest, MalformedListsAreUsageErrors) {
  for (const char* bad :
       {"--visibility none", "--visibility ,", "--planner greedy", "--planner ,"}) {
    CLI::App command{"evaluate"};
    EvaluateOptions options;
    addEvaluateOptions(command, options);
    EXPECT_THROW(command.parse(std::string("--model m --mesh m --out o ") + bad, false),
                 CLI::ValidationError)
        << bad;
  }
}

TEST_F(EvaluateOptionsTest, StreamRateAndDwellAreZeroOrMoreAndFinite) {
  for (const char* bad : {"--stream-rate -1", "--stream-rate nan", "--stream-rate inf",
                          "--stream-rate 30hz", "--dwell -0.5", "--dwell nan",
                          "--min-view-separation nan", "--independent-view-separation inf"}) {
    CLI::App command{"evaluate"};
    EvaluateOptions options;
    addEvaluateOptions(command, options);
    EXPECT_THROW(command.parse(std::string("--model m --mesh m --out o ") + bad, false),
                 CLI::ValidationError)
        << bad;
  }
  parse("--stream-rate 0 --dwell 0");
  EXPECT_EQ(options_.settings.stream_rate_hz, 0.0);
  EXPECT_EQ(options_.settings.stream_dwell_s, 0.0);
}

TEST_F(EvaluateOptionsTest, PoseErrorAndMeshOptionsParseIntoTheSettingsAndDefaultToNone) {
  parse("");
  EXPECT_FALSE(options_.settings.camera_pose_error.any());
  EXPECT_FALSE(options_.settings.mesh_perturbation.any());
  CLI::App command{"evaluate"};
  EvaluateOptions options;
  addEvaluateOptions(command, options);
  command.parse(
      "--model m --mesh m --out o --camera-pose-noise 1,5 --hand-eye-bias 2,4.5 "
      "--mesh-scale 1,0.98,1.03 --mesh-dents 4,2",
      false);
  const CameraPoseError& error = options.settings.camera_pose_error;
  EXPECT_EQ(error.noise_deg, 1.0);
  EXPECT_EQ(error.noise_mm, 5.0);
  EXPECT_EQ(error.bias_deg, 2.0);
  EXPECT_EQ(error.bias_mm, 4.5);
  const MeshPerturbation& mesh = options.settings.mesh_perturbation;
  EXPECT_EQ(mesh.scale, Eigen::Vector3d(1.0, 0.98, 1.03));
  EXPECT_EQ(mesh.dents, 4);
  EXPECT_DOUBLE_EQ(mesh.dent_depth, 0.002);
}

TEST_F(EvaluateOptionsTest, BadPoseErrorAndMeshValuesAreRefusedNamingTheOption) {
  const std::vector<std::pair<std::string, std::string>> bad = {{"--camera-pose-noise", "1"},
                                                                {"--camera-pose-noise", "1,5,3"},
                                                                {"--camera-pose-noise", "-1,5"},
                                                                {"--camera-pose-noise", "nan,5"},
                                                                {"--hand-eye-bias", "2,inf"},
                                                                {"--hand-eye-bias", "2,5mm"},
                                                                {"--hand-eye-bias", ",5"},
                                                                {"--mesh-scale", "1,1"},
                                                                {"--mesh-scale", "1,0,1"},
                                                                {"--mesh-scale", "1,1,-1.03"},
                                                                {"--mesh-scale", "1,1,nan"},
                                                                {"--mesh-dents", "2.5,1"},
                                                                {"--mesh-dents", "-2,1"},
                                                                {"--mesh-dents", "3,-1"},
                                                                {"--mesh-dents", "3"}};
  for (const auto& [flag, value] : bad) {
    // The parser's vdc::Error names the option; the command line refuses it as a usage error.
    CameraPoseError error;
    MeshPerturbation mesh;
    try {
      if (flag == "--camera-pose-noise") parseCameraPoseNoise(value, error);
      if (flag == "--hand-eye-bias") parseHandEyeBias(value, error);
      if (flag == "--mesh-scale") parseMeshScale(value, mesh);
      if (flag == "--mesh-dents") parseMeshDents(value, mesh);
      ADD_FAILURE() << flag << " " << value << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(flag + ": ", 0), 0u) << e.what();
    }
    CLI::App command{"evaluate"};
    EvaluateOptions options;
    addEvaluateOptions(command, options);
    EXPECT_THROW(command.parse("--model m --mesh m --out o " + flag + " " + value, false),
                 CLI::ValidationError)
        << flag << " " << value;
  }
}

TEST_F(EvaluateOptionsTest, MalformedAnchorsAreRefusedNamingTheOption) {
  parse("--anchors '0,0;1,2,3'");
  EXPECT_THROW(parseEvaluateOptions(options_), Error);
}

}  // namespace
}  // namespace vdc::tools
