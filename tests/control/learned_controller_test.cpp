// The learned method: the policy's forward pass against a hand-worked network, the scenes it
// refuses, when a camera takes the policy's step and when the baseline's, and runs of a
// published scene that repeat to the bit.
#include "control/learned_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "control/local_controller.h"
#include "control/methods.h"
#include "kinematics/kinematics.h"
#include "reward/reward_model.h"
#include "scene/scene_loader.h"
#include "sim/simulator.h"
#include "support/small_worlds.h"
#include "support/test_paths.h"
#include "util/input_error.h"

namespace camcov::control {
namespace {

// One camera slot, no target: 4 + 10 floats. Feature 1 (the team's coverage) is normalized by
// mean 0.5 and deviation 0.25, goes through one tanh unit, and the outputs are that unit times
// 1, −2 and 0.5.
std::string oneUnitPolicy(const std::string& lastLayer = R"([[1],[-2],[0.5]])") {
  std::string mean = "[0", deviation = "[1";
  for (int i = 1; i < 14; ++i) {
    mean += i == 1 ? ",0.5" : ",0";
    deviation += i == 1 ? ",0.25" : ",1";
  }
  return R"({"observation":{"view":"own","targets":"nearest","sizes":[1,0,0,0],"mean":)" + mean +
         "],\"std\":" + deviation +
         R"(],"clip":10},"layers":[{"weight":[[0,1,0,0,0,0,0,0,0,0,0,0,0,0]],"bias":[0]},)"
         R"({"weight":)" +
         lastLayer + R"(,"bias":[0,0,0]}]})";
}

TEST(LearnedPolicy, ActsAsItsNetworkComputesClippedToOne) {
  const LearnedPolicy policy(oneUnitPolicy());
  EXPECT_EQ(policy.sizes().size(), 14u);
  std::vector<float> observation(14, 0.0f);
  observation[1] = 0.75f;  // normalized: 1
  const auto a = policy.act(observation);
  EXPECT_DOUBLE_EQ(a[0], std::tanh(1.0));
  EXPECT_DOUBLE_EQ(a[1], -1.0) << "−2 tanh(1) clipped";
  EXPECT_DOUBLE_EQ(a[2], 0.5 * std::tanh(1.0));
}

TEST(LearnedPolicy, ATextThatIsNotAPolicyIsRefused) {
  EXPECT_THROW(LearnedPolicy(oneUnitPolicy(R"([[1],[-2]])")), std::invalid_argument)
      << "two actions, not three";
  EXPECT_THROW(LearnedPolicy(oneUnitPolicy(R"([[1,2],[-2,1],[0.5,0]])")), std::invalid_argument)
      << "rows longer than the layer before";
}

TEST(LearnedController, AScenePastThePolicysObservationIsAnInputError) {
  const scene::Scene twoCameras = testing::sceneFromJson(testing::kOneTargetScene);
  const LearnedPolicy oneCamera(oneUnitPolicy());
  try {
    LearnedController controller(twoCameras, params::Parameters{}, oneCamera);
    FAIL() << "two cameras in a policy of one";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("method learned: scene"), std::string::npos) << e.what();
  }
}

TEST(LearnedController, TheBuiltInPolicyHoldsEveryPublishedScene) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  for (const auto& file : testing::jsonFilesIn(testing::publishedScenesDir())) {
    SCOPED_TRACE(file.filename().string());
    EXPECT_NO_THROW(LearnedController(scene::loadScene(file), params::Parameters{}));
  }
}

// A policy whose mean action is (vx, vy, turn) whatever it observes: one linear layer of zero
// weights. One camera, no target slot, rings of up to 4 vertices.
std::string constantPolicy(double vx, double vy, double turn) {
  const std::string zeros = "[0,0,0,0,0,0,0,0,0,0,0,0,0,0]";
  const std::string ones = "[1,1,1,1,1,1,1,1,1,1,1,1,1,1]";
  return R"({"observation":{"view":"own","targets":"nearest","sizes":[1,0,0,4],"mean":)" + zeros +
         ",\"std\":" + ones + R"(,"clip":10},"layers":[{"weight":[)" + zeros + "," + zeros + "," +
         zeros + "],\"bias\":[" + std::to_string(vx) + "," + std::to_string(vy) + "," +
         std::to_string(turn) + "]}]}";
}

// One camera 8.5 m from a 2 m square, `angle` degrees: 45 faces it, 225 turns its back on it.
scene::Scene oneCamera(int angle) {
  return testing::sceneFromJson(R"js({
    "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
    "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))"}],
    "cameraFoV": 30,
    "cameras": [{"pos": "POINT(-6 -6)", "angle": )js" +
                                std::to_string(angle) +
                                R"js(, "maxVelocity": 2, "maxAngularVelocity": 10}]})js");
}

// The command a controller gives at t = 0.
scene::CameraCommand firstCommand(Controller& controller, const scene::Scene& scene) {
  kinematics::World world;
  kinematics::Kinematics(scene).worldAt(0.0, world);
  const std::vector<geometry::Pose> team{scene.cameras[0].initial};
  std::vector<scene::CameraCommand> commands(1);
  controller.control(Observation{0.0, world, team}, commands);
  return commands[0];
}

TEST(LearnedController, ACameraThatSeesNothingFollowsThePolicy) {
  // Nothing in view: no step changes the reward, so none lowers it.
  const scene::Scene scene = oneCamera(225);
  const LearnedPolicy sideways(constantPolicy(0.5, -0.25, 0.0));
  LearnedController controller(scene, params::Parameters{}, sideways);
  const scene::CameraCommand u = firstCommand(controller, scene);
  EXPECT_NEAR(u.velocity.x, 0.5 * 2, 1e-9) << "v_max = 2";
  EXPECT_NEAR(u.velocity.y, -0.25 * 2, 1e-9);
  EXPECT_NEAR(u.angularVelocity, 0.0, 1e-9);
}

TEST(LearnedController, AStepThatWouldLowerTheRewardGivesWayToTheBaselinesStep) {
  // Facing the square, a full turn (1 rad in a step of 0.1 s) takes it out of the field of
  // view: the camera takes the baseline's local step instead.
  const scene::Scene scene = oneCamera(45);
  const params::Parameters params;
  const geometry::Pose start = scene.cameras[0].initial;
  kinematics::World world;
  kinematics::Kinematics(scene).worldAt(0.0, world);
  reward::RewardModel model(params.reward, scene::lenses(scene));
  model.setWorld(world);
  const geometry::Pose turned{start.x, start.y,
                              geometry::wrapAngle(start.yaw + 10.0 * params.sim.dt)};
  ASSERT_LT(model.reward(std::span(&turned, 1)), model.reward(std::span(&start, 1)))
      << "the turn must lower the reward for this test to mean anything";

  const LearnedPolicy turning(constantPolicy(0.0, 0.0, 1.0));
  LearnedController learned(scene, params, turning);
  LocalController local(scene, params);
  const scene::CameraCommand u = firstCommand(learned, scene),
                             baseline = firstCommand(local, scene);
  EXPECT_EQ(u.velocity, baseline.velocity);
  EXPECT_EQ(u.angularVelocity, baseline.angularVelocity);
  EXPECT_LT(std::abs(u.angularVelocity), 10.0) << "not the policy's full turn";
}

class PoseSeries final : public sim::Recorder {
 public:
  void step(const sim::StepRecord& r) override {
    for (const geometry::Pose& p : r.cameras)
      poses.insert(poses.end(), {p.x, p.y, p.yaw});
  }
  std::vector<double> poses;
};

TEST(LearnedController, RunsAPublishedSceneTheSameWayEveryTime) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const scene::Scene scene = scene::loadScene(testing::publishedScenesDir() / "dynamic9.json");
  params::Parameters params;
  params.sim.duration = 10.0;
  const Method& learned = requireMethod("learned");
  EXPECT_EQ(learned.role, Role::example) << "not in the default batch: golden runs unchanged";
  std::vector<PoseSeries> runs(2);
  std::vector<double> coverage;
  for (std::uint64_t seed : {1, 2}) {
    const auto controller = learned.make(scene, params, seed);
    coverage.push_back(
        sim::simulate(scene, params, *controller, runs[seed - 1], seed).averageCoverage);
  }
  ASSERT_EQ(runs[0].poses.size(), 101u * 3 * scene.cameras.size());
  EXPECT_EQ(runs[0].poses, runs[1].poses) << "the policy's mean: no random draw";
  EXPECT_EQ(coverage[0], coverage[1]);
  EXPECT_NE(runs[0].poses.front(), runs[0].poses[runs[0].poses.size() - 3]) << "it moves";
}

}  // namespace
}  // namespace camcov::control
