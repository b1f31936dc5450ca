// Runs under limited knowledge (params::KnowledgeParams): the methods read only what the team
// knows, and where the team knows the true world the run is the full-knowledge one.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "control/methods.h"
#include "sim/simulator.h"
#include "support/small_worlds.h"

namespace camcov::sim {
namespace {

// Static: camera 0 sees the target, camera 1 the obstacle, from the first instant on.
const char* kAllInViewAtOnce = R"js({
  "boundary": "POLYGON((-20 -20,20 -20,20 20,-20 20))",
  "targets": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((0 0))"}],
  "obstacles": [{"shape": "POLYGON((-1 -0.5,1 -0.5,1 0.5,-1 0.5))", "path": "POLYGON((6 0))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-5 0)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(8 10)", "angle": -90, "maxVelocity": 1, "maxAngularVelocity": 1}]})js";

// Target 1 at (5, 0) stands behind a wall from x = -1.5 to -1 over y in [-8, 8]; the two
// cameras, west of the wall and nearly unable to move or turn, never see it.
const char* kHiddenTarget = R"js({
  "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
  "targets": [{"shape": "POLYGON((-0.3 -0.3,0.3 -0.3,0.3 0.3,-0.3 0.3))", "path": "POLYGON((-5 1))"},
              {"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((5 0))"}],
  "obstacles": [{"shape": "POLYGON((-0.25 -8,0.25 -8,0.25 8,-0.25 8))", "path": "POLYGON((-1.25 0))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-8 0)", "angle": 0, "maxVelocity": 0.001, "maxAngularVelocity": 0.001},
              {"pos": "POINT(-8 -5)", "angle": 0, "maxVelocity": 0.001, "maxAngularVelocity": 0.001}]})js";

params::Parameters shortRun(bool limited) {
  params::Parameters p;
  p.sim.duration = 3.0;
  p.global.K = 100;
  p.knowledge.limited = limited;
  return p;
}

// Everything a run measured, step by step.
class Keeper final : public Recorder {
 public:
  void step(const StepRecord& r) override {
    coverage.push_back(r.terms.coverage);
    reward.push_back(r.terms.reward);
    poses.emplace_back(r.cameras.begin(), r.cameras.end());
    for (const auto& e : r.events)
      events.push_back(e.kind + " " + e.detail);
  }
  std::vector<double> coverage, reward;
  std::vector<std::vector<geometry::Pose>> poses;
  std::vector<std::string> events;
};

// A method's controller, watched: which targets each observation held.
class Watched final : public control::Controller {
 public:
  explicit Watched(std::unique_ptr<control::Controller> inner) : inner_(std::move(inner)) {}
  void control(const control::Observation& o, std::span<scene::CameraCommand> out) override {
    targetIds.insert(targetIds.end(), o.world.targetIds.begin(), o.world.targetIds.end());
    for (const auto& s : o.seen)
      segmentsOutsideTheWorld += s.target >= o.world.targets.size() ? 1 : 0;
    inner_->control(o, out);
  }
  std::optional<geometry::Pose> goal(std::size_t j) const override { return inner_->goal(j); }
  void takeEvents(std::vector<control::ControlEvent>& out) override { inner_->takeEvents(out); }
  std::vector<std::uint32_t> targetIds;
  int segmentsOutsideTheWorld = 0;

 private:
  std::unique_ptr<control::Controller> inner_;
};

const char* const kMethods[] = {"paper", "local", "camcov"};

TEST(LimitedKnowledge, WhereTheTeamSeesEverythingAtOnceARunIsTheFullKnowledgeRun) {
  // Nothing moves and every object is seen at t = 0, so what the team knows is the true world
  // at every instant: the methods decide exactly as with full knowledge.
  const scene::Scene scene = testing::sceneFromJson(kAllInViewAtOnce);
  for (const char* name : kMethods) {
    SCOPED_TRACE(name);
    const control::Method& method = control::requireMethod(name);
    Keeper full, limited;
    auto a = method.make(scene, shortRun(false), 3);
    auto b = method.make(scene, shortRun(true), 3);
    const RunSummary fullSummary = simulate(scene, shortRun(false), *a, full, 3);
    const RunSummary limitedSummary = simulate(scene, shortRun(true), *b, limited, 3);
    EXPECT_EQ(limited.coverage, full.coverage);
    EXPECT_EQ(limited.reward, full.reward);
    EXPECT_EQ(limited.poses, full.poses);
    EXPECT_EQ(limited.events, full.events);
    EXPECT_EQ(limitedSummary.averageCoverage, fullSummary.averageCoverage);
    EXPECT_FALSE(fullSummary.messages.has_value());
    ASSERT_TRUE(limitedSummary.messages.has_value());
    // 31 instants, each camera sends to the other at each: 62 messages, all heard.
    EXPECT_EQ(limitedSummary.messages->sent, 62);
    EXPECT_EQ(limitedSummary.messages->delivered, 62);
    EXPECT_EQ(limitedSummary.messages->lost, 0);
  }
}

TEST(LimitedKnowledge, NoMethodIsShownATargetNobodyHasSeen) {
  const scene::Scene scene = testing::sceneFromJson(kHiddenTarget);
  for (const char* name : kMethods) {
    SCOPED_TRACE(name);
    const control::Method& method = control::requireMethod(name);
    for (const bool limited : {false, true}) {
      Watched watched(method.make(scene, shortRun(limited), 1));
      Keeper keeper;
      const RunSummary summary = simulate(scene, shortRun(limited), watched, keeper, 1);
      EXPECT_EQ(summary.steps, 31);
      const bool shownHidden =
          std::count(watched.targetIds.begin(), watched.targetIds.end(), 1U) > 0;
      // Full knowledge shows it (the check can fail); limited never does.
      EXPECT_EQ(shownHidden, !limited);
      EXPECT_EQ(std::count(watched.targetIds.begin(), watched.targetIds.end(), 0U), 30);
      EXPECT_EQ(watched.segmentsOutsideTheWorld, 0);
      // The simulator still scores the true world: the hidden target's boundary is unseen.
      EXPECT_LT(keeper.coverage.front(), 0.5);
    }
  }
}

TEST(LimitedKnowledge, TheObservationsTermsAreTheKnownWorldsAndTheScoredOnesTheTrueWorlds) {
  const scene::Scene scene = testing::sceneFromJson(kHiddenTarget);
  Simulation full(scene, shortRun(false), 1);
  Simulation limited(scene, shortRun(true), 1);
  EXPECT_EQ(full.observation().terms.coverage, full.scored().terms.coverage);
  EXPECT_EQ(limited.scored().terms.coverage, full.scored().terms.coverage);
  EXPECT_EQ(limited.scored().world.targets.size(), 2U);
  EXPECT_EQ(limited.observation().world.targets.size(), 1U);
  // The hidden target's 4 m of boundary count in the true world only: what is seen of the
  // small target (2.4 m round) is a larger part of the known world's perimeter.
  const double seen = full.scored().terms.coverage * 6.4;
  EXPECT_GT(seen, 0.0);
  EXPECT_NEAR(limited.observation().terms.coverage, seen / 2.4, 1e-9);
}

}  // namespace
}  // namespace camcov::sim
