#pragma once
// Where the benchmark programs read the published scenes: COVERAGE_SCENES_DIR, else the
// default their CMake target defines (../shared/coverage_scenes beside the clone).
#include <cstdlib>
#include <filesystem>

namespace camcov::testing {

inline std::filesystem::path benchScenesDir() {
  const char* dir = std::getenv("COVERAGE_SCENES_DIR");
  return dir != nullptr && *dir != '\0' ? dir : CAMCOV_DEFAULT_SCENES_DIR;
}

}  // namespace camcov::testing
