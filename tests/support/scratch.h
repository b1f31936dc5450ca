#pragma once
// Files and folders for tests that run the executable or write results: a scratch folder per
// test, and whole-file reads.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace camcov::testing {

// The contents of `file`, byte for byte; empty if it cannot be read.
inline std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// <tmp>/camcov_<suite>_<test>_<pid>: one folder per running test, so tests running in
// parallel (ctest -j) never share one.
inline std::filesystem::path testScratchRoot(const ::testing::TestInfo& info) {
  std::string name = std::string("camcov_") + info.test_suite_name() + "_" + info.name() + "_" +
                     std::to_string(::getpid());
  for (char& c : name) {
    if (c == '/') c = '_';  // parameterized tests are named "Prefix/Suite.Test/Param"
  }
  return std::filesystem::temp_directory_path() / name;
}
inline std::filesystem::path testScratchRoot() {
  return testScratchRoot(*::testing::UnitTest::GetInstance()->current_test_info());
}

// A passing test's scratch root is removed when it ends; a failing test's is left for
// inspection. So a passing test run leaves nothing in the temporary folder.
class ScratchCleaner : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo& info) override {
    if (info.result() != nullptr && !info.result()->Failed()) {
      std::error_code ignored;
      std::filesystem::remove_all(testScratchRoot(info), ignored);
    }
  }
};
// Installed once per test program that includes this header (gtest owns the listener).
inline const bool kScratchCleanerInstalled = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new ScratchCleaner);
  return true;
}();

// An empty folder `name` in the running test's scratch root; kept if the test fails.
inline std::filesystem::path freshDir(const std::string& name) {
  const std::filesystem::path dir = testScratchRoot() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The running test's scratch root, empty at the start and removed when the test ends.
class ScratchDir {
 public:
  ScratchDir() : path_(testScratchRoot()) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace camcov::testing
