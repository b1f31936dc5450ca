#include "control/methods.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "support/small_worlds.h"
#include "util/input_error.h"

namespace camcov::control {
namespace {

TEST(Methods, NamesAreUniqueAndEachHasAColourAndADescription) {
  std::set<std::string_view> names, colours;
  for (const Method& m : methods()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    EXPECT_TRUE(colours.insert(m.color).second) << m.name << " shares its colour";
    EXPECT_FALSE(m.description.empty()) << m.name;
    EXPECT_EQ(findMethod(m.name), &m);
  }
  EXPECT_EQ(methods().front().name, "paper") << "the paper's method leads figures and tables";
  EXPECT_TRUE(names.count("local")) << "the baseline";
}

TEST(Methods, ListingsFollowTheTableThenUnknownNamesByName) {
  EXPECT_EQ(inMethodOrder({"zeta", "camcov", "alpha", "local", "paper"}),
            (std::vector<std::string>{"paper", "local", "camcov", "alpha", "zeta"}));
}

TEST(Methods, AnUnknownNameIsAnInputErrorListingTheKnownOnes) {
  EXPECT_EQ(findMethod("nope"), nullptr);
  try {
    requireMethod("nope");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "unknown method 'nope' (known: paper, local, camcov, camcov-dec, learned)");
  }
}

TEST(Methods, EveryMethodMakesAControllerThatCommandsEveryCamera) {
  const scene::Scene scene = testing::sceneFromJson(testing::kOneTargetScene);
  params::Parameters p;
  p.global.K = 20;
  p.planner.T2 = 0.02;
  const kinematics::World world = testing::roomWithTargetAndObstacle();
  std::vector<geometry::Pose> cameras;
  for (const auto& c : scene.cameras)
    cameras.push_back(c.initial);
  for (const Method& m : methods()) {
    SCOPED_TRACE(m.name);
    const auto controller = m.make(scene, p, 1);
    ASSERT_NE(controller, nullptr);
    std::vector<scene::CameraCommand> commands(cameras.size(), {{1e9, 1e9}, 1e9});
    controller->control({0.0, world, cameras}, commands);
    for (const auto& u : commands)
      EXPECT_LT(geometry::norm(u.velocity), 1e9) << "every command was written";
  }
}

}  // namespace
}  // namespace camcov::control
