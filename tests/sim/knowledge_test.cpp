// What each camera knows under limited knowledge, and what the cameras tell each other:
// sim/knowledge.h, sim/communication.h, sim/team_knowledge.h.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "reward/reward_model.h"
#include "sim/communication.h"
#include "sim/knowledge.h"
#include "sim/team_knowledge.h"
#include "support/small_worlds.h"

namespace camcov::sim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The reference for what the team knows: of each object, the entry seen last among the
// cameras', gathered afresh.
Knowledge unionOf(std::span<const Knowledge> team) {
  Knowledge all;
  for (const Knowledge& camera : team)
    all.hear(camera.objects());
  return all;
}

// A 1 m square target at the origin and a 2 x 1 m obstacle at (6, 0). Camera 0 at (-5, 0)
// faces the target along +x; the target hides the obstacle from it (from (-5, 0) the target
// spans ±6.3°, the obstacle's near side ±2.9°). Camera 1 at (8, 10) faces down onto the
// obstacle's top; the target, 35° or more off its axis, is outside its 30° half field of view.
const char* kTwoLookers = R"js({
  "boundary": "POLYGON((-20 -20,20 -20,20 20,-20 20))",
  "targets": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((0 0))"}],
  "obstacles": [{"shape": "POLYGON((-1 -0.5,1 -0.5,1 0.5,-1 0.5))", "path": "POLYGON((6 0))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-5 0)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(8 10)", "angle": -90, "maxVelocity": 1, "maxAngularVelocity": 1}]})js";

const scene::Scene& twoLookers() {
  static const scene::Scene s = testing::sceneFromJson(kTwoLookers);
  return s;
}

const std::vector<geometry::Pose> kLooking = {{-5, 0, 0}, {8, 10, -kPi / 2}};

kinematics::World worldAt(double time, geometry::Vec2 targetAt) {
  kinematics::World w = testing::world(
      testing::box(-20, -20, 20, 20),
      {testing::box(targetAt.x - 0.5, targetAt.y - 0.5, targetAt.x + 0.5, targetAt.y + 0.5)},
      {testing::box(5, -0.5, 7, 0.5)});
  w.time = time;
  w.targetIds = {0};
  w.obstacleIds = {0};
  return w;
}

params::Parameters limited(double range = kInf) {
  params::Parameters p;
  p.knowledge.limited = true;
  p.comms.range = range;
  return p;
}

KnownObject entry(ObjectKind kind, std::uint32_t id, double seenAt) {
  KnownObject o;
  o.kind = kind;
  o.id = id;
  o.seenAt = seenAt;
  o.shape = testing::box(id, 0, id + 1, 1);
  return o;
}

TEST(Knowledge, ACameraThatNeverSeesATargetDoesNotKnowIt) {
  TeamKnowledge team(twoLookers(), limited(0.0), 1);  // nobody hears anybody
  for (int k = 0; k < 5; ++k)
    team.update(worldAt(0.1 * k, {0, 0}), kLooking);
  const Knowledge& looker = team.cameras()[0];
  const Knowledge& other = team.cameras()[1];
  EXPECT_NE(looker.find(ObjectKind::target, 0), nullptr);
  EXPECT_EQ(looker.find(ObjectKind::obstacle, 0), nullptr);  // hidden behind the target
  EXPECT_EQ(other.find(ObjectKind::target, 0), nullptr);
  EXPECT_NE(other.find(ObjectKind::obstacle, 0), nullptr);
  // The team as a whole knows both.
  EXPECT_EQ(team.known().targets.size(), 1U);
  EXPECT_EQ(team.known().obstacles.size(), 1U);
}

TEST(Knowledge, ATargetSeenThenHiddenIsRememberedWhereAndWhenLastSeen) {
  TeamKnowledge team(twoLookers(), limited(0.0), 1);
  team.update(worldAt(0.0, {0, 0}), kLooking);
  team.update(worldAt(0.1, {0, 0.3}), kLooking);  // moved 0.3 m up in 0.1 s
  // Camera 0 turns away; the target moves on unseen.
  const std::vector<geometry::Pose> away = {{-5, 0, kPi}, kLooking[1]};
  team.update(worldAt(0.2, {0, 0.6}), away);
  team.update(worldAt(0.3, {0, 0.9}), away);
  const KnownObject* known = team.cameras()[0].find(ObjectKind::target, 0);
  ASSERT_NE(known, nullptr);
  EXPECT_DOUBLE_EQ(known->seenAt, 0.1);
  EXPECT_EQ(known->shape, testing::box(-0.5, -0.2, 0.5, 0.8));
  EXPECT_NEAR(known->velocity.x, 0.0, 1e-12);
  EXPECT_NEAR(known->velocity.y, 3.0, 1e-9);
  // What the methods read: the target where it was last seen, at the present time.
  const kinematics::World& known_world = team.known();
  EXPECT_DOUBLE_EQ(known_world.time, 0.3);
  ASSERT_EQ(known_world.targets.size(), 1U);
  EXPECT_EQ(known_world.targets[0], testing::box(-0.5, -0.2, 0.5, 0.8));
  EXPECT_EQ(known_world.targetIds, std::vector<std::uint32_t>{0});
}

TEST(Knowledge, TheTeamKnowsTheWorldWhileEveryObjectIsWhereItIsKnown) {
  TeamKnowledge team(twoLookers(), limited(0.0), 1);
  team.update(worldAt(0.0, {0, 0}), kLooking);
  EXPECT_TRUE(team.knowsTheWorld());  // camera 0 sees the target, camera 1 the obstacle
  // Camera 0 turns away; the target moves on unseen, then comes back to where it was seen.
  const std::vector<geometry::Pose> away = {{-5, 0, kPi}, kLooking[1]};
  team.update(worldAt(0.1, {0, 0.3}), away);
  EXPECT_FALSE(team.knowsTheWorld());
  team.update(worldAt(0.2, {0, 0}), away);
  EXPECT_TRUE(team.knowsTheWorld());  // unseen, but known as it is
  team.update(worldAt(0.3, {0, 0.3}), away);
  EXPECT_FALSE(team.knowsTheWorld());
  team.update(worldAt(0.4, {0, 0.3}), kLooking);
  EXPECT_TRUE(team.knowsTheWorld());
}

TEST(Knowledge, EveryCameraKnowsTheUnionWhenEveryoneHearsEveryoneAtOnce) {
  // Range inf, no loss, no latency, a message every step.
  TeamKnowledge team(twoLookers(), limited(), 1);
  for (int k = 0; k < 3; ++k) {
    team.update(worldAt(0.1 * k, {0, 0.1 * k}), kLooking);
    const Knowledge all = unionOf(team.cameras());
    for (const Knowledge& camera : team.cameras()) {
      ASSERT_EQ(camera.objects().size(), all.objects().size());
      for (std::size_t i = 0; i < all.objects().size(); ++i) {
        EXPECT_EQ(camera.objects()[i].id, all.objects()[i].id);
        EXPECT_EQ(camera.objects()[i].kind, all.objects()[i].kind);
        EXPECT_EQ(camera.objects()[i].seenAt, all.objects()[i].seenAt);
        EXPECT_EQ(camera.objects()[i].shape, all.objects()[i].shape);
      }
    }
    EXPECT_EQ(all.objects().size(), 2U);  // the target from camera 0, the obstacle from 1
  }
}

TEST(Knowledge, TheKnownWorldIsTheUnionOfWhatTheCamerasKnow) {
  // Late and lost messages, and camera 0 looking away for a while: the cameras' knowledge
  // differs, and the team's is of each object the entry seen last among theirs.
  params::Parameters p = limited();
  p.comms.latency = 0.2;
  p.comms.loss = 0.3;
  TeamKnowledge team(twoLookers(), p, 1);
  const std::vector<geometry::Pose> away = {{-5, 0, kPi}, kLooking[1]};
  for (int k = 0; k < 12; ++k) {
    const kinematics::World now = worldAt(0.1 * k, {0, 0.1 * k});
    team.update(now, k >= 4 && k < 8 ? away : kLooking);
    kinematics::World expected;
    knownWorld(unionOf(team.cameras()), now, false, expected);
    const kinematics::World& known = team.known();
    EXPECT_EQ(known.time, expected.time);
    EXPECT_EQ(known.targets, expected.targets);
    EXPECT_EQ(known.targetIds, expected.targetIds);
    EXPECT_EQ(known.obstacles, expected.obstacles);
    EXPECT_EQ(known.obstacleIds, expected.obstacleIds);
  }
}

TEST(Knowledge, WithoutObstaclesTheSimulatorsSweepTellsWhatEachCameraSees) {
  // The same instants, once swept by the team itself and once read from S as the simulator
  // measured it: every camera comes to know the same.
  TeamKnowledge sweeping(twoLookers(), limited(0.0), 1);
  TeamKnowledge reading(twoLookers(), limited(0.0), 1);
  reward::RewardModel simulator(params::RewardParams{}, scene::lenses(twoLookers()));
  for (int k = 0; k < 4; ++k) {
    kinematics::World now = worldAt(0.1 * k, {0, 0.1 * k});
    now.obstacles.clear();
    now.obstacleIds.clear();
    simulator.setWorld(now);
    simulator.evaluate(kLooking);
    sweeping.update(now, kLooking);
    reading.update(now, kLooking, {}, simulator.segments());
    for (std::size_t j = 0; j < 2; ++j) {
      const auto swept = sweeping.cameras()[j].objects();
      const auto read = reading.cameras()[j].objects();
      ASSERT_EQ(read.size(), swept.size());
      for (std::size_t i = 0; i < swept.size(); ++i) {
        EXPECT_EQ(read[i].id, swept[i].id);
        EXPECT_EQ(read[i].seenAt, swept[i].seenAt);
        EXPECT_EQ(read[i].shape, swept[i].shape);
      }
    }
  }
  EXPECT_NE(reading.cameras()[0].find(ObjectKind::target, 0), nullptr);
  EXPECT_EQ(reading.cameras()[1].find(ObjectKind::target, 0), nullptr);
}

TEST(Knowledge, AHeardEntryReplacesOnlyAnOlderOne) {
  Knowledge k;
  k.see(entry(ObjectKind::target, 3, 2.0));
  KnownObject older = entry(ObjectKind::target, 3, 1.0);
  older.shape = testing::box(9, 9, 10, 10);
  KnownObject newer = entry(ObjectKind::target, 3, 3.0);
  newer.shape = testing::box(7, 7, 8, 8);
  k.hear(std::vector{older});
  EXPECT_EQ(k.find(ObjectKind::target, 3)->seenAt, 2.0);
  k.hear(std::vector{newer});
  EXPECT_EQ(k.find(ObjectKind::target, 3)->shape, testing::box(7, 7, 8, 8));
  // Targets and obstacles are told apart by kind, not only by id.
  k.hear(std::vector{entry(ObjectKind::obstacle, 3, 0.5)});
  EXPECT_EQ(k.objects().size(), 2U);
  EXPECT_EQ(k.find(ObjectKind::target, 3)->seenAt, 3.0);
}

// Two cameras `apart` metres apart, each knowing one object of its own.
struct Pair {
  std::vector<geometry::Pose> poses;
  std::vector<Knowledge> knowledge;
  explicit Pair(double apart) : poses{{0, 0, 0}, {apart, 0, 0}}, knowledge(2) {
    knowledge[0].see(entry(ObjectKind::target, 0, 0.0));
    knowledge[1].see(entry(ObjectKind::target, 1, 0.0));
  }
  // Sends and delivers at instant k of steps of 0.1 s.
  std::span<const Hearing> step(Communication& c, int k) {
    c.send(0.1 * k, poses, knowledge);
    return c.deliver(0.1 * k, knowledge);
  }
};

params::CommsParams comms(double range, double latency = 0.0, double loss = 0.0) {
  params::CommsParams p;
  p.range = range;
  p.latency = latency;
  p.loss = loss;
  return p;
}

TEST(Communication, AMessageTellsWhereItsSenderWasAndWhereItWasHeading) {
  Pair pair(5.0);
  Communication c(comms(10.0, 0.2), 0.1, 2, 1);
  const std::vector<std::optional<geometry::Pose>> goals{geometry::Pose{3, 4, 1}, std::nullopt};
  c.send(0.0, pair.poses, pair.knowledge, goals);
  EXPECT_TRUE(c.deliver(0.1, pair.knowledge).empty());  // on its way
  EXPECT_TRUE(pair.knowledge[1].teammates().empty());
  pair.poses[0] = {1, 0, 0};
  c.send(0.1, pair.poses, pair.knowledge, goals);  // not heard before t = 0.3
  EXPECT_EQ(c.deliver(0.2, pair.knowledge).size(), 2U);
  // Camera 1 heard camera 0 as it was at t = 0, heading for its goal; camera 0 heard camera 1,
  // which had none. Neither knows of itself.
  const auto heard = pair.knowledge[1].teammates();
  ASSERT_EQ(heard.size(), 1U);
  ASSERT_TRUE(heard[0].has_value());
  EXPECT_EQ(heard[0]->sentAt, 0.0);
  EXPECT_EQ(heard[0]->pose, (geometry::Pose{0, 0, 0}));
  EXPECT_EQ(heard[0]->goal, (geometry::Pose{3, 4, 1}));
  const auto back = pair.knowledge[0].teammates();
  ASSERT_EQ(back.size(), 2U);
  EXPECT_FALSE(back[0].has_value());
  EXPECT_EQ(back[1]->pose, (geometry::Pose{5, 0, 0}));
  EXPECT_FALSE(back[1]->goal.has_value());
  // The later message replaces the earlier; an older one heard late would not.
  c.deliver(0.3, pair.knowledge);
  EXPECT_EQ(pair.knowledge[1].teammates()[0]->pose, (geometry::Pose{1, 0, 0}));
  pair.knowledge[1].hearTeammate(0, {0.05, {9, 9, 0}, std::nullopt});
  EXPECT_EQ(pair.knowledge[1].teammates()[0]->sentAt, 0.1);
}

TEST(Communication, APoseIsPassedOnToCamerasOutOfItsSendersRange) {
  // Cameras at 0, 8 and 16 m with a range of 10 m: 0 and 2 hear only 1, which passes on what
  // it heard of each, so both learn where the other was one step before.
  std::vector<geometry::Pose> poses{{0, 0, 0}, {8, 0, 0}, {16, 0, 0}};
  std::vector<Knowledge> knowledge(3);
  Communication c(comms(10.0), 0.1, 3, 1);
  c.send(0.0, poses, knowledge);
  c.deliver(0.0, knowledge);
  EXPECT_EQ(knowledge[0].teammates().size(), 2U);  // camera 1 only: nothing passed on yet
  poses[0] = {0, 1, 0};
  c.send(0.1, poses, knowledge);
  c.deliver(0.1, knowledge);
  ASSERT_EQ(knowledge[0].teammates().size(), 3U);
  ASSERT_TRUE(knowledge[0].teammates()[2].has_value());
  EXPECT_EQ(knowledge[0].teammates()[2]->sentAt, 0.0);
  EXPECT_EQ(knowledge[0].teammates()[2]->pose, (geometry::Pose{16, 0, 0}));
  EXPECT_EQ(knowledge[2].teammates()[0]->pose, (geometry::Pose{0, 0, 0}));
  EXPECT_EQ(knowledge[1].teammates()[0]->pose, (geometry::Pose{0, 1, 0}));  // heard directly
  // Nobody is told of itself.
  EXPECT_FALSE(knowledge[0].teammates()[0].has_value());
}

TEST(Communication, AReceiverOutOfRangeHearsNothing) {
  Pair far(10.0);
  Communication c(comms(9.99), 0.1, 2, 1);
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(far.step(c, k).empty());
  EXPECT_EQ(far.knowledge[0].find(ObjectKind::target, 1), nullptr);
  EXPECT_EQ(c.counts().sent, 0);
  // At exactly the range it hears.
  Pair near(10.0);
  Communication d(comms(10.0), 0.1, 2, 1);
  EXPECT_EQ(near.step(d, 0).size(), 2U);
  EXPECT_NE(near.knowledge[0].find(ObjectKind::target, 1), nullptr);
}

TEST(Communication, LatencyDelaysHearingToTheFirstStepAfterIt) {
  Pair pair(1.0);
  params::CommsParams once = comms(kInf, 0.25);
  once.period = 100.0;  // one message each, at t = 0
  Communication single(once, 0.1, 2, 1);
  std::vector<int> heardAt;
  for (int k = 0; k < 6; ++k) {
    if (!pair.step(single, k).empty()) heardAt.push_back(k);
  }
  EXPECT_EQ(heardAt, std::vector<int>{3});  // sent at 0, due at 0.25: heard at 0.3
  EXPECT_EQ(single.counts().sent, 2);
  EXPECT_EQ(single.counts().delivered, 2);
}

TEST(Communication, APeriodSpacesACameraMessages) {
  Pair pair(1.0);
  params::CommsParams p = comms(kInf);
  p.period = 0.5;
  Communication c(p, 0.1, 2, 1);
  for (int k = 0; k < 10; ++k)  // t = 0 ... 0.9: messages at 0 and 0.5
    pair.step(c, k);
  EXPECT_EQ(c.counts().sent, 4);
}

TEST(Communication, LossIsDeterministicForASeedAndNearItsProbability) {
  const double loss = 0.3;
  auto heardPattern = [&](std::uint64_t seed, MessageCounts& counts) {
    Pair pair(1.0);
    Communication c(comms(kInf, 0.0, loss), 0.1, 2, seed);
    std::vector<int> pattern;
    for (int k = 0; k < 10000; ++k)
      pattern.push_back(static_cast<int>(pair.step(c, k).size()));
    counts = c.counts();
    return pattern;
  };
  MessageCounts a, b, other;
  const std::vector<int> first = heardPattern(7, a);
  EXPECT_EQ(heardPattern(7, b), first);
  EXPECT_NE(heardPattern(8, other), first);
  EXPECT_EQ(a.sent, 20000);
  EXPECT_EQ(a.sent, a.delivered + a.lost);
  // Binomial: standard deviation sqrt(0.3 · 0.7 / 20000) = 0.0032; within five of them.
  EXPECT_NEAR(static_cast<double>(a.lost) / a.sent, loss, 0.016);
}

// Camera 0 sends what it knows to camera 1, 1 m away, once, in messages of at most `sizeLimit`
// entries.
void sendOnce(std::vector<Knowledge>& knowledge, int sizeLimit) {
  params::CommsParams p = comms(kInf);
  p.sizeLimit = sizeLimit;
  Communication c(p, 0.1, 2, 1);
  const std::vector<geometry::Pose> poses = {{0, 0, 0}, {1, 0, 0}};
  c.send(0.0, poses, knowledge);
  c.deliver(0.0, knowledge);
}

TEST(Communication, AMessageCarriesAtMostSizeLimitEntriesTheNewestFirst) {
  std::vector<Knowledge> knowledge(2);
  for (std::uint32_t id = 0; id < 5; ++id)  // seen at 0.4, 0.3, 0.2, 0.1, 0.0
    knowledge[0].see(entry(ObjectKind::target, id, 0.1 * (4 - id)));
  knowledge[0].see(entry(ObjectKind::obstacle, 0, 0.35));
  sendOnce(knowledge, 3);
  const auto& heard = knowledge[1].objects();
  ASSERT_EQ(heard.size(), 3U);
  EXPECT_NE(knowledge[1].find(ObjectKind::target, 0), nullptr);
  EXPECT_NE(knowledge[1].find(ObjectKind::obstacle, 0), nullptr);
  EXPECT_NE(knowledge[1].find(ObjectKind::target, 1), nullptr);
}

TEST(Communication, EntriesSeenAtOnceFillASizeLimitInTheirKnownOrder) {
  // Five targets all seen at 0.2 and an obstacle at 0.3: the obstacle, then the first two
  // targets by id.
  std::vector<Knowledge> knowledge(2);
  for (std::uint32_t id : {4U, 0U, 3U, 1U, 2U})
    knowledge[0].see(entry(ObjectKind::target, id, 0.2));
  knowledge[0].see(entry(ObjectKind::obstacle, 7, 0.3));
  sendOnce(knowledge, 3);
  std::vector<std::uint32_t> targets;
  for (const KnownObject& o : knowledge[1].objects())
    if (o.kind == ObjectKind::target) targets.push_back(o.id);
  EXPECT_EQ(targets, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_NE(knowledge[1].find(ObjectKind::obstacle, 7), nullptr);
}

}  // namespace
}  // namespace camcov::sim
