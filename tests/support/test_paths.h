#pragma once
// Where the tests find their data. The published benchmark is read from COVERAGE_SCENES_DIR
// (set by .ci/run and scripts/test.sh), never copied into the repository.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace camcov::testing {

inline std::filesystem::path testDataDir() {
  return CAMCOV_TEST_DATA_DIR;
}
inline std::filesystem::path ownScenesDir() {
  return CAMCOV_SCENES_DIR;
}

// Empty if COVERAGE_SCENES_DIR is unset; a set but missing folder is a test failure.
inline std::filesystem::path publishedScenesDir() {
  const char* dir = std::getenv("COVERAGE_SCENES_DIR");
  if (dir == nullptr || *dir == '\0') return {};
  EXPECT_TRUE(std::filesystem::is_directory(dir)) << "COVERAGE_SCENES_DIR=" << dir;
  return dir;
}

inline std::vector<std::filesystem::path> jsonFilesIn(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  if (dir.empty() || !std::filesystem::is_directory(dir)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace camcov::testing

// Skips a test that needs the published benchmark when COVERAGE_SCENES_DIR is unset.
#define CAMCOV_REQUIRE_PUBLISHED_SCENES()              \
  if (::camcov::testing::publishedScenesDir().empty()) \
  GTEST_SKIP() << "set COVERAGE_SCENES_DIR to the published coverage_scenes folder"
