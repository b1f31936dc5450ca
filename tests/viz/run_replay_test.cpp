#include "viz/run_replay.h"

#include <gtest/gtest.h>

#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "viz_test_support.h"

namespace camcov::viz {
namespace {

using geometry::Pose;
using geometry::Vec2;

// 31 steps over 3 s; camera 0 follows a plan from t = 0.5 until it completes at t = 1.5.
class TinyRun : public ::testing::Test {
 protected:
  TinyRun() : scene_(scene::loadScene(testing::tinyScene())) {
    run_.metadata.scene = scene_.name;
    run_.metadata.method = "paper";
    run_.metadata.seed = 7;
    for (int i = 0; i <= 30; ++i) {
      records::StepRow row;
      row.time = i * 0.1;
      row.cameras = {Pose{-3.0, 0.1 * i, 0.0}};
      row.goals = {i >= 5 && i < 15 ? std::optional<Pose>(kGoal) : std::nullopt};
      run_.steps.push_back(row);
    }
    run_.events.push_back({0.5, "plan", 0, "", {{-3.0, 0.5, 0.0}, {-3.0, 2.0, 0.0}, kGoal}, {}});
    run_.events.push_back({1.5, "plan-completed", 0, "", {}, {}});
  }

  static constexpr Pose kGoal{0.0, 2.0, 1.0};
  scene::Scene scene_;
  records::RunRecord run_;
};

TEST_F(TinyRun, OneFramePerStepAtTheRecordedRate) {
  RunReplay replay(run_, scene_);
  EXPECT_EQ(runVideoSettings(run_).fps, 10);
  EXPECT_EQ(replay.frameCount(10), 31u);
  for (std::size_t k = 0; k < 31; ++k)
    EXPECT_EQ(replay.stepOfFrame(k, 10), k);
}

TEST_F(TinyRun, HigherRatesHoldStepsAndLowerRatesSkipThem) {
  RunReplay replay(run_, scene_);
  EXPECT_EQ(replay.frameCount(20), 61u);
  EXPECT_EQ(replay.stepOfFrame(2, 20), 1u);
  EXPECT_EQ(replay.stepOfFrame(60, 20), 30u);
  EXPECT_EQ(replay.frameCount(5), 16u);
  EXPECT_EQ(replay.stepOfFrame(3, 5), 6u);
  EXPECT_EQ(replay.frameCount(1), 4u);
}

TEST_F(TinyRun, FrameShowsThePlanOnlyWhileTheCameraFollowsIt) {
  RunReplay replay(run_, scene_);
  Frame frame;
  replay.build(10, frame);  // t = 1.0: camera at (-3, 1), on the plan's first leg
  EXPECT_EQ(frame.caption.subtitle, "method paper, seed 7");
  EXPECT_NEAR(frame.caption.time, 1.0, 1e-12);
  ASSERT_EQ(frame.cameras.size(), 1u);
  ASSERT_TRUE(frame.cameras[0].goal.has_value());
  EXPECT_EQ(*frame.cameras[0].goal, kGoal);
  const std::vector<Vec2> rest{{-3.0, 1.0}, {-3.0, 2.0}, {0.0, 2.0}};
  EXPECT_EQ(frame.cameras[0].plan, rest);

  replay.build(15, frame);  // t = 1.5: completed
  EXPECT_TRUE(frame.cameras[0].plan.empty());
  EXPECT_FALSE(frame.cameras[0].goal.has_value());
  replay.build(2, frame);  // before the plan
  EXPECT_TRUE(frame.cameras[0].plan.empty());
}

TEST_F(TinyRun, RunWithAnotherCameraCountIsAnInputError) {
  run_.steps[3].cameras.push_back({});
  EXPECT_THROW(RunReplay(run_, scene_), InputError);
  run_.steps.clear();
  EXPECT_THROW(RunReplay(run_, scene_), InputError);
}

TEST(RunVideoSettings, ShowEachStepOnceAtOneOverDtFramesPerSecond) {
  records::RunRecord run;
  run.metadata.parameters.sim.dt = 0.04;
  EXPECT_EQ(runVideoSettings(run).fps, 25);
  run.metadata.parameters.sim.dt = 3.0;
  EXPECT_EQ(runVideoSettings(run).fps, 1);
}

TEST(LoadRunScene, NoticesAChangedSceneFile) {
  records::RunMetadata metadata;
  metadata.sceneFile = "/nonexistent/scene.json";
  const RunScene moved = loadRunScene(metadata, testing::tinyScene());
  EXPECT_EQ(moved.scene.name, "tiny_scene");
  EXPECT_TRUE(moved.changed);  // the hash 0 matches no file
  EXPECT_THROW(loadRunScene(metadata), InputError);
}

}  // namespace
}  // namespace camcov::viz
