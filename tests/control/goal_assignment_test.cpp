#include "control/goal_assignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

namespace camcov::control {
namespace {

scene::CameraSpec camera(double halfFov, double speed = 1.0) {
  scene::CameraSpec c;
  c.maxVelocity = speed;
  c.maxAngularVelocity = 1.0;
  c.lens.halfFov = halfFov;
  return c;
}

TEST(AssignGoals, LikeCamerasTakeTheNearerGoalsAndTheTeamNeedsTheLongestTrip) {
  scene::Scene s;
  s.cameras = {camera(0.5), camera(0.5, 2.0)};
  const std::vector<geometry::Pose> at{{0, 0, 0}, {10, 0, 0}};
  const std::vector<geometry::Pose> goals{{9, 0, 0}, {1, 0, 0}};  // each nearer the other
  const GoalAssignment a = assignGoals(s, at, goals);
  EXPECT_EQ(a.goalOf, (std::vector<int>{1, 0}));
  EXPECT_DOUBLE_EQ(a.travelTime, 1.0) << "1 m at 1 m/s, and 1 m at 2 m/s";
}

TEST(AssignGoals, AGoalSampledForAnotherFieldOfViewIsNeverTaken) {
  scene::Scene s;
  s.cameras = {camera(0.3), camera(0.6)};
  const std::vector<geometry::Pose> at{{0, 0, 0}, {10, 0, 0}};
  const std::vector<geometry::Pose> goals{{10, 0, 0}, {0, 0, 3.0}};  // swapped would be free
  const GoalAssignment a = assignGoals(s, at, goals);
  EXPECT_EQ(a.goalOf, (std::vector<int>{0, 1}));
  EXPECT_DOUBLE_EQ(a.travelTime, 10.0) << "10 m at 1 m/s; the turn of 3 rad takes 3 s";
}

// camcov-dec's claims. Two cameras at `at` (camera 0 three seconds from the best spot A) each
// plan the team as it believes it: the other where the scene started it, near the other goal
// B, so each copy of V-B's assignment sends its own camera to A.
struct TwoCopies {
  scene::Scene scene;
  std::vector<geometry::Pose> at;
  std::vector<geometry::Pose> goals{{0, 0, 0}, {0, 10, 0}};  // A, B
  geometry::Pose believedStart{0, 12, 0};                    // 2 s from B, 12 s from A
  static constexpr double kSpot = 2.0;                       // d2

  explicit TwoCopies(double camera1ToA) : at{{-3, 0, 0}, {camera1ToA, 0, 0}} {
    scene.cameras = {camera(0.5), camera(0.5)};
  }
  // The goal camera j's own copy gives camera j, having heard the other's claim `heard`.
  int goalOfIn(std::size_t j, std::optional<Claim> heard) const {
    std::vector<geometry::Pose> believed = at;
    believed[1 - j] = believedStart;
    std::vector<std::optional<Claim>> claims(2);
    claims[1 - j] = heard;
    return assignGoals(scene, believed, goals, heard ? claims : std::vector<std::optional<Claim>>{},
                       kSpot)
        .goalOf[j];
  }
  // Camera j's claim on A, as the other hears it: its travel time from where it is, |x| m at
  // 1 m/s along the x axis to A at the origin, facing the same way.
  Claim claimOnA(std::size_t j) const { return {goals[0], std::abs(at[j].x)}; }
};

TEST(AssignGoalsWithClaims, OfTwoCamerasThatBothChoseASpotTheBetterBidKeepsIt) {
  const TwoCopies copies(4.0);  // camera 1 four seconds from A, camera 0 three
  ASSERT_EQ(copies.goalOfIn(0, std::nullopt), 0) << "without claims both choose A";
  ASSERT_EQ(copies.goalOfIn(1, std::nullopt), 0);
  EXPECT_EQ(copies.goalOfIn(0, copies.claimOnA(1)), 0) << "3 s beats the claim of 4 s: it keeps A";
  EXPECT_EQ(copies.goalOfIn(1, copies.claimOnA(0)), 1) << "outbid: it takes its next best, B";
}

TEST(AssignGoalsWithClaims, OnEqualBidsTheLowerIndexKeepsTheSpot) {
  const TwoCopies copies(3.0);  // both three seconds from A
  ASSERT_EQ(copies.goalOfIn(1, std::nullopt), 0);
  EXPECT_EQ(copies.goalOfIn(0, copies.claimOnA(1)), 0);
  EXPECT_EQ(copies.goalOfIn(1, copies.claimOnA(0)), 1);
  EXPECT_TRUE(outbids(3.0, 0, {copies.goals[0], 3.0}, 1));
  EXPECT_FALSE(outbids(3.0, 1, {copies.goals[0], 3.0}, 0));
}

TEST(AssignGoalsWithClaims, AClaimOnAnotherSpotChangesNothing) {
  // A claim d2 or more from every goal is on no spot the copy could give away.
  const TwoCopies copies(4.0);
  const Claim elsewhere{{0, -TwoCopies::kSpot, 0}, 0.0};
  EXPECT_EQ(copies.goalOfIn(1, elsewhere), 0);
}

}  // namespace
}  // namespace camcov::control
