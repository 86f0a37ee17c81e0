#pragma once

// A test fixture with a fresh directory per test under the system temp dir, removed afterwards:
// <tmp>/vdc_<suite>_<test>_<pid>, so parallel runs and tests of one suite never share files.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <iterator>
#include <string>

namespace vdc::test {

class TemporaryDirectoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = std::filesystem::temp_directory_path() /
                 ("vdc_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
                  std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  const std::filesystem::path& directory() const { return directory_; }
  // The path of `name` inside the directory (nothing is created).
  std::string path(const std::string& name) const { return (directory_ / name).string(); }
  // How many files and directories the directory holds (not recursive).
  std::ptrdiff_t entryCount() const {
    return std::distance(std::filesystem::directory_iterator(directory_),
                         std::filesystem::directory_iterator());
  }

 private:
  std::filesystem::path directory_;
};

}  // namespace vdc::test
