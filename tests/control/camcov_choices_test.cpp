// The pieces of our method (control/camcov_choices.h), each against numbers worked
// out by hand on a unit square target.
#include "control/camcov_choices.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/same_bits.h"
#include "support/random_worlds.h"
#include "support/small_worlds.h"

namespace camcov::control {
namespace {

using geometry::Pose;

constexpr double kTheta = std::numbers::pi / 6;

scene::CameraSpec withLimits(double maxVelocity, double maxAngularVelocity) {
  scene::CameraSpec c;
  c.maxVelocity = maxVelocity;
  c.maxAngularVelocity = maxAngularVelocity;
  return c;
}

kinematics::World squareWorld() {
  return testing::world(testing::box(-20, -20, 20, 20), {testing::box(0, 0, 1, 1)});
}

TEST(PathTravelTime, IsTheLongerOfRunningTheLengthAndTurning) {
  const std::vector<Pose> path{{0, 0, 0}, {3, 0, 0}, {3, 4, 0.5}};
  EXPECT_DOUBLE_EQ(pathTravelTime(path, withLimits(1.0, 1.0)), 7.0);   // 7 m at 1 m/s
  EXPECT_DOUBLE_EQ(pathTravelTime(path, withLimits(10.0, 0.1)), 5.0);  // 0.5 rad at 0.1 rad/s
  EXPECT_DOUBLE_EQ(pathTravelTime({{{1, 1, 0}}}, withLimits(1.0, 1.0)), 0.0);
}

TEST(AverageCoverageAhead, HoldsTheGoalsCoverageWhenNothingMoves) {
  reward::RewardModel model(params::RewardParams{}, kTheta);
  model.setWorld(squareWorld());
  // Facing the bottom side from 5 m: a quarter of the perimeter.
  const std::vector<std::vector<Pose>> paths{{{0.5, -5, std::numbers::pi / 2}}};
  const std::vector<double> travel{0.0};
  EXPECT_NEAR(averageCoverageAhead(model, {paths, travel}, 10.0, 4), 0.25, 1e-12);
}

TEST(AverageCoverageAhead, CountsTheTransitByTheTrapezoidRuleThenTheGoalToTheHorizon) {
  reward::RewardModel model(params::RewardParams{}, kTheta);
  model.setWorld(squareWorld());
  // Facing away from the target all the way (coverage 0), then facing it at the goal: with
  // one sample inside a 4 s transit and a 10 s horizon, the trapezoid rule gives the last 2 s
  // of the transit half the goal's coverage: (0.5 · 0.25 · 2 + 0.25 · 6) / 10.
  const std::vector<std::vector<Pose>> paths{
      {{0.5, -9, -std::numbers::pi / 2}, {0.5, -5, std::numbers::pi / 2}}};
  const std::vector<double> travel{4.0};
  const double expected = (0.5 * 0.25 * 2.0 + 0.25 * 6.0) / 10.0;
  // The yaw turns from −90° to 90° along the way: at the midpoint it faces 0° (east), away
  // from the target's x range: nothing seen, as assumed.
  EXPECT_NEAR(averageCoverageAhead(model, {paths, travel}, 10.0, 1), expected, 1e-12);
  // A horizon shorter than the transit counts the transit only, up to the horizon.
  EXPECT_NEAR(averageCoverageAhead(model, {paths, travel}, 2.0, 1), 0.0, 1e-12);
}

// The forecast after seeing the unit square target, then the same moved by (dx, dy) 0.1 s on.
Forecast squareMovedBy(double dx, double dy) {
  MotionWatch watch;
  kinematics::World w = squareWorld();
  watch.see(w);
  w.time = 0.1;
  for (auto& p : w.targets[0])
    p = p + geometry::Vec2{dx, dy};
  watch.see(w);
  return watch.forecast({{-20, -20}, {20, 20}});
}

// A camera that stays where it is, facing north.
double stayingFacingNorth(const Forecast& forecast, double x, double horizon) {
  reward::RewardModel model(params::RewardParams{}, kTheta);
  const std::vector<std::vector<Pose>> paths{{{x, -5, std::numbers::pi / 2}}};
  const std::vector<double> travel{0.0};
  return forecastCoverageAhead(model, forecast, {paths, travel}, horizon);
}

TEST(ForecastCoverageAhead, IsThePresentCoverageWhileThingsMoveAlongTheLineOfSight) {
  // A target going straight away (1 m/s north) from a camera that faces it keeps showing the
  // same side: a quarter of its perimeter.
  EXPECT_NEAR(stayingFacingNorth(squareMovedBy(0.0, 0.1), 0.5, 8.0), 0.25, 1e-12);
}

TEST(ForecastCoverageAhead, CountsOnlyTheInstantsAtWhichTheForecastTargetIsInView) {
  // The target leaves the field of view sideways at 10 m/s (gone within 0.3 s, stopped at the
  // room's edge x = 20, far outside the 30° half-angle): of the nine instants 0, 1, …, 8 s only
  // the first sees it, so the trapezoid rule gives 0.5 · 0.25 / 8.
  ASSERT_EQ(kForecastIntervals, 8);
  EXPECT_NEAR(stayingFacingNorth(squareMovedBy(1.0, 0.0), 1.5, 8.0), 0.5 * 0.25 / 8.0, 1e-12);
}

TEST(LookoutYaw, LooksAtTheTargetWhenThereIsTimeAndKeepsThePlanWhenThereIsNot) {
  reward::RewardModel model(params::RewardParams{}, kTheta);
  model.setWorld(squareWorld());
  // West of the target, planned to face north: turning east shows the target.
  std::vector<Pose> team{{-6, 0.5, std::numbers::pi / 2}};
  const double planned = std::numbers::pi / 2, goal = std::numbers::pi / 2;
  const double seen = lookoutYaw(model, team, 0, planned, goal, 10.0, 1.0, 16);
  EXPECT_NEAR(seen, 0.0, 1e-12) << "east, of 16 directions";
  EXPECT_EQ(team[0], (Pose{-6, 0.5, std::numbers::pi / 2})) << "the team is restored";
  // One second left at 1 rad/s: east and back to north (π) does not fit.
  EXPECT_EQ(lookoutYaw(model, team, 0, planned, goal, 1.0, 1.0, 16), planned);
}

// lookoutYaw as its header states it, every yaw swept: the first of the highest reward among
// the planned yaw and the reachable directions. lookoutYaw skips the yaws its bound rules out;
// it must choose the same.
double everyYawSwept(reward::RewardModel& model, std::vector<Pose> team, std::size_t j,
                     double plannedYaw, double goalYaw, double timeLeft, double turnRate,
                     int directions) {
  const double from = team[j].yaw, reach = turnRate * std::max(0.0, timeLeft);
  double bestYaw = plannedYaw, best = -std::numeric_limits<double>::infinity();
  for (int k = -1; k < directions; ++k) {
    const double yaw =
        k < 0 ? plannedYaw : geometry::wrapAngle(2.0 * std::numbers::pi * k / directions);
    if (k >= 0 &&
        std::abs(geometry::wrapAngle(yaw - from)) + std::abs(geometry::wrapAngle(goalYaw - yaw)) >
            reach)
      continue;
    team[j].yaw = yaw;
    if (const double r = model.reward(team); r > best) {
      best = r;
      bestYaw = yaw;
    }
  }
  return bestYaw;
}

TEST(LookoutYaw, ChoosesAsIfEveryYawWereSwept) {
  int turned = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    testing::SplitMix64 random{seed};
    const kinematics::World w = testing::randomWorld(random);
    // Unlike lenses (camera 1 narrower than camera 0), and a team of one among the sizes.
    reward::RewardModel model(params::RewardParams{}, {kTheta, 0.3, 0.8, 1.0});
    model.setWorld(w);
    for (int trial = 0; trial < 40; ++trial) {
      std::vector<Pose> team(1 + trial % 4);
      for (Pose& p : team)
        p = testing::randomPose(random);
      const std::size_t j = static_cast<std::size_t>(trial / 4) % team.size();
      const double planned = random.uniform(-std::numbers::pi, std::numbers::pi),
                   goal = random.uniform(-std::numbers::pi, std::numbers::pi),
                   timeLeft = random.uniform(-1.0, 8.0);
      const double expected = everyYawSwept(model, team, j, planned, goal, timeLeft, 1.0, 16);
      const double chosen = lookoutYaw(model, team, j, planned, goal, timeLeft, 1.0, 16);
      EXPECT_TRUE(geometry::sameBits(chosen, expected))
          << "seed " << seed << ", trial " << trial << ": chose " << chosen << ", every yaw swept "
          << expected;
      if (!geometry::sameBits(expected, planned)) ++turned;
    }
  }
  EXPECT_GT(turned, 30) << "the directions, not only the planned yaw, are chosen";
}

TEST(LookoutYaw, ATieGoesToTheFirstDirectionEvenWhenALaterOneIsSweptFirst) {
  // From the origin, east and west each show one side of a square, mirror images: the same
  // reward to the bit. West also has a small target behind its square, hidden, which raises
  // west's bound (occlusion is not bounded), so west is swept first; east, direction 0, still
  // wins the tie as in index order.
  reward::RewardModel model(params::RewardParams{}, kTheta);
  model.setWorld(testing::world(testing::box(-20, -20, 20, 20),
                                {testing::box(3, -0.5, 4, 0.5), testing::box(-4, -0.5, -3, 0.5),
                                 testing::box(-8, -0.1, -7.8, 0.1)}));
  std::vector<Pose> team{{0, 0, std::numbers::pi / 2}};
  const double planned = std::numbers::pi / 2;  // north: nothing in view
  std::vector<Pose> east{{0, 0, 0}}, west{{0, 0, std::numbers::pi}}, north{team};
  const double eastReward = model.reward(east);
  ASSERT_EQ(eastReward, model.reward(west)) << "the premise: a tie";
  ASSERT_LT(model.reward(north), eastReward);
  EXPECT_EQ(everyYawSwept(model, team, 0, planned, planned, 10.0, 1.0, 16), 0.0);
  EXPECT_EQ(lookoutYaw(model, team, 0, planned, planned, 10.0, 1.0, 16), 0.0);
}

}  // namespace
}  // namespace camcov::control
