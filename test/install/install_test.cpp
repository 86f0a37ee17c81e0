// The package as a dependency: installed into its install space (scripts/build.sh puts it inside
// the build directory, as catkin_make does in a workspace, in the hidden folder .install), a
// catkin package that depends on it builds and links the core through catkin's exports alone, and
// the installed `vdc` runs with the plot scripts installed beside it (not the source tree's).
// After the install, the source tree's launch files still resolve by package name and the demo
// runs: roslaunch searches the whole package folder, and an install tree inside it that it does
// not skip holds a second demo.launch ("multiple files named [demo.launch] in package").
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "support/command_run.h"

namespace {

namespace fs = std::filesystem;
using vdc::test::runCommand;

// One install for the suite: installing and configuring take most of its time.
class InstalledPackage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("vdc_install_test_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    // catkin bakes the prefix into the installed setup files and package config, so the test
    // installs where the build was configured to, and only into its own build directory.
    if (!insideBuildDirectory()) return;
    fs::remove_all(installPrefix());
    install_run_ = runCommand("cmake --install '" VDC_BINARY_DIR "'");
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  void SetUp() override {
    if (!insideBuildDirectory()) {
      GTEST_SKIP() << "CMAKE_INSTALL_PREFIX (" << installPrefix()
                   << ") is not inside the build directory; configure as scripts/build.sh does";
    }
    ASSERT_EQ(install_run_.exit_code, 0) << install_run_.output;
  }

  static bool insideBuildDirectory() {
    const std::string prefix = fs::weakly_canonical(installPrefix()).string();
    const std::string build = fs::weakly_canonical(VDC_BINARY_DIR).string();
    return prefix.rfind(build + "/", 0) == 0;
  }
  static fs::path installPrefix() { return VDC_INSTALL_PREFIX; }
  static fs::path installedVdc() {
    return installPrefix() / "lib/view_direction_classification/vdc";
  }
  static std::string quickModel() { return VDC_BINARY_DIR "/test_data/mug_quick.h5"; }
  // Runs a command with the install tree's environment, as a user who sourced its setup.bash.
  static vdc::test::CommandRun runInstalled(const std::string& command) {
    return runCommand("bash -c \"export PATH=/usr/bin:/bin:\\$PATH && . '" +
                      (installPrefix() / "setup.bash").string() + "' && " + command + "\"");
  }

  // Runs `command` with the build's devel space sourced and a master port of this test's own.
  static vdc::test::CommandRun runDeveloped(const std::string& command) {
    const std::string master = "http://localhost:" + std::to_string(20000 + ::getpid() % 20000);
    return runCommand(
        "bash -c \"export PATH=/usr/bin:/bin:\\$PATH ROS_HOSTNAME=localhost "
        "ROS_MASTER_URI=" +
        master + " && . '" VDC_BINARY_DIR "/devel/setup.bash' && " + command + "\"");
  }
  // `make demo`'s script on the quick model, two views, headless.
  static vdc::test::CommandRun runDemo(const fs::path& out) {
    return runDeveloped("cd '" VDC_SOURCE_DIR "' && BUILD_DIR='" VDC_BINARY_DIR "' DEMO_MODEL='" +
                        quickModel() + "' DEMO_VIEWS=2 DEMO_OUT='" + out.string() +
                        "' scripts/demo.sh");
  }

  static fs::path root_;
  static vdc::test::CommandRun install_run_;
};
fs::path InstalledPackage::root_;
vdc::test::CommandRun InstalledPackage::install_run_;

TEST_F(InstalledPackage, InstallsTheToolTheNodesTheHeadersAndThePlotScripts) {
  for (const char* file :
       {"lib/view_direction_classification/vdc",
        "lib/view_direction_classification/orientation_estimator",
        "lib/libview_direction_classification_nodelets.so", "lib/libvdc_estimation.so",
        "include/view_direction_classification/estimation/orientation_estimator.h",
        "share/view_direction_classification/scripts/plot_heatmaps.py",
        "share/view_direction_classification/scripts/plot_evaluation.py",
        "share/view_direction_classification/launch/estimator.launch"}) {
    EXPECT_TRUE(fs::exists(installPrefix() / file)) << file;
  }
}

TEST_F(InstalledPackage, ACatkinPackageThatDependsOnItLinksTheCore) {
  const fs::path build = root_ / "consumer_build";
  const auto configure =
      runInstalled("cmake -S '" VDC_SOURCE_DIR "/test/install/consumer' -B '" + build.string() +
                   "' -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3"
                   " -DCATKIN_ENABLE_TESTING=OFF");
  ASSERT_EQ(configure.exit_code, 0) << configure.output;
  const auto make = runInstalled("cmake --build '" + build.string() + "' -- -j2");
  ASSERT_EQ(make.exit_code, 0) << make.output;
  const auto run =
      runInstalled("'" + (build / "devel/lib/vdc_install_consumer/vdc_consumer").string() + "' '" +
                   quickModel() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("views 12 updated 1"), std::string::npos) << run.output;
}

TEST_F(InstalledPackage, TheInstalledToolRunsTheScriptsInstalledBesideIt) {
  const fs::path out = root_ / "heatmaps";
  const auto run = runInstalled("'" + installedVdc().string() + "' heatmap --model '" +
                                quickModel() + "' --out '" + out.string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::is_regular_file(out / "heatmaps.png")) << run.output;

  // Without its installed scripts it fails, naming them: it never falls back to the source tree.
  const fs::path scripts = installPrefix() / "share/view_direction_classification/scripts";
  fs::rename(scripts, root_ / "scripts_moved_away");
  const auto without = runInstalled("'" + installedVdc().string() + "' heatmap --model '" +
                                    quickModel() + "' --out '" + out.string() + "'");
  fs::rename(root_ / "scripts_moved_away", scripts);
  EXPECT_EQ(without.exit_code, 1) << without.output;
  EXPECT_NE(without.output.find(scripts.string()), std::string::npos) << without.output;
}

TEST_F(InstalledPackage, EveryLaunchFileStillResolvesByPackageNameToTheSourceTree) {
  for (const auto& file : fs::directory_iterator(VDC_SOURCE_DIR "/launch")) {
    const std::string name = file.path().filename().string();
    const auto run = runDeveloped(
        "/usr/bin/python3 -c 'import roslaunch.rlutil as r, sys; "
        "print(r.resolve_launch_arguments(sys.argv[1:]))' view_direction_classification " +
        name);
    EXPECT_EQ(run.exit_code, 0) << name << ": " << run.output;
    EXPECT_NE(run.output.find(fs::canonical(file.path()).string()), std::string::npos)
        << name << ": " << run.output;
  }
}

TEST_F(InstalledPackage, TheDemoRunsByPackageNameAfterTheInstall) {
  const fs::path out = root_ / "demo";
  const auto run = runDemo(out);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::is_regular_file(out / "errors.csv")) << run.output;
  EXPECT_NE(run.output.find("view  2: error"), std::string::npos) << run.output;
}

// A second demo.launch where roslaunch searches (what an install inside the package folder
// made): the demo fails and prints roslaunch's own reason, not a pointer to an empty log.
TEST_F(InstalledPackage, AFailingDemoPrintsRoslaunchsOwnError) {
  const std::string source = fs::weakly_canonical(VDC_SOURCE_DIR).string();
  const std::string build = fs::weakly_canonical(VDC_BINARY_DIR).string();
  if (build.rfind(source + "/", 0) != 0) {
    GTEST_SKIP() << "the build directory is outside the package folder: roslaunch never sees it";
  }
  const fs::path clash = fs::path(VDC_BINARY_DIR) / "launch_name_clash";
  fs::create_directories(clash);
  fs::copy_file(VDC_SOURCE_DIR "/launch/demo.launch", clash / "demo.launch",
                fs::copy_options::overwrite_existing);
  const auto run = runDemo(root_ / "failing_demo");
  fs::remove_all(clash);
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("multiple files named [demo.launch]"), std::string::npos) << run.output;
}

}  // namespace
