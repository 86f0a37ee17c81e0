// The core must build and run without ROS (doc/method.md, "Layout"): no header or source of a core
// module may include a ROS header. CMake separately refuses a ROS library in the core's link interface.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<std::string> rosIncludesUnder(const fs::path& directory) {
  // Headers of ROS packages (Debian installs them under /usr/include like any library, so the
  // compiler alone would not catch them).
  static const std::regex ros_include(
      R"(^\s*#\s*include\s*[<"](ros|tf2|tf2_ros|tf2_eigen|tf2_geometry_msgs|pcl_ros|pcl_conversions|nodelet|pluginlib|sensor_msgs|geometry_msgs|std_msgs|std_srvs|visualization_msgs|diagnostic_updater|diagnostic_msgs|view_direction_classification/(ros|Bingham|Get))[/.])");
  std::vector<std::string> offenders;
  for (const auto& entry : fs::recursive_directory_iterator(directory)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream file(entry.path());
    std::string line;
    int number = 0;
    while (std::getline(file, line)) {
      ++number;
      if (std::regex_search(line, ros_include)) {
        offenders.push_back(entry.path().string() + ":" + std::to_string(number) + ": " + line);
      }
    }
  }
  return offenders;
}

// Every module folder except the ROS shell's is core.
std::vector<fs::path> coreDirectories() {
  const fs::path root(VDC_SOURCE_DIR);
  std::vector<fs::path> directories;
  for (const auto& entry : fs::directory_iterator(root / "include/view_direction_classification")) {
    if (!entry.is_directory() || entry.path().filename() == "ros") continue;
    directories.push_back(entry.path());
    directories.push_back(root / "src" / entry.path().filename());
  }
  return directories;
}

TEST(CoreIsRosFree, NoCoreFileIncludesARosHeader) {
  const auto directories = coreDirectories();
  ASSERT_GE(directories.size(), 2u * 11u) << "fewer core modules than expected";
  for (const fs::path& directory : directories) {
    ASSERT_TRUE(fs::is_directory(directory)) << directory;
    const auto offenders = rosIncludesUnder(directory);
    EXPECT_TRUE(offenders.empty()) << offenders.front();
  }
}

TEST(CoreIsRosFree, TheCheckRecognisesARosInclude) {
  const fs::path directory = fs::temp_directory_path() / "vdc_core_is_ros_free_check";
  fs::create_directories(directory);
  std::ofstream(directory / "bad.h") << "#pragma once\n#include <ros/ros.h>\n";
  std::ofstream(directory / "good.h") << "#include <Eigen/Core>\n// see ros/ros.h\n";
  const auto offenders = rosIncludesUnder(directory);
  fs::remove_all(directory);
  ASSERT_EQ(offenders.size(), 1u);
  EXPECT_NE(offenders.front().find("bad.h:2"), std::string::npos);
}

}  // namespace
