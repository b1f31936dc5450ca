// What `camcov inspect --json` and the engine print: each camera's visible length is the length
// of the segments that list it, each segment's length is the distance between its ends, and a
// weighted scene's segments carry their edge's importance.
#include "inspection/inspection_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "kinematics/kinematics.h"
#include "params/parameters.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"

namespace camcov::inspection {
namespace {

nlohmann::json inspected(const std::string& sceneName, double time) {
  const scene::Scene scene = scene::loadScene(std::string(CAMCOV_SCENES_DIR) + "/" + sceneName);
  const std::vector<geometry::Pose> cameras = scene::initialPoses(scene);
  reward::RewardModel model(params::Parameters{}.reward, scene::lenses(scene));
  model.setWorld(kinematics::Kinematics(scene).worldAt(time));
  const reward::RewardTerms terms = model.evaluate(cameras);
  return inspectionJson(scene, time, cameras, model, terms);
}

TEST(CameraNumbers, ListsTheCamerasLowestFirst) {
  using scene::CameraSet;
  EXPECT_EQ(cameraNumbers(CameraSet::fromBits(0b1011)), nlohmann::json::array({0, 1, 3}));
  EXPECT_EQ(cameraNumbers(CameraSet{}), nlohmann::json::array());
  CameraSet farApart = CameraSet::only(127);
  farApart.insert(63);
  EXPECT_EQ(cameraNumbers(farApart), nlohmann::json::array({63, 127}));
}

TEST(InspectionJson, EachCameraSeesTheLengthOfTheSegmentsThatListIt) {
  for (const char* name : {"fig1_example.json", "walking_figures.json"}) {
    const nlohmann::json out = inspected(name, 3.0);
    ASSERT_FALSE(out["segments"].empty()) << name;
    for (std::size_t j = 0; j < out["cameras"].size(); ++j) {
      double seen = 0.0;
      for (const auto& s : out["segments"]) {
        const double dx = s["b"][0].get<double>() - s["a"][0].get<double>();
        const double dy = s["b"][1].get<double>() - s["a"][1].get<double>();
        EXPECT_NEAR(s["length"].get<double>(), std::hypot(dx, dy), 1e-12);
        for (const auto& k : s["visibleBy"])
          if (k.get<std::size_t>() == j) seen += s["length"].get<double>();
      }
      EXPECT_NEAR(out["cameras"][j]["visibleLength"].get<double>(), seen, 1e-9)
          << name << " camera " << j;
    }
  }
}

TEST(InspectionJson, NamesTheSceneTheInstantAndEachTerm) {
  const nlohmann::json out = inspected("fig1_example.json", 2.5);
  EXPECT_EQ(out["scene"], "fig1_example");
  EXPECT_EQ(out["time"], 2.5);
  std::set<std::string> keys;
  for (const auto& [key, unused] : out.items())
    keys.insert(key);
  EXPECT_EQ(keys, (std::set<std::string>{"cameras", "coverage", "repulsion", "reward", "scene",
                                         "segments", "targetPerimeter", "time", "utilization"}));
  EXPECT_GT(out["coverage"].get<double>(), 0.0);
  EXPECT_LE(out["coverage"].get<double>(), 1.0);
  EXPECT_TRUE(out["cameras"][0].contains("yaw_deg"));
  EXPECT_FALSE(out["segments"][0].contains("weight")) << "an unweighted scene";
}

TEST(InspectionJson, AWeightedScenesSegmentsCarryTheirEdgesImportance) {
  const nlohmann::json out = inspected("weighted_stage_and_walkers.json", 1.0);
  ASSERT_TRUE(out.contains("weightedCoverage"));
  for (const auto& s : out["segments"]) {
    ASSERT_TRUE(s.contains("weight"));
    EXPECT_GE(s["weight"].get<double>(), 0.0);
    EXPECT_LE(s["weight"].get<double>(), 1.0);
  }
}

}  // namespace
}  // namespace camcov::inspection
