// The safety layer in whole runs, on the adversarial scenes of tests/data/safety/, whose
// outcome is proven by hand in the comment above each test (and in the README there). A
// scripted controller plays the adversary (it commands what a careless method might), so
// what is tested is the layer, which every method goes through.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "control/paper_controller.h"
#include "safety/safety_filter.h"
#include "scene/scene_loader.h"
#include "sim/simulator.h"
#include "support/test_paths.h"

namespace camcov::safety {
namespace {

// Commands camera j the velocity command(j, its position) every step.
class ScriptedController final : public control::Controller {
 public:
  using Script = std::function<geometry::Vec2(std::size_t, geometry::Vec2)>;
  explicit ScriptedController(Script script) : script_(std::move(script)) {}
  void control(const control::Observation& o, std::span<scene::CameraCommand> out) override {
    for (std::size_t j = 0; j < out.size(); ++j)
      out[j] = {script_(j, o.cameras[j].position()), 0.0};
  }
  std::optional<geometry::Pose> goal(std::size_t) const override { return std::nullopt; }
  void takeEvents(std::vector<control::ControlEvent>&) override {}

 private:
  Script script_;
};

// Full speed towards a fixed point: a controller that never looks where it goes.
ScriptedController::Script towards(geometry::Vec2 point, double speed) {
  return [point, speed](std::size_t, geometry::Vec2 p) {
    const double d = geometry::distance(p, point);
    return d > 1e-9 ? (point - p) * (speed / d) : geometry::Vec2{};
  };
}

struct Outcome {
  sim::RunSummary summary;
  std::vector<control::ControlEvent> events;
  std::vector<double> minObjectDistance;  // per step, over the step (continuous)
  std::vector<geometry::Pose> last;
};

class Keeper final : public sim::Recorder {
 public:
  explicit Keeper(Outcome& o) : o_(o) {}
  void step(const sim::StepRecord& r) override {
    o_.events.insert(o_.events.end(), r.events.begin(), r.events.end());
    o_.minObjectDistance.push_back(r.minObjectDistanceInStep);
    o_.last.assign(r.cameras.begin(), r.cameras.end());
  }

 private:
  Outcome& o_;
};

std::filesystem::path sceneFile(const std::string& name) {
  return testing::testDataDir() / "safety" / (name + ".json");
}

Outcome run(const std::string& name, control::Controller& controller, double duration,
            bool enabled = true) {
  const scene::Scene scene = scene::loadScene(sceneFile(name));
  params::Parameters p;
  p.sim.duration = duration;
  p.safety.enabled = enabled;
  Outcome o;
  Keeper keeper(o);
  o.summary = sim::simulate(scene, p, controller, keeper);
  return o;
}

std::vector<const control::ControlEvent*> eventsOf(const Outcome& o, const std::string& kind) {
  std::vector<const control::ControlEvent*> out;
  for (const auto& e : o.events) {
    if (e.kind == kind) out.push_back(&e);
  }
  return out;
}

// A run whose every contact the proof says is unavoidable: some time below δ, none of it
// avoidable, no avoidable-contact event. Returns the unavoidable-contact events.
std::vector<const control::ControlEvent*> onlyUnavoidableContacts(const Outcome& o) {
  EXPECT_GT(o.summary.unavoidableContactTime, 0.0);
  EXPECT_EQ(o.summary.avoidableContactTime, 0.0);
  EXPECT_TRUE(eventsOf(o, "avoidable-contact").empty());
  return eventsOf(o, "unavoidable-contact");
}

// OUTPACED. A corridor 30 × 4 m; a bar target 0.2 m × 3.6 m (y from 0.2 to 3.8) shuttles along
// it at 3 m/s from x = 2 to x = 28; the camera (0.5 m/s) starts at x = 15 in the middle.
// Proof that contact is unavoidable: where the bar's centre line is at the camera's x, every
// point of the corridor is within 0.2 m < δ of the bar; the bar first reaches x = 15 at
// t = 13/3 s, by when the camera has moved at most 2.2 m, so it cannot get past either end;
// and it cannot stay out of the bar's way, since the bar crosses every x in [2, 28].
// The layer must say so: "outpaced" (the bar alone closes faster than the camera can move
// away; the walls, 2 m off, play no part) — and no time below δ may count as avoidable.
TEST(SafetyScenarios, ABarFasterThanTheCameraSweepingACorridorIsAnUnavoidableOutpacedContact) {
  ScriptedController stay([](std::size_t, geometry::Vec2) { return geometry::Vec2{}; });
  const Outcome o = run("corridor_outpaced", stay, 10.0);
  const auto contacts = onlyUnavoidableContacts(o);
  ASSERT_FALSE(contacts.empty());
  EXPECT_EQ(contacts.front()->reason, "outpaced") << contacts.front()->detail;
  EXPECT_NE(contacts.front()->detail.find("target 0"), std::string::npos);
}

// OUTPACED, SLOWLY. The same corridor, 40 m long; the bar drives at 1 m/s from x = 2 towards
// x = 38, and a camera of 0.5 m/s at x = 8 is commanded straight at it (as dynamic1's plan
// drove its camera into an oncoming target). Unchecked, they would be δ apart at
// t = (8 − 0.1 − 0.5 − 2) / 1.5 = 3.6 s. The layer holds the camera at δ + margin, then at δ
// while it can (closing at 0.5 m/s it loses 0.05 m a step), then no velocity keeps δ, and it
// cannot get past the bar (every point of the corridor at the bar's x is within 0.2 m of it).
// The step that ends exactly at δ is no contact: the whole contact is unavoidable and begins
// after 3.6 s, none of it counted as avoidable (it all was, when the last step that could keep
// δ kept it only to rounding and the accounting, which never undercounts, saw a contact begin).
TEST(SafetyScenarios, ACameraChasedAtTwiceItsSpeedKeepsDeltaWhileItCanThenIsOutpaced) {
  ScriptedController careless(towards({0.0, 2.0}, 0.5));
  const Outcome o = run("chased_at_twice_its_speed", careless, 16.0);
  const auto contacts = onlyUnavoidableContacts(o);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts.front()->reason, "outpaced") << contacts.front()->detail;
  EXPECT_GE(contacts.front()->time, 3.6);
}

// CORNERED. A 10 m square room; a target 9.4 m wide (x from 0.3 to 9.7) and 2 m tall comes
// down from y = 6..8 to y = 0.2..2.2 at 0.8 m/s and goes back; the camera (1 m/s, faster
// than the target) starts at (5, 3), below it. Proof that contact is unavoidable: the camera
// cannot get above the target (the gaps beside it are 0.3 m wide, so every point in them is
// within 0.3 m < δ of it); once the target is down, every point below it is within 0.2 m of
// its bottom edge, and the corners of the room within √(0.3² + 0.2²) = 0.36 m of its corners.
// Yet no single threat outpaces the camera (1 m/s > 0.8 m/s): it is the wall that traps it,
// so the layer must call it "cornered" and count nothing as avoidable.
TEST(SafetyScenarios, ATargetPressingTheCameraAgainstTheWallIsAnUnavoidableCorneredContact) {
  ScriptedController stay([](std::size_t, geometry::Vec2) { return geometry::Vec2{}; });
  const Outcome o = run("wall_press_cornered", stay, 9.0);
  const auto contacts = onlyUnavoidableContacts(o);
  ASSERT_FALSE(contacts.empty());
  EXPECT_EQ(contacts.front()->reason, "cornered") << contacts.front()->detail;
  EXPECT_NE(contacts.front()->detail.find("boundary"), std::string::npos)
      << contacts.front()->detail;
  // Cornered means pressed to the wall, not pushed through it.
  EXPECT_EQ(o.summary.boundaryClamps, 0);
  // Without the layer the camera stands still and is hit far harder.
  ScriptedController stayAgain([](std::size_t, geometry::Vec2) { return geometry::Vec2{}; });
  const Outcome bare = run("wall_press_cornered", stayAgain, 9.0, false);
  EXPECT_GT(bare.summary.objectCollisionTime, o.summary.objectCollisionTime);
}

// HEAD-ON. Two cameras 10 m apart, each commanded at its full 2 m/s straight at the other.
// Proof that contact is avoidable: standing still is always admissible and keeps their
// distance, so a velocity that keeps δ exists at every step. The layer must keep them
// at least δ apart in continuous time, which the samples alone would not show.
TEST(SafetyScenarios, TwoCamerasCommandedHeadOnStopAtLeastDeltaApart) {
  ScriptedController collide([](std::size_t j, geometry::Vec2) {
    return geometry::Vec2{j == 0 ? 2.0 : -2.0, 0.0};
  });
  const Outcome o = run("head_on_cameras", collide, 5.0);
  EXPECT_GE(o.summary.minCameraDistance, 0.5);
  EXPECT_EQ(o.summary.cameraCollisionTime, 0.0);
  EXPECT_EQ(o.summary.avoidableContactTime + o.summary.unavoidableContactTime, 0.0);
  // Not stopped needlessly far apart either: about δ + margin.
  EXPECT_LT(geometry::distance(o.last[0].position(), o.last[1].position()), 0.7);
  ScriptedController collideAgain([](std::size_t j, geometry::Vec2) {
    return geometry::Vec2{j == 0 ? 2.0 : -2.0, 0.0};
  });
  const Outcome bare = run("head_on_cameras", collideAgain, 5.0, false);
  EXPECT_LT(bare.summary.minCameraDistance, 0.5) << "without the layer they meet";
  EXPECT_GT(bare.summary.avoidableContactTime, 0.0) << "and the layer judged it avoidable";
}

// A LONG ARM SWEEPING. A 4 m bar obstacle turns at 0.3 rad/s about its end at (15, 15), so
// no point of it moves faster than 0.3 · 4.0012 = 1.2 m/s; the camera, at 1.5 m/s, is
// commanded straight at the pivot all the time. Proof that contact is avoidable: moving
// directly away from the nearest point of the bar at 1.5 m/s opens the distance whatever the
// bar does, and the walls are over 10 m from the bar's reach, so a velocity keeping δ always
// exists. The layer must therefore keep δ for the whole run, against a rotating object
// whose speed it only knows from what it has seen.
TEST(SafetyScenarios, ACameraPressingTowardsTheHubOfASweepingArmKeepsDelta) {
  ScriptedController seek(towards({15.0, 15.0}, 1.5));
  const Outcome o = run("sweeping_arm", seek, 30.0);
  EXPECT_GE(o.summary.minObjectDistance, 0.5);
  EXPECT_EQ(o.summary.objectCollisionTime, 0.0);
  EXPECT_EQ(o.summary.unavoidableContacts + o.summary.avoidableContacts, 0);
  ScriptedController seekAgain(towards({15.0, 15.0}, 1.5));
  EXPECT_GT(run("sweeping_arm", seekAgain, 30.0, false).summary.objectCollisionTime, 0.0)
      << "the scene must be a real threat";
}

// INSIDE d1. A camera 0.8 m from a pillar — closer than the planner's d1 = 1 m, so no
// planner state is valid where it stands — commanded at full speed into the pillar.
// Proof that contact is avoidable: the pillar does not move, so standing still keeps the
// 0.8 m. The layer must stop the camera between δ and δ + margin, and the paper's method,
// which starts there with no valid state, must not hit it either.
TEST(SafetyScenarios, ACameraStartingInsideD1CommandedIntoAPillarStopsBeyondDelta) {
  ScriptedController ram(towards({5.0, 5.0}, 2.0));
  const Outcome o = run("inside_d1_pillar", ram, 3.0);
  EXPECT_GE(o.summary.minObjectDistance, 0.5);
  EXPECT_LE(o.minObjectDistance.back(), 0.5 + 0.1 + 1e-9);
  EXPECT_EQ(o.summary.objectCollisionTime, 0.0);

  const scene::Scene scene = scene::loadScene(sceneFile("inside_d1_pillar"));
  params::Parameters p;
  p.sim.duration = 10.0;
  control::PaperController paper(scene, p, 1);
  Outcome withPaper;
  Keeper keeper(withPaper);
  withPaper.summary = sim::simulate(scene, p, paper, keeper);
  EXPECT_GE(withPaper.summary.minObjectDistance, 0.5);
}

// WITHIN δ FROM THE START. A camera placed 0.3 m from a pillar (allowed: it is not inside it)
// is in contact at t = 0, before anything could be done: unavoidable, "within-delta". The
// layer must then take it out to δ (2 m/s against a static pillar: one step) and keep it.
TEST(SafetyScenarios, ACameraStartingWithinDeltaIsAnUnavoidableContactAndIsTakenOut) {
  ScriptedController ram(towards({5.0, 5.0}, 2.0));
  const Outcome o = run("starts_within_delta", ram, 3.0);
  const auto contacts = onlyUnavoidableContacts(o);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts.front()->reason, "within-delta");
  EXPECT_EQ(contacts.front()->time, 0.0);
  EXPECT_LE(o.summary.unavoidableContactTime, 0.1 + 1e-12) << "out within one step";
  EXPECT_GE(o.minObjectDistance.back(), 0.5);
}

}  // namespace
}  // namespace camcov::safety
