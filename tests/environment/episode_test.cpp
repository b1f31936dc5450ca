// Episodes stepped by their caller: the same run as sim::simulate's, the documented
// observation layout against the scene itself, and many episodes stepped on threads giving what
// one thread gives.
#include "environment/episode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "control/methods.h"
#include "environment/episode_batch.h"
#include "environment/method_policy.h"
#include "environment/observation_encoding.h"
#include "geometry/ring.h"
#include "support/small_worlds.h"

namespace camcov::environment {
namespace {

std::shared_ptr<const scene::Scene> oneTargetScene() {
  static const auto s =
      std::make_shared<const scene::Scene>(testing::sceneFromJson(testing::kOneTargetScene));
  return s;
}

params::Parameters shortRun(double seconds) {
  params::Parameters p;
  p.sim.duration = seconds;
  return p;
}

class CoverageSeries final : public sim::Recorder {
 public:
  void step(const sim::StepRecord& r) override { coverage.push_back(r.terms.coverage); }
  std::vector<double> coverage;
};

TEST(Episode, DrivenByAMethodsPolicyIsThatMethodsRunToTheBit) {
  const auto scene = oneTargetScene();
  const params::Parameters params = shortRun(5.0);
  for (const char* name : {"paper", "local", "camcov"}) {
    const control::Method& method = control::requireMethod(name);
    CoverageSeries run;
    const auto controller = method.make(*scene, params, 7);
    const sim::RunSummary expected = sim::simulate(*scene, params, *controller, run);

    Episode episode(scene, params);
    MethodPolicy policy(method, episode, 7);
    std::vector<double> coverage{episode.observation().terms.coverage};
    std::vector<scene::CameraCommand> commands(scene->cameras.size());
    while (!episode.finished()) {
      policy.decide(episode, commands);
      episode.step(commands);
      coverage.push_back(episode.observation().terms.coverage);
    }
    episode.close();
    EXPECT_EQ(coverage, run.coverage) << name;
    EXPECT_EQ(episode.summary().averageCoverage, expected.averageCoverage) << name;
    EXPECT_THROW(episode.step(commands), std::logic_error);
  }
}

TEST(Episode, TheObservationIsTheDocumentedLayout) {
  const auto scene = oneTargetScene();
  Episode episode(scene, shortRun(1.0));
  // Two cameras, one target, one obstacle, squares of 4 vertices: padded to more of each.
  const EncodingSizes sizes{3, 2, 2, 6};
  std::vector<float> out(sizes.size());
  encodeObservation(episode, sizes, View::team, 0, out);
  // The room is the square [-10, 10]²: c = 0, L = 10.
  const float* camera = out.data() + EncodingSizes::kGlobal;
  EXPECT_EQ(camera[0], 1.0f);
  EXPECT_FLOAT_EQ(camera[1], -0.6f);  // POINT(-6 -6)
  EXPECT_FLOAT_EQ(camera[2], -0.6f);
  EXPECT_NEAR(camera[3], std::cos(225.0 * M_PI / 180.0), 1e-6);
  EXPECT_FLOAT_EQ(camera[5], 0.2f);                             // v_max 2 m/s over L
  EXPECT_FLOAT_EQ(camera[8], 0.0f);                             // no sensing range
  const float* empty = camera + 2 * EncodingSizes::kPerCamera;  // a third slot: padding
  for (std::size_t k = 0; k < EncodingSizes::kPerCamera; ++k)
    EXPECT_EQ(empty[k], 0.0f);
  const float* target = camera + sizes.cameras * EncodingSizes::kPerCamera;
  EXPECT_EQ(target[0], 1.0f);
  EXPECT_FLOAT_EQ(target[2], 0.0f);  // the square about (0, 0)
  EXPECT_FLOAT_EQ(target[4], 4.0f / 6.0f);
  EXPECT_FLOAT_EQ(target[5], -0.1f);  // its first vertex, (-1, -1)
  EXPECT_FLOAT_EQ(target[6], -0.1f);
  const float* obstacle = target + sizes.targets * sizes.perTarget();
  EXPECT_EQ(obstacle[0], 1.0f);
  EXPECT_FLOAT_EQ(obstacle[2], 0.45f);  // (5 − 0.5) / 10
  EXPECT_EQ(out.size(), EncodingSizes::kGlobal + 3 * 10 + 2 * 17 + 2 * 14);

  // Camera 1's own view: itself in the first slot, its teammate after it, no obstacle.
  encodeObservation(episode, sizes, View::own, 1, out);
  EXPECT_FLOAT_EQ(camera[1], 0.6f);
  EXPECT_EQ(camera[EncodingSizes::kPerCamera], 1.0f);
  EXPECT_FLOAT_EQ(camera[EncodingSizes::kPerCamera + 1], -0.6f);
  EXPECT_EQ(camera[2 * EncodingSizes::kPerCamera], 0.0f);
  EXPECT_EQ(obstacle[0], 0.0f);

  const EncodingSizes small{1, 1, 1, 4};
  std::vector<float> tooSmall(small.size());
  EXPECT_THROW(encodeObservation(episode, small, View::team, 0, tooSmall), std::invalid_argument);
}

TEST(Episode, TheOwnViewNeedsNoObstacleSlotsAsItShowsNone) {
  const auto scene = oneTargetScene();  // one obstacle
  Episode episode(scene, shortRun(1.0));
  const EncodingSizes withObstacle{2, 1, 1, 4}, without{2, 1, 0, 4};
  std::vector<float> full(withObstacle.size()), cut(without.size());
  encodeObservation(episode, withObstacle, View::own, 1, full);
  encodeObservation(episode, without, View::own, 1, cut);
  EXPECT_EQ(std::vector<float>(full.begin(), full.begin() + cut.size()), cut)
      << "the same floats, without the obstacle slot the own view leaves zero";
  EXPECT_THROW(encodeObservation(episode, without, View::team, 0, cut), std::invalid_argument)
      << "the team view shows the obstacle";
}

// The floats of camera slot `slot` of an encoding.
std::vector<float> cameraSlot(const std::vector<float>& out, std::size_t slot) {
  const auto first = out.begin() + static_cast<std::ptrdiff_t>(EncodingSizes::kGlobal +
                                                               slot * EncodingSizes::kPerCamera);
  return {first, first + EncodingSizes::kPerCamera};
}

TEST(Episode, WithFullKnowledgeACamerasKnownViewIsTheTeamViewWithItsSlotFirst) {
  const auto scene = oneTargetScene();
  Episode episode(scene, shortRun(1.0));
  const EncodingSizes sizes{2, 1, 1, 4};
  std::vector<float> team(sizes.size()), known(sizes.size());
  for (int k = 0; k < 3; ++k) {
    encodeObservation(episode, sizes, View::team, 0, team);
    encodeObservation(episode, sizes, View::known, 1, known);
    EXPECT_EQ(cameraSlot(known, 0), cameraSlot(team, 1));
    EXPECT_EQ(cameraSlot(known, 1), cameraSlot(team, 0));
    const std::size_t rest = EncodingSizes::kGlobal + 2 * EncodingSizes::kPerCamera;
    EXPECT_TRUE(std::equal(team.begin(), team.begin() + EncodingSizes::kGlobal, known.begin()));
    EXPECT_TRUE(std::equal(team.begin() + rest, team.end(), known.begin() + rest))
        << "the same targets and obstacles";
    const std::vector<scene::CameraCommand> turn(2, {{0.5, 0.0}, 0.5});
    episode.step(turn);
  }
}

// Camera 1 faces the target from (6, 6), camera 0 looks away from it; neither sees the obstacle.
constexpr const char* kOneCameraFacingScene = R"js({
  "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
  "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))"}],
  "obstacles": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((7 0))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-6 -6)", "angle": 225, "maxVelocity": 2, "maxAngularVelocity": 1},
              {"pos": "POINT(6 6)", "angle": 225, "maxVelocity": 2, "maxAngularVelocity": 1}]})js";

TEST(Episode, UnderLimitedKnowledgeAKnownViewHoldsWhatTheCameraSawAndItsTeamAsLastHeard) {
  const auto scene =
      std::make_shared<const scene::Scene>(testing::sceneFromJson(kOneCameraFacingScene));
  params::Parameters params = shortRun(1.0);
  params.knowledge.limited = true;
  params.comms.range = 0.0;  // the cameras are 17 m apart: nobody hears anybody
  Episode episode(scene, params);
  const EncodingSizes sizes{2, 1, 1, 4};
  const std::size_t targetAt = EncodingSizes::kGlobal + 2 * EncodingSizes::kPerCamera;
  const std::size_t obstacleAt = targetAt + sizes.perTarget();
  std::vector<float> out(sizes.size());
  // The reference: who sees some of the target in the true world at t = 0.
  std::vector<bool> seesTarget(2, false);
  for (const visibility::Segment& s : episode.scored().seen)
    for (unsigned j = 0; j < 2; ++j)
      seesTarget[j] = seesTarget[j] || s.visibleBy.contains(j);
  ASSERT_FALSE(seesTarget[0]);
  ASSERT_TRUE(seesTarget[1]);
  for (std::size_t j = 0; j < 2; ++j) {
    encodeObservation(episode, sizes, View::known, j, out);
    EXPECT_EQ(out[targetAt], seesTarget[j] ? 1.0f : 0.0f) << "camera " << j;
    EXPECT_EQ(out[obstacleAt], 0.0f) << "nobody has seen the obstacle";
  }
  // Camera 0 drives off; camera 1, never hearing, believes it where the scene starts it.
  const std::vector<scene::CameraCommand> drive{{{1.0, 0.0}, 0.0}, {{0.0, 0.0}, 0.0}};
  for (int k = 0; k < 5; ++k)
    episode.step(drive);
  std::vector<float> team(sizes.size());
  encodeObservation(episode, sizes, View::team, 0, team);
  encodeObservation(episode, sizes, View::known, 1, out);
  EXPECT_GT(cameraSlot(team, 0)[1], -0.6f + 0.04f) << "camera 0 moved";
  EXPECT_FLOAT_EQ(cameraSlot(out, 1)[1], -0.6f) << "as camera 1 believes it: POINT(-6 -6)";
  EXPECT_EQ(cameraSlot(out, 0), cameraSlot(team, 1)) << "camera 1 knows itself";
  EXPECT_EQ(out[targetAt], 1.0f) << "it still knows the target";
  encodeObservation(episode, sizes, View::known, 0, out);
  EXPECT_EQ(cameraSlot(out, 0), cameraSlot(team, 0));
  EXPECT_EQ(out[targetAt], 0.0f) << "camera 0 was never told of the target";
}

// Two targets: a square about (0, 0), 8.5 m from the nearest camera, and one about (3, 3),
// 4.2 m from the camera at (6, 6); that camera senses 100 m, five times the room's side.
constexpr const char* kTwoTargetsScene = R"js({
  "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
  "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))"},
              {"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((3 3))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-6 -6)", "angle": 225, "maxVelocity": 2, "maxAngularVelocity": 1},
              {"pos": "POINT(6 6)", "angle": 0, "maxVelocity": 2, "maxAngularVelocity": 1,
               "sensingRange": 100}]})js";

TEST(Episode, NearestTargetSlotsHoldThePresentTargetsNearestFirstAsManyAsFit) {
  const auto scene = std::make_shared<const scene::Scene>(testing::sceneFromJson(kTwoTargetsScene));
  Episode episode(scene, shortRun(1.0));
  EncodingSizes sizes{2, 1, 0, 4, TargetSlots::nearest};
  std::vector<float> out(sizes.size());
  encodeObservation(episode, sizes, View::team, 0, out);
  const std::size_t first = EncodingSizes::kGlobal + 2 * EncodingSizes::kPerCamera;
  const float* target = out.data() + first;
  EXPECT_EQ(target[0], 1.0f);
  EXPECT_FLOAT_EQ(target[2], 0.3f);  // the square about (3, 3): (3 − 0) / 10
  EXPECT_FLOAT_EQ(target[3], 0.3f);

  sizes.targets = 3;  // room for both, and a padded slot
  out.assign(sizes.size(), -1.0f);
  encodeObservation(episode, sizes, View::team, 0, out);
  target = out.data() + first;
  EXPECT_FLOAT_EQ(target[2], 0.3f);
  EXPECT_FLOAT_EQ(target[sizes.perTarget() + 2], 0.0f);  // then the one about (0, 0)
  EXPECT_EQ(target[sizes.perTarget()], 1.0f);
  EXPECT_EQ(target[2 * sizes.perTarget()], 0.0f);

  // By index, one slot cannot hold the scene's two targets.
  const EncodingSizes byIndex{2, 1, 0, 4};
  std::vector<float> small(byIndex.size());
  EXPECT_THROW(encodeObservation(episode, byIndex, View::team, 0, small), std::invalid_argument);
}

TEST(Episode, EveryFloatLiesWithinTheDeclaredBoundsClampedWherePast) {
  const auto scene = std::make_shared<const scene::Scene>(testing::sceneFromJson(kTwoTargetsScene));
  Episode episode(scene, shortRun(1.0));
  const EncodingSizes sizes{3, 3, 1, 6};
  std::vector<float> out(sizes.size()), low(sizes.size()), high(sizes.size());
  observationBounds(sizes, low, high);
  for (const View view : {View::team, View::own, View::known}) {
    encodeObservation(episode, sizes, view, 1, out);
    for (std::size_t k = 0; k < out.size(); ++k) {
      EXPECT_LE(low[k], out[k]) << k;
      EXPECT_LE(out[k], high[k]) << k;
    }
  }
  encodeObservation(episode, sizes, View::team, 0, out);
  const float* second = out.data() + EncodingSizes::kGlobal + EncodingSizes::kPerCamera;
  EXPECT_EQ(second[8], kLengthBound);  // 100 m over L = 10 m: clamped
  EXPECT_EQ(high[EncodingSizes::kGlobal + EncodingSizes::kPerCamera + 8], kLengthBound);
  EXPECT_EQ(low[EncodingSizes::kGlobal + 1], -kPositionBound);  // a camera's x
  EXPECT_EQ(low[0], 0.0f);                                      // t / duration
  EXPECT_EQ(high[0], 1.0f);
}

TEST(Episode, OwnTermsAreTheTeamsTermsOfACameraAlone) {
  const auto scene = oneTargetScene();
  auto alone = std::make_shared<scene::Scene>(*scene);
  alone->cameras.resize(1);
  const params::Parameters params = shortRun(1.0);
  Episode team(scene, params), single(alone, params);
  const reward::RewardTerms own = ownTerms(team, 0);
  const reward::RewardTerms reference = single.observation().terms;
  EXPECT_DOUBLE_EQ(own.coverage, reference.coverage);
  EXPECT_DOUBLE_EQ(own.utilization, reference.utilization);
  // Alone, it has no other camera to be repelled by; in the team, camera 1 is far (17 m).
  EXPECT_DOUBLE_EQ(own.repulsion, reference.repulsion);
}

TEST(EpisodeStepper, ThreadsGiveWhatOneThreadGivesAndAFailureStopsNothingElse) {
  const auto scene = oneTargetScene();
  const EncodingSizes sizes = EncodingSizes::of(*scene);
  const std::size_t n = 7, m = scene->cameras.size();
  std::vector<float> observations[2];
  for (unsigned threads : {1u, 3u}) {
    EpisodeStepper stepper(threads);
    std::vector<std::unique_ptr<Episode>> owned;
    std::vector<Episode*> episodes;
    for (std::size_t i = 0; i < n; ++i) {
      owned.push_back(std::make_unique<Episode>(scene, shortRun(1.0)));
      episodes.push_back(owned.back().get());
    }
    std::vector<float> out(n * sizes.size());
    std::vector<reward::RewardTerms> terms(n);
    for (int k = 0; k < 10; ++k) {
      std::vector<scene::CameraCommand> commands(n * m);
      for (std::size_t i = 0; i < commands.size(); ++i)
        commands[i] = {{0.1 * static_cast<double>(i % 5), -0.2}, 0.05 * static_cast<double>(k)};
      stepper.step(episodes, commands, m, sizes, out, terms);
    }
    for (const Episode* e : episodes)
      EXPECT_TRUE(e->finished());
    observations[threads == 1 ? 0 : 1] = out;
    // Every episode is finished: each step fails, all are tried, the first failure is raised.
    std::vector<scene::CameraCommand> commands(n * m);
    EXPECT_THROW(stepper.step(episodes, commands, m, sizes, out, terms), std::logic_error);
    EXPECT_THROW(stepper.step(episodes, commands, m - 1, sizes, out, terms), std::invalid_argument);
  }
  EXPECT_EQ(observations[0], observations[1]);
  EXPECT_THROW(EpisodeStepper(0), std::invalid_argument);
  EXPECT_THROW(EpisodeStepper(EpisodeStepper::kMaxThreads + 1), std::invalid_argument);
}

TEST(EpisodeStepper, AnEpisodeGivenTwiceInOneCallIsRefusedBeforeAnyStep) {
  const auto scene = oneTargetScene();
  const EncodingSizes sizes = EncodingSizes::of(*scene);
  const std::size_t m = scene->cameras.size();
  Episode a(scene, shortRun(1.0)), b(scene, shortRun(1.0));
  const std::vector<Episode*> episodes{&a, &b, &a};
  std::vector<scene::CameraCommand> commands(3 * m);
  std::vector<float> out(3 * sizes.size());
  std::vector<reward::RewardTerms> terms(3);
  EpisodeStepper stepper(2);
  try {
    stepper.step(episodes, commands, m, sizes, out, terms);
    FAIL() << "an episode given twice was stepped";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "episodes: 0 and 2 are the same episode, which steps once per call");
  }
  EXPECT_EQ(a.index(), 0);
  EXPECT_EQ(b.index(), 0);
}

TEST(EpisodeStepper, CallsFromSeveralThreadsTakeTurns) {
  const auto scene = oneTargetScene();
  const EncodingSizes sizes = EncodingSizes::of(*scene);
  const std::size_t m = scene->cameras.size();
  EpisodeStepper stepper(2);
  // Each caller steps its own episodes through the one stepper until they finish.
  const auto stepToTheEnd = [&] {
    std::vector<std::unique_ptr<Episode>> owned;
    std::vector<Episode*> episodes;
    for (int i = 0; i < 3; ++i) {
      owned.push_back(std::make_unique<Episode>(scene, shortRun(1.0)));
      episodes.push_back(owned.back().get());
    }
    std::vector<scene::CameraCommand> commands(3 * m);
    std::vector<float> out(3 * sizes.size());
    std::vector<reward::RewardTerms> terms(3);
    while (!episodes.front()->finished())
      stepper.step(episodes, commands, m, sizes, out, terms);
    return episodes.front()->index();
  };
  std::vector<std::thread> callers;
  std::vector<int> reached(4);
  for (std::size_t t = 0; t < reached.size(); ++t)
    callers.emplace_back([&, t] { reached[t] = stepToTheEnd(); });
  for (std::thread& caller : callers)
    caller.join();
  const int steps = Episode(scene, shortRun(1.0)).steps();
  for (const int index : reached)
    EXPECT_EQ(index, steps);
}

TEST(EncodingSizes, CountsThatWouldOverflowTheSizeAreRefused) {
  const auto scene = oneTargetScene();
  Episode episode(scene, shortRun(1.0));
  std::vector<float> out(1);
  const std::size_t huge = std::size_t{1} << 62;
  for (const EncodingSizes& sizes :
       {EncodingSizes{huge, 1, 1, 4}, EncodingSizes{2, huge, 1, 4}, EncodingSizes{2, 1, 1, huge}}) {
    EXPECT_THROW(sizes.check(), std::invalid_argument);
    EXPECT_THROW(encodeObservation(episode, sizes, View::team, 0, out), std::invalid_argument);
  }
}

}  // namespace
}  // namespace camcov::environment
