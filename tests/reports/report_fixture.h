#pragma once
// A results folder for the report tests, made by the real `camcov bench` on the tiny scenes of
// tests/data/scenes (2 scenes x 2 methods x 3 seeds of 2 s: well under a second), in a scratch
// folder named after the running test and removed when it ends.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {

inline const char* const kFixtureScenes[] = {"tiny_dynamic", "tiny_static"};

// `camcov bench` into `out`; extra arguments (e.g. --no-report) are appended.
inline CommandResult benchFixture(const std::filesystem::path& out, const std::string& extra = "") {
  return runCamcov(
      "bench --scenes " + (testDataDir() / "scenes").string() +
      " --seeds 3 --duration 2 --set global.K=30 --set planner.T2=0.05 --jobs 2 --videos none"
      " --out " +
      out.string() + " " + extra);
}

inline int countOf(const std::string& text, const std::string& needle) {
  int n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
    ++n;
  return n;
}

}  // namespace camcov::testing
