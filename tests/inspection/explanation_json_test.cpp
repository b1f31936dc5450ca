// What the engine answers the playground: the terms and S are the inspection's, the reasons a
// camera misses a segment are given for the cameras that miss it, and the costly parts only
// when asked.
#include "inspection/explanation_json.h"

#include <gtest/gtest.h>

#include <string>

#include "inspection/inspection_json.h"
#include "params/parameters.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"

namespace camcov::inspection {
namespace {

struct Looked {
  nlohmann::json inspection, explanation;
};

Looked lookAt(const std::string& sceneName, double time, const ExplanationAsks& asks) {
  const scene::Scene scene = scene::loadScene(std::string(CAMCOV_SCENES_DIR) + "/" + sceneName);
  const std::vector<geometry::Pose> cameras = scene::initialPoses(scene);
  const kinematics::Kinematics kinematics(scene);
  reward::RewardModel model(params::Parameters{}.reward, scene::lenses(scene));
  model.setWorld(kinematics.worldAt(time));
  const reward::RewardTerms terms = model.evaluate(cameras);
  Looked out{inspectionJson(scene, time, cameras, model, terms), {}};
  out.explanation = explanationJson(scene, kinematics, time, cameras, model, asks);
  return out;
}

TEST(ExplanationJson, HasTheInspectionsTermsAndSegments) {
  const Looked l = lookAt("fig1_example.json", 3.0, {});
  for (const char* term : {"coverage", "utilization", "repulsion", "reward"})
    EXPECT_EQ(l.explanation["terms"][term], l.inspection[term]) << term;
  const nlohmann::json& columns = l.explanation["segments"];
  const nlohmann::json& segments = l.inspection["segments"];
  ASSERT_EQ(columns["target"].size(), segments.size());
  ASSERT_EQ(columns["ends"].size(), 4 * segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    EXPECT_EQ(columns["target"][i], segments[i]["target"]);
    EXPECT_EQ(columns["edge"][i], segments[i]["edge"]);
    EXPECT_EQ(columns["visibleBy"][i], segments[i]["visibleBy"]);
    EXPECT_EQ(columns["ends"][4 * i], segments[i]["a"][0]);
    EXPECT_EQ(columns["ends"][4 * i + 3], segments[i]["b"][1]);
  }
  ASSERT_EQ(l.explanation["cameras"].size(), l.inspection["cameras"].size());
  EXPECT_EQ(l.explanation["cameras"][0]["visibleLength"],
            l.inspection["cameras"][0]["visibleLength"]);
  EXPECT_FALSE(l.explanation.contains("reasons")) << "not asked";
  EXPECT_FALSE(l.explanation.contains("trace")) << "not asked";
}

TEST(ExplanationJson, GivesAReasonForEachCameraThatMissesTheSegmentAskedAbout) {
  const Looked first = lookAt("fig1_example.json", 3.0, {});
  const nlohmann::json& visibleBy = first.explanation["segments"]["visibleBy"];
  const std::size_t cameras = first.explanation["cameras"].size();
  // A segment some camera misses.
  int missed = -1;
  for (std::size_t i = 0; i < visibleBy.size() && missed < 0; ++i)
    if (visibleBy[i].size() < cameras) missed = static_cast<int>(i);
  ASSERT_GE(missed, 0);
  const nlohmann::json reasons =
      lookAt("fig1_example.json", 3.0, {0, missed}).explanation["reasons"];
  EXPECT_EQ(reasons["segment"], missed);
  ASSERT_EQ(reasons["why"].size(), cameras);
  for (std::size_t j = 0; j < cameras; ++j) {
    bool sees = false;
    for (const auto& k : visibleBy[missed])
      sees = sees || k.get<std::size_t>() == j;
    EXPECT_EQ(reasons["why"][j].is_null(), sees) << "camera " << j;
    if (!sees) {
      EXPECT_FALSE(reasons["why"][j].get<std::string>().empty());
    }
  }
}

TEST(ExplanationJson, TracesTheSweepOfTheCameraAskedAbout) {
  const nlohmann::json out = lookAt("fig1_example.json", 0.0, {1, -1}).explanation;
  ASSERT_TRUE(out.contains("trace"));
  EXPECT_EQ(out["trace"]["camera"], 1);
  EXPECT_FALSE(out["trace"]["events"].empty());
  EXPECT_FALSE(lookAt("fig1_example.json", 0.0, {99, -1}).explanation.contains("trace"))
      << "no such camera";
}

}  // namespace
}  // namespace camcov::inspection
