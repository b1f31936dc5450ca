// What our method learns from the instants it has seen (control/motion_watch.h): whether
// anything moves, and the worlds forecast by carrying on the last step's motion.
#include "control/motion_watch.h"

#include <gtest/gtest.h>

#include "support/small_worlds.h"

namespace camcov::control {
namespace {

const geometry::Box kRoom{{-20, -20}, {20, 20}};

kinematics::World squareWorld() {
  return testing::world(testing::box(-20, -20, 20, 20), {testing::box(0, 0, 1, 1)});
}

void shift(geometry::Ring& ring, double dx, double dy) {
  for (auto& p : ring)
    p = p + geometry::Vec2{dx, dy};
}

TEST(MotionWatch, SaysNothingAtFirstThenWhetherAnythingMovedCameOrWent) {
  MotionWatch watch;
  kinematics::World w = squareWorld();
  EXPECT_FALSE(watch.see(w).has_value());
  EXPECT_EQ(watch.see(w), std::optional<bool>(false));
  w.targets[0][0].x += 1e-9;
  EXPECT_EQ(watch.see(w), std::optional<bool>(true));
  EXPECT_EQ(watch.see(w), std::optional<bool>(false));
  w.obstacles.push_back(testing::box(5, 5, 6, 6));
  EXPECT_EQ(watch.see(w), std::optional<bool>(true));
}

TEST(MotionWatch, ForecastsNothingMovingUntilItHasSeenTwoInstants) {
  MotionWatch watch;
  kinematics::World w = squareWorld();
  watch.see(w);
  const Forecast forecast = watch.forecast(kRoom);
  EXPECT_FALSE(forecast.moves());
  EXPECT_EQ(forecast.at(5.0).targets, w.targets);
  EXPECT_DOUBLE_EQ(forecast.at(5.0).time, w.time + 5.0);
}

TEST(MotionWatch, ForecastCarriesTheLastStepOnAndStopsAtTheRoomsBox) {
  MotionWatch watch;
  kinematics::World w = squareWorld();
  w.obstacles.push_back(testing::box(-3, -3, -2, -2));
  watch.see(w);
  w.time = 0.1;
  shift(w.targets[0], 0.1, 0.05);  // (1, 0.5) m/s
  watch.see(w);
  const Forecast forecast = watch.forecast(kRoom);
  EXPECT_TRUE(forecast.moves());
  const kinematics::World in2 = forecast.at(2.0);
  EXPECT_DOUBLE_EQ(in2.time, 2.1);
  EXPECT_NEAR(in2.targets[0][0].x, w.targets[0][0].x + 2.0, 1e-12);
  EXPECT_NEAR(in2.targets[0][0].y, w.targets[0][0].y + 1.0, 1e-12);
  EXPECT_EQ(in2.obstacles, w.obstacles) << "the obstacle stood still";
  // After 100 s it would be 100 m east and 50 m north: each coordinate stops at the box.
  const geometry::Box far = geometry::boundingBox(forecast.at(100.0).targets[0]);
  EXPECT_NEAR(far.max.x, 20.0, 1e-12);
  EXPECT_NEAR(far.max.y, 20.0, 1e-12);
  EXPECT_NEAR(far.max.x - far.min.x, 1.0, 1e-12) << "moved, not squeezed";
}

TEST(MotionWatch, ForecastFollowsEachObjectByItsSceneIdAndLetsNewcomersStand) {
  // Targets 0, 1, 2 seen, then 1 is gone and 3 has come; 2 moved east by 0.2 m in 0.1 s.
  MotionWatch watch;
  kinematics::World w = squareWorld();
  w.targets = {testing::box(0, 0, 1, 1), testing::box(3, 0, 4, 1), testing::box(6, 0, 7, 1)};
  w.targetIds = {0, 1, 2};
  watch.see(w);
  w.time = 0.1;
  w.targets = {testing::box(0, 0, 1, 1), testing::box(6.2, 0, 7.2, 1), testing::box(9, 0, 10, 1)};
  w.targetIds = {0, 2, 3};
  watch.see(w);
  const kinematics::World in1 = watch.forecast(kRoom).at(1.0);
  EXPECT_EQ(in1.targets[0], w.targets[0]);
  EXPECT_NEAR(geometry::boundingBox(in1.targets[1]).min.x, 8.2, 1e-9) << "2 m/s, by id";
  EXPECT_EQ(in1.targets[2], w.targets[2]) << "just came: no motion seen yet";
  EXPECT_EQ(in1.targetIds, w.targetIds);
}

TEST(MotionWatch, ATurnInPlaceForecastsNoMotion) {
  MotionWatch watch;
  kinematics::World w = squareWorld();
  w.targets = {testing::box(-1, -1, 1, 1)};
  watch.see(w);
  w.time = 0.1;
  geometry::transformRing(w.targets[0], 0.1, {0.0, 0.0});  // turned about its centre
  EXPECT_EQ(watch.see(w), std::optional<bool>(true)) << "it moved";
  EXPECT_FALSE(watch.forecast(kRoom).moves()) << "but its box stayed centred where it was";
}

}  // namespace
}  // namespace camcov::control
