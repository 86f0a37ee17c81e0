// The `vdc` tool's contract as its users (scripts, CI jobs) see it: exit code 0 on success and
// for --help, 2 for a usage error, 1 with one "vdc: ..." line on stderr for a failure; bad files
// never crash it and a failed command leaves existing output files untouched.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/command_run.h"
#include "support/temporary_directory_test.h"

namespace {

namespace fs = std::filesystem;

using ToolRun = vdc::test::CommandRun;

ToolRun runVdc(const std::string& arguments) {
  return vdc::test::runCommand(std::string(VDC_EXECUTABLE) + " " + arguments);
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeFile(const fs::path& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

// A failure is exactly one line naming the tool.
void expectOneFailureLine(const ToolRun& run) {
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_EQ(run.output.rfind("vdc: ", 0), 0u) << run.output;
  EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << run.output;
}

class VdcCliTest : public vdc::test::TemporaryDirectoryTest {};

TEST_F(VdcCliTest, HelpExitsZeroAndListsTheSubcommands) {
  const ToolRun run = runVdc("--help");
  EXPECT_EQ(run.exit_code, 0);
  for (const char* subcommand : {"mesh", "views", "train", "inspect", "heatmap", "evaluate"}) {
    EXPECT_NE(run.output.find(subcommand), std::string::npos) << subcommand;
  }
}

TEST_F(VdcCliTest, UsageErrorsExitTwo) {
  EXPECT_EQ(runVdc("").exit_code, 2);                    // no subcommand
  EXPECT_EQ(runVdc("frobnicate").exit_code, 2);          // unknown subcommand
  EXPECT_EQ(runVdc("inspect").exit_code, 2);             // missing required argument
  EXPECT_EQ(runVdc("train --mesh m.ply").exit_code, 2);  // missing --out
  EXPECT_EQ(runVdc("train --mesh m.ply --out m.h5 --views 1").exit_code, 2);  // out of range
  EXPECT_EQ(runVdc("evaluate --model m.h5 --mesh m.ply --out e --sequences 0").exit_code, 2);
  for (const char* range : {"1.5 0.5", "0 1", "1", "0.5 inf"}) {
    EXPECT_EQ(
        runVdc(std::string("train --mesh m.ply --out m.h5 --distance-range ") + range).exit_code, 2)
        << range;
  }
}

TEST_F(VdcCliTest, TrainingOverADistanceRangeWithASensorIsRecordedInTheBundle) {
  ASSERT_EQ(runVdc("mesh mug --out " + path("mug.ply")).exit_code, 0);
  const ToolRun train =
      runVdc("train --quick --views 4 --clouds-per-view 2 --mesh " + path("mug.ply") + " --out " +
             path("m.h5") + " --distance-range 0.8 1.2 --sensor tof");
  ASSERT_EQ(train.exit_code, 0) << train.output;
  const ToolRun inspect = runVdc("inspect " + path("m.h5"));
  EXPECT_NE(inspect.output.find("camera distances    0.80-1.20 m"), std::string::npos)
      << inspect.output;
  EXPECT_NE(inspect.output.find("depth sensor        tof"), std::string::npos) << inspect.output;
}

TEST_F(VdcCliTest, BadStreamOptionsAreUsageErrorsNamingTheOption) {
  for (const char* bad : {"--stream-rate -5", "--stream-rate nan", "--dwell inf"}) {
    const ToolRun run =
        runVdc(std::string("evaluate --model m.h5 --mesh m.ply --out e --no-figure ") + bad);
    EXPECT_EQ(run.exit_code, 2) << bad << ": " << run.output;
    const std::string option = std::string(bad).substr(0, std::string(bad).find(' '));
    EXPECT_EQ(run.output.rfind(option + ": ", 0), 0u) << run.output;
  }
}

TEST_F(VdcCliTest, BadPoseErrorAndMeshOptionsAreUsageErrorsNamingTheOptionOnce) {
  for (const char* bad : {"--camera-pose-noise 1", "--hand-eye-bias -2,5", "--mesh-scale 1,nan,1",
                          "--mesh-dents 2.5,1", "--camera-pose-uncertainty -1"}) {
    const ToolRun run =
        runVdc(std::string("evaluate --model m.h5 --mesh m.ply --out e --no-figure ") + bad);
    EXPECT_EQ(run.exit_code, 2) << bad << ": " << run.output;
    const std::string option = std::string(bad).substr(0, std::string(bad).find(' '));
    EXPECT_EQ(run.output.rfind(option + ": ", 0), 0u) << run.output;
    // CLI names the option; the parser's message does not repeat it.
    EXPECT_EQ(run.output.find(option, option.size()), std::string::npos) << run.output;
  }
}

TEST_F(VdcCliTest, MissingCorruptAndForeignModelFilesFailWithOneLine) {
  const ToolRun missing = runVdc("inspect " + path("absent.h5"));
  expectOneFailureLine(missing);
  EXPECT_NE(missing.output.find("absent.h5"), std::string::npos) << missing.output;

  writeFile(path("garbage.h5"), "this is not an HDF5 file\n");
  expectOneFailureLine(runVdc("inspect " + path("garbage.h5")));
  expectOneFailureLine(runVdc("heatmap --model " + path("garbage.h5") + " --out " + path("h")));

  // A real file of another kind: the tool's own mesh passed as a model.
  ASSERT_EQ(runVdc("mesh mug --out " + path("mug.ply")).exit_code, 0);
  expectOneFailureLine(runVdc("inspect " + path("mug.ply")));
  expectOneFailureLine(runVdc("evaluate --model " + path("mug.ply") + " --mesh " + path("mug.ply") +
                              " --out " + path("e") + " --no-figure"));
}

TEST_F(VdcCliTest, UnknownOrContradictorySensorsAreRefused) {
  EXPECT_EQ(runVdc("train --mesh m.ply --out m.h5 --sensor lidar").exit_code, 2);
  EXPECT_EQ(runVdc("evaluate --model m.h5 --mesh m.ply --out e --sensor lidar").exit_code, 2);
  EXPECT_EQ(runVdc("evaluate-scenes --model a=m.h5:m.ply --out e --sensor lidar").exit_code, 2);
  const ToolRun contradictory = runVdc("train --mesh m.ply --out m.h5 --sensor tof --no-noise");
  expectOneFailureLine(contradictory);
  EXPECT_NE(contradictory.output.find("--sensor none"), std::string::npos) << contradictory.output;
}

TEST_F(VdcCliTest, SensorStatsRefusesFilesThatAreNotScansAndTabulatesEveryModel) {
  writeFile(path("garbage.pcd"), "this is not a point cloud\n");
  expectOneFailureLine(runVdc("sensor-stats --cloud " + path("garbage.pcd")));
  writeFile(path("no_z.pcd"),
            "VERSION .7\nFIELDS x y\nSIZE 4 4\nTYPE F F\nCOUNT 1 1\nWIDTH 1\nHEIGHT 1\n"
            "POINTS 1\nDATA ascii\n1 2\n");
  expectOneFailureLine(runVdc("sensor-stats --cloud " + path("no_z.pcd")));
  const ToolRun run = runVdc("sensor-stats --distance 0.8");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* model :
       {"none", "kinect_gaussian", "structured_light", "active_stereo", "tof"}) {
    EXPECT_NE(run.output.find(std::string("render: ") + model), std::string::npos) << model;
  }
}

TEST_F(VdcCliTest, BadMeshesFailWithOneLine) {
  expectOneFailureLine(runVdc("mesh check " + path("absent.ply")));
  writeFile(path("broken.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n");
  expectOneFailureLine(runVdc("mesh check " + path("broken.ply")));
}

TEST_F(VdcCliTest, AFailedTrainingLeavesAnExistingBundleUntouched) {
  const std::string previous = "the previous bundle's bytes";
  writeFile(path("model.h5"), previous);
  writeFile(path("broken.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n");
  expectOneFailureLine(
      runVdc("train --quick --mesh " + path("broken.ply") + " --out " + path("model.h5")));
  EXPECT_EQ(readFile(path("model.h5")), previous);
  // Nothing half-written is left beside it either.
  EXPECT_EQ(entryCount(), 2);  // model.h5 and broken.ply
}

TEST_F(VdcCliTest, DamagedBopFilesFailWithOneLineNamingThem) {
  ASSERT_EQ(runVdc("mesh mug --out " + path("mug.ply")).exit_code, 0);
  ASSERT_EQ(runVdc("train --quick --views 4 --clouds-per-view 2 --mesh " + path("mug.ply") +
                   " --out " + path("m.h5"))
                .exit_code,
            0);
  const ToolRun written =
      runVdc("write-bop --model 1=" + path("mug.ply") +
             " --views 1 --known 1 --distractors 0 --no-noise --out " + path("bop"));
  ASSERT_EQ(written.exit_code, 0) << written.output;
  const std::string evaluate = "evaluate-bop --dataset " + path("bop") +
                               " --bop-model 1=" + path("m.h5") + " --out " + path("eval") +
                               " --no-fusion";

  const fs::path depth = directory() / "bop" / "test" / "000000" / "depth" / "000000.png";
  writeFile(depth, "not a PNG");
  const ToolRun bad_depth = runVdc(evaluate);
  expectOneFailureLine(bad_depth);
  EXPECT_NE(bad_depth.output.find(depth.string()), std::string::npos) << bad_depth.output;

  const fs::path camera = directory() / "bop" / "test" / "000000" / "scene_camera.json";
  writeFile(camera, R"({"0": {"cam_K": [525, 0, 319.5, 0, 525, 239.5, 0, 0, 1]}})");
  const ToolRun bad_camera = runVdc(evaluate);
  expectOneFailureLine(bad_camera);
  EXPECT_NE(bad_camera.output.find(camera.string() + ", image 0: missing key \"depth_scale\""),
            std::string::npos)
      << bad_camera.output;
}

TEST_F(VdcCliTest, BopModelsInMillimetresScaleToMetresForTraining) {
  ASSERT_EQ(runVdc("mesh mug --out " + path("mug.ply")).exit_code, 0);
  ASSERT_EQ(runVdc("write-bop --model 1=" + path("mug.ply") +
                   " --views 1 --known 1 --distractors 0 --no-noise --out " + path("bop"))
                .exit_code,
            0);
  const std::string model = (directory() / "bop" / "models" / "obj_000001.ply").string();
  EXPECT_NE(runVdc("mesh check " + model).output.find("looks like millimetres"), std::string::npos);
  ASSERT_EQ(runVdc("mesh scale " + model + " --factor 0.001 --out " + path("m.ply")).exit_code, 0);
  const ToolRun check = runVdc("mesh check " + path("m.ply"));
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_EQ(check.output.find("millimetres"), std::string::npos) << check.output;
  // The same summary as the mesh it was written from (sizes in cm after the file name).
  const std::string original = runVdc("mesh check " + path("mug.ply")).output;
  EXPECT_EQ(original.substr(original.find(": ")), check.output.substr(check.output.find(": ")));
}

}  // namespace
