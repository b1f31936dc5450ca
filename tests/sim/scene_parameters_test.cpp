// A scene's own settings of what a camera knows ("knowledge", "comms"; sim/scene_parameters.h).
#include "sim/scene_parameters.h"

#include <gtest/gtest.h>

#include <string>

#include "params/parameter_table.h"
#include "support/small_worlds.h"
#include "util/input_error.h"

namespace camcov::sim {
namespace {

// kOneTargetScene with `extra` keys before its closing brace.
std::string withKeys(const std::string& extra) {
  std::string text = testing::kOneTargetScene;
  text.insert(text.rfind('}'), ", " + extra);
  return text;
}

TEST(SceneParameters, AScenesKnowledgeSettingsApplyWhereTheParametersKeepTheirDefaults) {
  const scene::Scene scene = testing::sceneFromJson(
      withKeys(R"("knowledge": {"limited": true}, "comms": {"range": 8, "loss": 0.1})"));
  const params::Parameters p = forScene({}, scene, "test.json", false);
  EXPECT_TRUE(p.knowledge.limited);
  EXPECT_EQ(p.comms.range, 8.0);
  EXPECT_EQ(p.comms.loss, 0.1);
  EXPECT_EQ(p.comms.latency, 0.0);
  // The caller's own value wins.
  params::Parameters mine;
  mine.comms.range = 5.0;
  EXPECT_EQ(forScene(mine, scene, "test.json", false).comms.range, 5.0);
}

TEST(SceneParameters, ASceneWithoutThemKeepsTheParameters) {
  const scene::Scene scene = testing::sceneFromJson(testing::kOneTargetScene);
  params::Parameters p;
  p.global.K = 7;
  EXPECT_EQ(params::toJson(forScene(p, scene, "test.json", false)), params::toJson(p));
  EXPECT_FALSE(forScene(p, scene, "test.json", false).knowledge.limited);
}

TEST(SceneParameters, BadSettingsAreInputErrorsNamingTheKey) {
  const scene::Scene outOfRange = testing::sceneFromJson(withKeys(R"("comms": {"loss": 2})"));
  try {
    forScene({}, outOfRange, "test.json", false);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "test.json: comms.loss = 2 is outside [0, 1]");
  }
  const scene::Scene unknown = testing::sceneFromJson(withKeys(R"("comms": {"rnge": 2})"));
  EXPECT_THROW(forScene({}, unknown, "test.json", false), InputError);
  // Not an object at all: the loader says so.
  EXPECT_THROW(testing::sceneFromJson(withKeys(R"("knowledge": true)")), InputError);
}

}  // namespace
}  // namespace camcov::sim
