#include "planners/plan_executor.h"

#include <gtest/gtest.h>

#include "support/small_worlds.h"

namespace camcov::planners {
namespace {

constexpr double kDt = 0.1;

// Steps a single camera with the executor's commands, saturated to v_max like the simulator.
struct Runner {
  PlanExecutor executor{params::PotentialParams{}, 2.0};
  geometry::Pose pose;
  double t = 0.0;

  void step(const kinematics::World& w, double vmax, double wmax) {
    scene::CameraCommand u = executor.step(pose, w, {}, vmax, kDt, t);
    const double speed = geometry::norm(u.velocity);
    if (speed > vmax) u.velocity = u.velocity * (vmax / speed);
    u.angularVelocity = std::clamp(u.angularVelocity, -wmax, wmax);
    pose = {pose.x + u.velocity.x * kDt, pose.y + u.velocity.y * kDt,
            geometry::wrapAngle(pose.yaw + u.angularVelocity * kDt)};
    t += kDt;
  }
};

kinematics::World emptyRoom() {
  kinematics::World w;
  w.boundary = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};
  return w;
}

TEST(PlanExecutor, FollowsAPathAtMaximumSpeedAndCompletes) {
  Runner r;
  r.pose = {0, 0, 0};
  r.executor.start({{0, 0, 0}, {4, 0, 0}, {4, 4, 0.5}}, 0.0);
  const kinematics::World w = emptyRoom();
  int steps = 0;
  while (r.executor.executing() && steps < 200) {
    r.step(w, 2.0, 1.0);
    ++steps;
  }
  EXPECT_EQ(r.executor.status(), PlanExecutor::Status::Completed);
  // 8 m at 2 m/s: 40 steps, and one more to notice the arrival.
  EXPECT_LE(steps, 42);
  EXPECT_NEAR(r.pose.x, 4, PlanExecutor::kArrivalDistance);
  EXPECT_NEAR(r.pose.y, 4, PlanExecutor::kArrivalDistance);
  EXPECT_NEAR(r.pose.yaw, 0.5, PlanExecutor::kArrivalYaw);
}

TEST(PlanExecutor, IntermediateGoalIsTheFarthestPathPointInReach) {
  PlanExecutor executor(params::PotentialParams{}, 2.0);
  executor.start({{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.1, 0}, {5, 0.1, 0}}, 0.0);
  // Reach 0.2 m from the start: past the short zig-zag, onto the long last leg.
  executor.step({0, 0, 0}, emptyRoom(), {}, 2.0, kDt, 0.0);
  const geometry::Vec2 g = executor.intermediateGoal().position();
  EXPECT_NEAR(geometry::norm(g), 0.2, 1e-12);
  EXPECT_NEAR(g.y, 0.1, 1e-12);
}

TEST(PlanExecutor, AbortsAfterT3WithoutProgress) {
  // A wall right across the path: the potentials push back as hard as the goal pulls.
  kinematics::World w = emptyRoom();
  w.obstacles.push_back({{1.0, -5}, {1.2, -5}, {1.2, 5}, {1.0, 5}});
  params::PotentialParams potential;  // T3 = 2 s
  Runner r;
  r.executor = PlanExecutor(potential, 2.0);
  r.pose = {0, 0, 0};
  r.executor.start({{0, 0, 0}, {3, 0, 0}}, 0.0);
  double abortedAt = -1;
  for (int i = 0; i < 100 && abortedAt < 0; ++i) {
    r.step(w, 1.0, 1.0);
    if (r.executor.status() == PlanExecutor::Status::Aborted) abortedAt = r.t;
  }
  ASSERT_GT(abortedAt, 0) << "never aborted";
  EXPECT_LT(r.pose.x, 1.0) << "did not pass through the wall";
  // Progress stops somewhere before the wall; the abort follows T3 later.
  EXPECT_GE(abortedAt, potential.T3);
  EXPECT_LE(abortedAt, potential.T3 + 3.0);
}

TEST(RepulsiveDirection, PointsTowardsCloseObjectsOnly) {
  kinematics::World w = emptyRoom();
  w.obstacles.push_back({{1, -1}, {3, -1}, {3, 1}, {1, 1}});
  const geometry::Vec2 f = repulsiveDirection({0, 0}, w, {}, 2.0);
  EXPECT_NEAR(f.x, 1.0, 1e-12);  // 1 m away: invdist = 1, towards +x
  EXPECT_NEAR(f.y, 0.0, 1e-12);
  EXPECT_EQ(repulsiveDirection({-5, 0}, w, {}, 2.0), (geometry::Vec2{0, 0}));
  const geometry::Pose other{0, 0.5, 0};
  const geometry::Vec2 g = repulsiveDirection({-5, 0}, w, std::span(&other, 0), 2.0);
  EXPECT_EQ(g, (geometry::Vec2{0, 0}));
}

}  // namespace
}  // namespace camcov::planners
