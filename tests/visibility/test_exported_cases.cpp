// Corner cases exported from the visibility playground (its "case" file: the scene, the time
// and the camera poses), kept in tests/data/visibility_cases/: for each, every camera's visible
// length and the team's union, from the sweep, against the independent reference
// (reference_visibility.h). Saving the page's export there is the whole of making one a
// regression test (docs/visibility.md, "Debugging a corner case").
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "kinematics/kinematics.h"
#include "reference_visibility.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "visibility/sweep.h"

namespace camcov::visibility {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> caseFiles() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(testing::testDataDir() / "visibility_cases"))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ExportedCases, EachAgreesWithTheReference) {
  const auto files = caseFiles();
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json exported = nlohmann::json::parse(text.str());
    const scene::Scene s = scene::parseScene(exported.at("scene").dump(), file.string());
    const std::vector<geometry::Pose> poses =
        scene::parseCameraPoses(exported.at("poses").dump(), file.string());
    ASSERT_EQ(poses.size(), s.cameras.size());
    const kinematics::World world = kinematics::Kinematics(s).worldAt(exported.at("time"));
    const std::vector<scene::Lens> lenses = scene::lenses(s);
    Sweep sweep;
    std::vector<Segment> segments;
    sweep.segments(Occluders(world), poses, lenses, segments);
    const double floor = 1e-9 * reference::tolerance(world) / 1e-12;  // 1e-9 × extent
    const auto close = [&](double a, double b) {
      return std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b)) + floor;
    };
    for (std::size_t j = 0; j < poses.size(); ++j) {
      ASSERT_FALSE(lenses[j].limited()) << "the reference has no sensing range";
      double swept = 0.0, expected = 0.0;
      for (const Segment& seg : segments) {
        if (seg.visibleBy.contains(j)) swept += length(seg);
      }
      const auto seen =
          reference::visibleIntervals(world, poses[j].position(), poses[j].yaw, lenses[j].halfFov);
      for (std::size_t i = 0; i < world.targets.size(); ++i) {
        const geometry::Ring& ring = world.targets[i];
        for (std::size_t k = 0; k < ring.size(); ++k) {
          for (const reference::Interval& t : seen[i][k])
            expected += (t.hi - t.lo) * geometry::distance(ring[k], ring[(k + 1) % ring.size()]);
        }
      }
      EXPECT_TRUE(close(swept, expected))
          << "camera " << j << ": the sweep sees " << swept << " m, the reference " << expected;
    }
  }
}

}  // namespace
}  // namespace camcov::visibility
