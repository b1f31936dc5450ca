// camcov-dec (control/decentralized_controller.h): each camera decides from its own knowledge.
#include "control/decentralized_controller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "control/event_kind.h"
#include "control/methods.h"
#include "sim/simulator.h"
#include "support/small_worlds.h"
#include "support/test_paths.h"
#include "util/run_threads.h"

namespace camcov::control {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Two rooms: a wall along x = 0 (gaps of 5 cm at the ends, too narrow for a camera or a line
// of sight that reaches anything) keeps camera 0 and target 0 in the west, camera 1 and
// target 1 in the east, along `eastPath`; without `eastCamera`, camera 0 alone.
std::string twoRooms(const std::string& eastPath, int westYaw = -34, bool eastCamera = true) {
  return R"js({
  "boundary": "POLYGON((-10 -5,10 -5,10 5,-10 5))",
  "targets": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((-5 0))"},
              {"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": ")js" +
         eastPath + R"js("}],
  "obstacles": [{"shape": "POLYGON((-0.25 -4.95,0.25 -4.95,0.25 4.95,-0.25 4.95))", "path": "POLYGON((0 0))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-8 2)", "angle": )js" +
         std::to_string(westYaw) + R"js(, "maxVelocity": 1, "maxAngularVelocity": 1})js" +
         (eastCamera ? R"js(,
              {"pos": "POINT(8 -2)", "angle": 146, "maxVelocity": 1, "maxAngularVelocity": 1})js"
                     : "") +
         "]}";
}

params::Parameters limited(double range, double loss = 0.0) {
  params::Parameters p;
  p.sim.duration = 6.0;  // two global steps: at dt and at dt + T1
  p.global.K = 100;
  p.knowledge.limited = true;
  p.comms.range = range;
  p.comms.loss = loss;
  return p;
}

// The commands a controller gave, step by step, and the poses and events of the run.
class Recorded final : public Controller, public sim::Recorder {
 public:
  explicit Recorded(std::unique_ptr<Controller> inner) : inner_(std::move(inner)) {}
  void control(const Observation& o, std::span<scene::CameraCommand> out) override {
    inner_->control(o, out);
    commands.emplace_back(out.begin(), out.end());
  }
  std::optional<geometry::Pose> goal(std::size_t j) const override { return inner_->goal(j); }
  void takeEvents(std::vector<ControlEvent>& out) override { inner_->takeEvents(out); }
  void step(const sim::StepRecord& r) override {
    poses.emplace_back(r.cameras.begin(), r.cameras.end());
    for (const auto& e : r.events) {
      events.push_back(e.kind + " " + std::to_string(e.camera) + " " + e.detail);
      if (e.kind == eventName(EventKind::Neighbourhood))
        neighbourhoods.push_back({r.time, poses.size() - 1, e.camera, e.detail});
      if (e.kind == eventName(EventKind::NonFiniteCommand)) ++nonFinite;
    }
  }
  // Camera j's commands over the run, as (vx, vy, γ̇) triples.
  std::vector<std::vector<double>> of(std::size_t j) const {
    std::vector<std::vector<double>> out;
    for (const auto& step : commands)
      out.push_back({step[j].velocity.x, step[j].velocity.y, step[j].angularVelocity});
    return out;
  }
  std::vector<std::vector<scene::CameraCommand>> commands;
  std::vector<std::vector<geometry::Pose>> poses;
  std::vector<std::string> events;
  // camcov-dec's neighbourhood changes: when, at which step, whose, and its detail.
  struct Change {
    double time;
    std::size_t step;
    int camera;
    std::string detail;
  };
  std::vector<Change> neighbourhoods;
  int nonFinite = 0;

 private:
  std::unique_ptr<Controller> inner_;
};

struct Run {
  Recorded recorded;
  sim::RunSummary summary;
};

std::unique_ptr<Run> run(const scene::Scene& scene, const params::Parameters& p, std::uint64_t seed,
                         const char* method = "camcov-dec") {
  auto r = std::make_unique<Run>(Run{Recorded(requireMethod(method).make(scene, p, seed)), {}});
  r->summary = sim::simulate(scene, p, r->recorded, r->recorded, seed);
  return r;
}

TEST(DecentralizedController, IsInTheTableRunOnlyWhenAskedFor) {
  const Method& method = requireMethod("camcov-dec");
  EXPECT_EQ(method.role, Role::example);
  const auto defaults = defaultMethods();
  EXPECT_EQ(std::count(defaults.begin(), defaults.end(), "camcov-dec"), 0);
}

TEST(DecentralizedController, TheSameSeedGivesTheSameRun) {
  const scene::Scene scene = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))"));
  const params::Parameters p = limited(10.0, 0.5);
  const auto a = run(scene, p, 7), b = run(scene, p, 7);
  EXPECT_EQ(a->recorded.poses, b->recorded.poses);
  EXPECT_EQ(a->recorded.events, b->recorded.events);
  EXPECT_EQ(a->summary.averageCoverage, b->summary.averageCoverage);
}

TEST(DecentralizedController, WithFullKnowledgeEveryCameraTakesItsPartOfCamcovsPlan) {
  // Every camera knows what the centralized method knows and draws from the same seed, so
  // the team moves as camcov moves it, pose for pose.
  const scene::Scene scene = testing::sceneFromJson(testing::kOneTargetScene);
  params::Parameters p;
  p.sim.duration = 6.0;
  p.global.K = 100;
  const auto ours = run(scene, p, 3), centralized = run(scene, p, 3, "camcov");
  EXPECT_EQ(ours->recorded.poses, centralized->recorded.poses);
  EXPECT_EQ(ours->summary.averageCoverage, centralized->summary.averageCoverage);
}

TEST(DecentralizedController, ACameraWhoseNeighbourhoodIsItselfMovesAsCamcovMovesItAlone) {
  // With neighbourhoods of one, camera 0 plans for itself only: its run is camcov's in the same
  // rooms without camera 1, whose wall-separated presence changes nothing it plans with.
  const scene::Scene both = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))"));
  const scene::Scene alone = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))", -34, false));
  params::Parameters p;
  p.sim.duration = 11.0;  // three global steps
  p.global.K = 100;
  p.camcov.neighbours = 1;
  const auto ours = run(both, p, 5), centralized = run(alone, p, 5, "camcov");
  EXPECT_EQ(ours->recorded.of(0), centralized->recorded.of(0));
  // With one neighbourhood of both (the default) the team plans as one, and camera 0 moves
  // otherwise (the check can fail).
  p.camcov.neighbours = 2;
  EXPECT_NE(run(both, p, 5)->recorded.of(0), centralized->recorded.of(0));
}

// A 30 m hall: two cameras at each end, two targets driving across it in opposite directions,
// so that each camera's nearest teammates change as the cameras follow them.
scene::Scene crossingHall() {
  return testing::sceneFromJson(R"js({
  "boundary": "POLYGON((-15 -6,15 -6,15 6,-15 6))",
  "targets": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((-12 -4,12 -4))"},
              {"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((12 4,-12 4))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-13 0)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(-10 0)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(10 0)", "angle": 180, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(13 0)", "angle": 180, "maxVelocity": 1, "maxAngularVelocity": 1}]})js");
}

TEST(DecentralizedController, ALargerTeamPlansInNeighbourhoodsOfItsNearestChosenEveryT1) {
  // Four cameras and two neighbourhoods of two: as the cameras follow the targets across the
  // hall the nearest teammates change, and each change is one event at a global step's time
  // naming the camera's nearest teammate where the run put the team at that step.
  const scene::Scene scene = crossingHall();
  params::Parameters p;
  p.sim.duration = 30.0;
  p.global.K = 100;
  p.camcov.neighbours = 2;
  const auto r = run(scene, p, 2);
  const auto& changes = r->recorded.neighbourhoods;
  EXPECT_GE(changes.size(), 2u);
  for (const auto& change : changes) {
    SCOPED_TRACE(change.detail);
    const double globalSteps = (change.time - p.sim.dt) / p.global.T1;
    EXPECT_NEAR(globalSteps, std::round(globalSteps), 1e-9);
    EXPECT_GE(globalSteps, 1.0);  // chosen at the start without an event
    // The teammate it names is the nearest one at that step.
    const std::vector<geometry::Pose>& team = r->recorded.poses[change.step];
    const auto j = static_cast<std::size_t>(change.camera);
    std::size_t nearest = j == 0 ? 1 : 0;
    for (std::size_t i = 0; i < team.size(); ++i) {
      if (i != j && geometry::distance(team[i].position(), team[j].position()) <
                        geometry::distance(team[nearest].position(), team[j].position()))
        nearest = i;
    }
    const auto [first, second] = std::minmax(j, nearest);
    EXPECT_EQ(change.detail,
              "plans with cameras " + std::to_string(first) + ", " + std::to_string(second));
  }
  EXPECT_EQ(r->summary.avoidableContacts, 0);
}

// A 60 m hall: cameras 0 and 1 and a standing target in the west, cameras 2 and 3 and a target
// driving along `eastPath` in the east.
std::string westAndEast(const std::string& eastPath) {
  return R"js({
  "boundary": "POLYGON((-30 -6,30 -6,30 6,-30 6))",
  "targets": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((-20 3))"},
              {"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": ")js" +
         eastPath + R"js("}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-25 0)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(-22 -2)", "angle": 90, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(22 0)", "angle": 180, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(25 2)", "angle": 180, "maxVelocity": 1, "maxAngularVelocity": 1}]})js";
}

TEST(DecentralizedController, InATeamLargerThanItsNeighbourhoodACameraPlansInItsRegionOnly) {
  // Neighbourhoods of two: cameras 0 and 1 plan in the west, where their region (their box
  // widened by twice its larger side) holds the west target only. Though every camera knows
  // everything, what the east target does changes nothing cameras 0 and 1 do.
  const scene::Scene along = testing::sceneFromJson(westAndEast("POLYGON((10 -3,10 3))"));
  const scene::Scene across = testing::sceneFromJson(westAndEast("POLYGON((5 0,15 1,12 -3))"));
  params::Parameters p;
  p.sim.duration = 11.0;  // three global steps
  p.global.K = 100;
  p.camcov.neighbours = 2;
  p.camcov.region = 2.0;
  const auto a = run(along, p, 4), b = run(across, p, 4);
  EXPECT_EQ(a->recorded.of(0), b->recorded.of(0));
  EXPECT_EQ(a->recorded.of(1), b->recorded.of(1));
  EXPECT_NE(a->recorded.of(2), b->recorded.of(2));
  // Planning in the whole hall they do differ (the check can fail).
  p.camcov.region = kInf;
  const auto wholeA = run(along, p, 4), wholeB = run(across, p, 4);
  EXPECT_NE(wholeA->recorded.of(0), wholeB->recorded.of(0));
  EXPECT_EQ(a->summary.avoidableContacts + b->summary.avoidableContacts, 0);
}

TEST(DecentralizedController, ItsLoopsGiveTheSameRunOnAnyNumberOfThreads) {
  // The loops of a step run side by side on the run's threads: commands, poses and events in
  // the same order and to the bit, with neighbourhoods that change, limited knowledge and
  // claims over the messages.
  const scene::Scene scene = crossingHall();
  params::Parameters p = limited(20.0, 0.3);
  p.sim.duration = 30.0;
  p.camcov.neighbours = 2;
  p.camcov.claims = 20.0;
  struct Threads {
    explicit Threads(unsigned n) { setRunThreads(n); }
    ~Threads() { setRunThreads(1); }
  };
  const auto alone = run(scene, p, 5);
  for (const unsigned n : {2u, 3u, 8u}) {
    SCOPED_TRACE(n);
    const Threads threads(n);
    const auto side = run(scene, p, 5);
    EXPECT_EQ(side->recorded.events, alone->recorded.events);
    for (std::size_t j = 0; j < scene.cameras.size(); ++j)
      EXPECT_EQ(side->recorded.of(j), alone->recorded.of(j));
  }
  // Something to compare: every camera moved, and neighbourhoods were chosen again.
  EXPECT_FALSE(alone->recorded.neighbourhoods.empty());
  EXPECT_GT(alone->recorded.events.size(), 8u);
}

TEST(DecentralizedController, ACameraIgnoresWhatItNeitherSawNorHeard) {
  // Target 1 moves along one path or another in the east room. Camera 0, in the west, never
  // sees it; without messages it never hears of it either, so its commands are the same
  // bits whichever path target 1 takes, although camera 1's are not.
  const scene::Scene along = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))"));
  const scene::Scene across = testing::sceneFromJson(twoRooms("POLYGON((3 0,7 1,6 -3))"));
  const auto a = run(along, limited(0.0), 1), b = run(across, limited(0.0), 1);
  EXPECT_EQ(a->recorded.of(0), b->recorded.of(0));
  EXPECT_NE(a->recorded.of(1), b->recorded.of(1));
  // With messages camera 0 hears where target 1 is, and does differ (the check can fail).
  const auto heardA = run(along, limited(kInf), 1), heardB = run(across, limited(kInf), 1);
  EXPECT_NE(heardA->recorded.of(0), heardB->recorded.of(0));
}

TEST(DecentralizedController, ACameraThatKnowsNoTargetLooksRoundForOne) {
  // Camera 0 starts facing the north wall and hears nothing: it turns at its full rate until
  // target 0 comes into view, then plans for it and comes to cover it.
  const scene::Scene scene = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))", 90));
  const auto r = run(scene, limited(0.0), 1);
  const auto commands = r->recorded.of(0);
  EXPECT_EQ(commands.front(), (std::vector<double>{0.0, 0.0, 1.0}));
  const auto turning = std::count(commands.begin(), commands.end(), commands.front());
  EXPECT_GT(turning, 1);
  EXPECT_LT(turning, static_cast<long>(commands.size()));
  EXPECT_GT(r->summary.finalCoverage, 0.0);
}

TEST(DecentralizedController, AClaimNobodyHearsChangesNothing) {
  // camcov.claims: a teammate's goal is a claim only where its message arrives. Out of range
  // (no messages at all) or lost, every command is the same bits as without claims.
  const scene::Scene scene = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))"));
  for (const auto& [range, loss] : {std::pair{0.0, 0.0}, std::pair{kInf, 1.0}}) {
    SCOPED_TRACE(range);
    params::Parameters p = limited(range, loss);
    const auto without = run(scene, p, 4);
    p.camcov.claims = 5.0;
    const auto with = run(scene, p, 4);
    EXPECT_EQ(with->recorded.of(0), without->recorded.of(0));
    EXPECT_EQ(with->recorded.of(1), without->recorded.of(1));
    EXPECT_EQ(with->recorded.events, without->recorded.events);
  }
}

TEST(DecentralizedController, WithHeardOnlyACameraThatHearsNobodyPlansAlone) {
  // camcov.heardOnly: a teammate never heard is left out instead of believed at its start, so
  // without messages each camera plans as it does in a neighbourhood of itself alone.
  const scene::Scene scene = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))"));
  params::Parameters alone = limited(0.0);
  alone.sim.duration = 11.0;  // three global steps
  alone.camcov.neighbours = 1;
  params::Parameters heardOnly = limited(0.0);
  heardOnly.sim.duration = 11.0;
  heardOnly.camcov.heardOnly = true;
  const auto a = run(scene, alone, 5), b = run(scene, heardOnly, 5);
  EXPECT_EQ(b->recorded.of(0), a->recorded.of(0));
  EXPECT_EQ(b->recorded.of(1), a->recorded.of(1));
  // Believing camera 1 at its start changes camera 0's plan (the check can fail).
  heardOnly.camcov.heardOnly = false;
  EXPECT_NE(run(scene, heardOnly, 5)->recorded.of(0), a->recorded.of(0));
}

TEST(DecentralizedController, MovingItsOwnPartOnlyChangesNothingForACameraWithoutTeammates) {
  // camcov.ownPartOnly: a camera judges its part of its neighbourhood's plan as its move alone.
  // In a neighbourhood of itself alone its part is the plan: every command the same bits.
  const scene::Scene scene = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))"));
  params::Parameters p = limited(kInf);
  p.sim.duration = 11.0;  // three global steps
  p.camcov.neighbours = 1;
  const auto own = run(scene, p, 5);
  p.camcov.ownPartOnly = false;
  const auto whole = run(scene, p, 5);
  EXPECT_EQ(own->recorded.of(0), whole->recorded.of(0));
  EXPECT_EQ(own->recorded.of(1), whole->recorded.of(1));
  // With a teammate in its neighbourhood, the judgement alone differs (the check can fail).
  p.camcov.neighbours = 2;
  const auto together = run(scene, p, 5);
  p.camcov.ownPartOnly = true;
  const auto alone = run(scene, p, 5);
  EXPECT_TRUE(alone->recorded.of(0) != together->recorded.of(0) ||
              alone->recorded.of(1) != together->recorded.of(1));
}

TEST(DecentralizedController, WithFullKnowledgeACameraMovesItsOwnPartOnlyInATeamLargerThanN) {
  // Neighbourhoods differ from camera to camera in a team larger than N, so no teammate takes
  // the part a camera's loop planned for it, whatever the camera knows: camcov.ownPartOnly
  // holds with full knowledge too. A team of at most N stays camcov's, bit for bit.
  const scene::Scene scene = crossingHall();
  params::Parameters p;
  p.sim.duration = 11.0;  // three global steps
  p.global.K = 100;
  const auto posesOf = [&](int neighbours, bool ownPartOnly) {
    p.camcov.neighbours = neighbours;
    p.camcov.ownPartOnly = ownPartOnly;
    return run(scene, p, 2)->recorded.poses;
  };
  EXPECT_NE(posesOf(2, true), posesOf(2, false));
  const auto oneNeighbourhood = posesOf(4, true);
  EXPECT_EQ(oneNeighbourhood, posesOf(4, false));
  EXPECT_EQ(oneNeighbourhood, run(scene, p, 2, "camcov")->recorded.poses);
}

// The published scenes with messages that reach everyone (`range` inf), or few of them.
void runEveryPublishedScene(const params::Parameters& p) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const auto files = testing::jsonFilesIn(testing::publishedScenesDir());
  EXPECT_EQ(files.size(), 32U);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    const scene::Scene scene = scene::loadScene(file);
    const auto r = run(scene, p, 1);
    EXPECT_EQ(r->summary.steps, static_cast<int>(std::llround(p.sim.duration / p.sim.dt)) + 1);
    EXPECT_EQ(r->recorded.nonFinite, 0);
    // The safety layer still stands between the commands and the cameras.
    EXPECT_EQ(r->summary.avoidableContacts, 0);
    EXPECT_GE(r->summary.averageCoverage, 0.0);
    EXPECT_LE(r->summary.averageCoverage, 1.0);
  }
}

TEST(DecentralizedController, RunsEveryPublishedSceneWithMessagesThatReachEveryone) {
  params::Parameters p = limited(kInf);
  p.global.K = 500;
  p.sim.duration = 10.0;
  runEveryPublishedScene(p);
}

TEST(DecentralizedController, RunsEveryPublishedSceneWhenHalfTheMessagesAreLost) {
  params::Parameters p = limited(10.0, 0.5);
  p.global.K = 500;
  p.sim.duration = 10.0;
  p.comms.latency = 0.2;
  runEveryPublishedScene(p);
}

}  // namespace
}  // namespace camcov::control
