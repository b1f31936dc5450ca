#include "control/paper_controller.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "control/local_controller.h"
#include "kinematics/kinematics.h"
#include "reward/reward_model.h"
#include "sim/simulator.h"
#include "support/small_worlds.h"

namespace camcov::control {
namespace {

class EventLog final : public sim::Recorder {
 public:
  void step(const sim::StepRecord& r) override {
    for (const auto& e : r.events)
      events.push_back(e);
  }
  std::vector<ControlEvent> events;
};

params::Parameters quick() {
  params::Parameters p;
  p.global.K = 40;
  p.planner.T2 = 0.1;
  p.sim.duration = 11.0;
  return p;
}

TEST(PaperController, ImprovesNeedsTheFactorTauForPositiveRewards) {
  EXPECT_TRUE(PaperController::improves(1.3, 1.0, 1.2));
  EXPECT_FALSE(PaperController::improves(1.1, 1.0, 1.2));
  EXPECT_TRUE(PaperController::improves(0.1, 0.0, 1.2)) << "nothing seen: anything is better";
  EXPECT_TRUE(PaperController::improves(-0.5, -1.0, 1.2)) << "τ·current would lower the bar";
  EXPECT_FALSE(PaperController::improves(-1.0, -1.0, 1.2));
}

TEST(PaperController, RunsGlobalOptimizationAtZeroAndEveryT1AndPlans) {
  const scene::Scene s = testing::sceneFromJson(testing::kOneTargetScene);
  const params::Parameters p = quick();
  PaperController controller(s, p, 1);
  EventLog log;
  const sim::RunSummary summary = sim::simulate(s, p, controller, log);
  std::vector<double> globals;
  int plans = 0, replans = 0;
  for (const auto& e : log.events) {
    if (e.kind == "global") {
      globals.push_back(e.time);
      EXPECT_TRUE(e.reason == "replan" || e.reason == "keep") << e.reason;
      replans += e.reason == "replan";
    }
    if (e.kind == "plan") {
      ++plans;
      EXPECT_GE(e.path.size(), 2u);
    }
  }
  EXPECT_EQ(globals, (std::vector<double>{0.0, 5.0, 10.0}));
  EXPECT_GE(plans, 1) << "both cameras start looking away: the first global result wins";
  EXPECT_GE(replans, 1) << "and its event says so in its reason";
  // Local optimization alone, from poses that see nothing, never finds the target.
  LocalController local(s, p);
  EventLog none;
  EXPECT_GT(summary.averageCoverage, sim::simulate(s, p, local, none).averageCoverage);
}

TEST(PaperController, HorizonKeepsSlowCamerasFromChasingFarGoals) {
  const scene::Scene s = testing::sceneFromJson(testing::kOneTargetScene);
  params::Parameters p = quick();
  p.sim.duration = 1.0;
  p.global.horizon = 1e-3;  // any travel at all discounts the global reward to nothing
  PaperController controller(s, p, 1);
  EventLog log;
  sim::simulate(s, p, controller, log);
  ASSERT_FALSE(log.events.empty());
  EXPECT_EQ(log.events[0].kind, "global");
  EXPECT_EQ(log.events[0].reason, "keep") << log.events[0].detail;
  EXPECT_NE(log.events[0].detail.find("keep"), std::string::npos) << log.events[0].detail;
}

TEST(PaperController, GivesEachCameraAGoalSampledForItsOwnFieldOfView) {
  // Goal g of global optimization is sampled to see a point with camera g's θ: a 4° camera
  // sent to a goal sampled for 80° would mostly look past the target. With three cameras of
  // two kinds, every plan's goal sees the target with its own camera's θ alone.
  const scene::Scene s = testing::sceneFromJson(R"js({
    "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
    "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))"}],
    "cameraFoV": 4,
    "cameras": [{"pos": "POINT(-6 -6)", "angle": 225, "maxVelocity": 2, "maxAngularVelocity": 1},
                {"pos": "POINT(6 6)", "angle": 0, "maxVelocity": 2, "maxAngularVelocity": 1,
                 "cameraFoV": 80},
                {"pos": "POINT(6 -6)", "angle": 0, "maxVelocity": 2, "maxAngularVelocity": 1}]})js");
  const params::Parameters p = quick();
  int plans = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    PaperController controller(s, p, seed);
    EventLog log;
    sim::simulate(s, p, controller, log);
    for (const auto& e : log.events) {
      if (e.kind != "plan") continue;
      ++plans;
      reward::RewardModel alone(p.reward, s.cameras[e.camera].lens.halfFov);
      kinematics::World w;
      kinematics::Kinematics(s).worldAt(e.time, w);
      alone.setWorld(w);
      EXPECT_GT(alone.evaluate(std::span(&e.path.back(), 1)).coverage, 0.0)
          << "seed " << seed << ", camera " << e.camera << " at t = " << e.time;
    }
  }
  EXPECT_GE(plans, 3);
}

TEST(CamcovMethod, WaitsAStepToSeeMotionThenJudgesOverTheStaticHorizonAndGoesStraight) {
  // The scene holds still: the first global optimization comes at t = dt, is judged over the
  // static horizon, and both cameras, looking away, go; in the open room straight.
  const scene::Scene s = testing::sceneFromJson(testing::kOneTargetScene);
  params::Parameters p = quick();
  PaperController controller(s, p, 1, PaperController::Variant::Camcov);
  EventLog log;
  const sim::RunSummary summary = sim::simulate(s, p, controller, log);
  std::vector<double> globals;
  int straight = 0;
  for (const auto& e : log.events) {
    if (e.kind == "global") {
      globals.push_back(e.time);
      EXPECT_NE(e.detail.find("over the next 60 s"), std::string::npos) << e.detail;
    }
    if (e.kind == "plan") straight += e.detail.find("straight") != std::string::npos;
  }
  ASSERT_EQ(globals.size(), 3u);
  EXPECT_NEAR(globals[0], 0.1, 1e-9);
  EXPECT_NEAR(globals[1], 5.1, 1e-9);
  EXPECT_GE(straight, 1);
  PaperController paper(s, p, 1);
  EventLog none;
  EXPECT_GT(summary.averageCoverage, sim::simulate(s, p, paper, none).averageCoverage * 0.9);
}

TEST(CamcovMethod, TakesAFarBetterGoalThoughTheTripOutlastsTheHorizon) {
  // Both cameras look away, so any goal is better; with a horizon shorter than every trip the
  // window becomes the trip itself and the goal is taken, not refused for its distance.
  const scene::Scene s = testing::sceneFromJson(testing::kOneTargetScene);
  params::Parameters p = quick();
  p.sim.duration = 1.0;
  p.camcov.staticHorizon = 1e-3;
  PaperController controller(s, p, 1, PaperController::Variant::Camcov);
  EventLog log;
  sim::simulate(s, p, controller, log);
  ASSERT_FALSE(log.events.empty());
  const ControlEvent& global = log.events[0];
  ASSERT_EQ(global.kind, "global");
  EXPECT_EQ(global.reason, "replan") << global.detail;
  double travel = 0.0, window = 0.0;
  ASSERT_EQ(
      std::sscanf(global.detail.c_str() + global.detail.find("travel"), "travel %lf", &travel), 1);
  ASSERT_EQ(std::sscanf(global.detail.c_str() + global.detail.find("next"), "next %lf", &window),
            1);
  EXPECT_GT(travel, 0.0);
  EXPECT_NEAR(window, travel, 0.05 + 1e-3 * travel) << global.detail;
}

TEST(CamcovMethod, MovingItsOwnCameraOnlyItSendsThatOneToSeeAndNeverMovesTheTeammate) {
  // camcov-dec's loop of camera 1 (camcov.ownPartOnly). Both cameras look away from the target;
  // the teammate is left where it is (no plan, no command: it decides for itself), and the own
  // camera is sent where it sees the target.
  const scene::Scene s = testing::sceneFromJson(testing::kOneTargetScene);
  const params::Parameters p = quick();
  PaperController controller(s, p, 1, PaperController::Variant::Camcov);
  controller.moveOwnCameraOnly(1);
  struct Log final : sim::Recorder {
    void step(const sim::StepRecord& r) override {
      teammate.push_back(r.cameras[0]);
      for (const auto& e : r.events)
        events.push_back(e);
    }
    std::vector<geometry::Pose> teammate;
    std::vector<ControlEvent> events;
  } log;
  sim::simulate(s, p, controller, log);
  ASSERT_FALSE(log.teammate.empty());
  for (const geometry::Pose& pose : log.teammate)
    EXPECT_EQ(pose, s.cameras[0].initial);
  int plans = 0;
  for (const auto& e : log.events) {
    if (e.kind != "plan") continue;
    ++plans;
    EXPECT_EQ(e.camera, 1);
    reward::RewardModel model(p.reward, s.cameras[1].lens.halfFov);
    kinematics::World w;
    kinematics::Kinematics(s).worldAt(e.time, w);
    model.setWorld(w);
    EXPECT_GT(model.evaluate(std::span(&e.path.back(), 1)).coverage, 0.0) << "t = " << e.time;
  }
  EXPECT_GE(plans, 1);
}

TEST(CamcovMethod, StaysWhereATargetIsAboutToDriveIntoView) {
  // The published dynamic1: a slow camera that sees nothing yet, a target driving east at
  // 1 m/s towards its field of view. Judged in the world as it stands, staying sees nothing and
  // a far trip wins; as the target goes on moving, staying sees it come.
  const scene::Scene s = testing::sceneFromJson(R"js({
    "boundary": "POLYGON((-15 -15,15 -15,15 15,-15 15))",
    "targets": [{"shape": "POLYGON((-2 -1,2 1,2 -1))", "path": "POLYGON((0 0,10 0,10 5))",
                 "velocity": 1.0}],
    "cameraFoV": 30,
    "cameras": [{"pos": "POINT(14 -5)", "angle": 120, "maxVelocity": 0.5,
                 "maxAngularVelocity": 0.1}]})js");
  const auto firstGlobal = [&s](bool forecastStay) {
    params::Parameters p;
    p.sim.duration = 0.2;
    p.camcov.forecastStay = forecastStay;
    PaperController controller(s, p, 1, PaperController::Variant::Camcov);
    EventLog log;
    sim::simulate(s, p, controller, log);
    for (const auto& e : log.events) {
      if (e.kind == "global") return e;
    }
    return ControlEvent{};
  };
  const ControlEvent standing = firstGlobal(false);
  EXPECT_EQ(standing.reason, "replan") << standing.detail;
  EXPECT_NE(standing.detail.find("vs 0.0000 kept"), std::string::npos) << standing.detail;
  const ControlEvent moving = firstGlobal(true);
  EXPECT_EQ(moving.reason, "keep") << moving.detail;
  EXPECT_NE(moving.detail.find("(0.0000 as things stand"), std::string::npos) << moving.detail;
}

}  // namespace
}  // namespace camcov::control
