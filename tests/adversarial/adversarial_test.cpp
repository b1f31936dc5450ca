// Every command on every scene of tests/data/adversarial/ (degenerate geometry, extreme scales,
// crowded or boxed-in cameras; see the README there), end to end through the camcov binary.
// A file named reject_*.json must be refused by each command with exit 2 and a message naming
// the file; every other file must be handled: exit 0, well-formed output, runs whose series
// hold no NaN (JSON null) and never put a camera outside the boundary. Each command runs
// under a timeout, so a hang fails the test instead of stalling CI.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/ring.h"
#include "scene/scene_loader.h"
#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// Seconds per command; the slowest (64 cameras, the paper's method, ASan) takes a few.
constexpr int kTimeoutSeconds = 120;
// Short runs with a small sample and planning budget: the point is robustness, not quality.
const std::string kRunOptions = " --duration 3 --set global.K=40 --set planner.T2=0.05";

std::vector<std::string> adversarialScenes() {
  std::vector<std::string> names;
  for (const fs::path& file : jsonFilesIn(testDataDir() / "adversarial"))
    names.push_back(file.stem().string());
  return names;
}

class AdversarialScene : public ::testing::TestWithParam<std::string> {
 protected:
  fs::path scene() const { return testDataDir() / "adversarial" / (GetParam() + ".json"); }
  bool rejected() const { return GetParam().starts_with("reject_"); }

  // Runs `camcov <command> <scene> <options>`; checks the exit code against the file's
  // expectation and returns the result for further checks.
  CommandResult expectHandledOrRejected(const std::string& command, const std::string& options) {
    const CommandResult r =
        runShell("timeout -k 5 " + std::to_string(kTimeoutSeconds) + " " + camcovBinary() + " " +
                 command + " " + scene().string() + " " + options);
    EXPECT_NE(r.exitCode, 124) << command << " did not finish in " << kTimeoutSeconds << " s";
    if (rejected()) {
      EXPECT_EQ(r.exitCode, 2) << command << ":\n" << r.err;
      // validate reports on stdout, one line per file; the other commands on stderr.
      EXPECT_NE((r.out + r.err).find(scene().string() + ": "), std::string::npos)
          << command << " must name the file:\n"
          << r.out << r.err;
    } else {
      EXPECT_EQ(r.exitCode, 0) << command << ":\n" << r.err;
    }
    return r;
  }
};

// JSON writes NaN and infinity as null: a number that should be there and is null was not finite.
void expectNumber(const nlohmann::json& value, const std::string& what) {
  EXPECT_TRUE(value.is_number()) << what << " is " << value.dump();
}

TEST_P(AdversarialScene, ValidateStateAndInspectHandleItOrRejectIt) {
  expectHandledOrRejected("validate", "");
  const CommandResult state = expectHandledOrRejected("state", "--time 1.3");
  const CommandResult inspect = expectHandledOrRejected("inspect", "--time 1.3 --json");
  if (rejected() || HasFailure()) return;
  EXPECT_TRUE(nlohmann::json::accept(state.out)) << state.out;
  const auto j = nlohmann::json::parse(inspect.out);
  for (const char* key : {"coverage", "utilization", "repulsion", "reward", "targetPerimeter"})
    expectNumber(j[key], key);
  EXPECT_GE(j["coverage"].get<double>(), 0.0);
  EXPECT_LE(j["coverage"].get<double>(), 1.0 + 1e-9);
  for (const auto& camera : j["cameras"])
    expectNumber(camera["visibleLength"], "a camera's visible length");
  for (const auto& segment : j["segments"]) {
    for (const char* end : {"a", "b"}) {
      expectNumber(segment[end][0], "a segment endpoint");
      expectNumber(segment[end][1], "a segment endpoint");
    }
  }
}

TEST_P(AdversarialScene, RunsStayFiniteAndInsideTheBoundary) {
  for (const std::string method : {"paper", "local", "camcov"}) {
    SCOPED_TRACE(method);
    const fs::path out = freshDir("run-" + method);
    expectHandledOrRejected("run", "--method " + method + kRunOptions + " --out " + out.string());
    if (rejected()) {
      EXPECT_TRUE(fs::is_empty(out)) << "a rejected scene writes nothing";
      continue;
    }
    const fs::path file = out / (GetParam() + "-" + method + "-seed1.json");
    ASSERT_TRUE(fs::exists(file));
    const auto run = nlohmann::json::parse(readFile(file));
    for (const char* key : {"averageCoverage", "averageUtilization", "averageReward",
                            "minObjectDistance", "objectCollisionTime"})
      expectNumber(run["summary"][key], std::string("summary.") + key);
    const auto& series = run["series"];
    for (const char* key :
         {"time", "coverage", "utilization", "repulsion", "reward", "minObjectDistance"}) {
      for (const auto& value : series[key])
        expectNumber(value, std::string("series.") + key);
    }

    const geometry::Ring boundary = scene::loadScene(scene()).boundary;
    const geometry::Box box = geometry::boundingBox(boundary);
    // On the boundary is allowed (a camera may start there); rounding may put it a hair out.
    const double tolerance = 1e-9 * std::max(box.max.x - box.min.x, box.max.y - box.min.y);
    int outside = 0;
    for (std::size_t c = 0; c < series["cameras"].size(); ++c) {
      for (const auto& pose : series["cameras"][c]) {
        for (int k = 0; k < 3; ++k)
          expectNumber(pose[k], "camera " + std::to_string(c) + " pose");
        if (HasFailure()) return;
        const geometry::Vec2 p{pose[0].get<double>(), pose[1].get<double>()};
        if (geometry::locate(boundary, p, tolerance) == geometry::Containment::Outside &&
            ++outside <= 5)
          ADD_FAILURE() << "camera " << c << " outside the boundary at (" << p.x << ", " << p.y
                        << ")";
      }
    }
  }
}

TEST_P(AdversarialScene, RendersAFrame) {
  const fs::path out = freshDir("render");
  expectHandledOrRejected("render", "--time 1.3 --out " + (out / "frame.png").string());
  if (rejected()) return;
  EXPECT_EQ(readFile(out / "frame.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
}

TEST(AdversarialScenes, EveryFileHasALineInTheReadme) {
  const std::string readme = readFile(testDataDir() / "adversarial" / "README.md");
  for (const std::string& name : adversarialScenes())
    EXPECT_NE(readme.find("`" + name + ".json`"), std::string::npos) << name;
}

INSTANTIATE_TEST_SUITE_P(Files, AdversarialScene, ::testing::ValuesIn(adversarialScenes()),
                         [](const auto& info) {
                           std::string name = info.param;  // gtest names: letters, digits, _
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace camcov::testing
