#include "planners/motion_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/ring.h"
#include "planners/state_validity.h"
#include "reward/reward_model.h"
#include "support/random_worlds.h"
#include "support/rings.h"
#include "support/small_worlds.h"
#include "support/splitmix64.h"

namespace camcov::planners {
namespace {

constexpr double kTheta = std::numbers::pi / 6;

params::Parameters smallBudget() {
  params::Parameters p;
  p.planner.milestonesPerSecond = 600;  // 300 milestones for T2 = 0.5 s
  return p;
}

TEST(Roadmap, PathRunsFromStartToGoalThroughValidMotionsAroundTheObstacle) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  Roadmap roadmap(w, smallBudget(), kTheta, 3);
  EXPECT_EQ(roadmap.milestones(), 300u);
  const geometry::Pose start{10, 0, 0}, goal{-10, 0, std::numbers::pi / 2};
  const auto path = roadmap.query(start, goal);
  ASSERT_TRUE(path);
  ASSERT_GE(path->size(), 3u) << "the target and obstacle block the straight line";
  EXPECT_EQ(path->front().position(), start.position());
  EXPECT_EQ(path->back().position(), goal.position());
  StateValidity validity(1.0);
  validity.setWorld(w);
  for (std::size_t i = 1; i < path->size(); ++i) {
    EXPECT_TRUE(validity.isValidMotion((*path)[i - 1].position(), (*path)[i].position())) << i;
  }
}

TEST(Roadmap, AWorldThatIsAPartOfTheRoomIsGivenItsShareOfTheMilestones) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  EXPECT_EQ(Roadmap(w, smallBudget(), kTheta, 3, 0.25).milestones(), 75u);
  // Rounded up: a part, however small, gets a milestone.
  EXPECT_EQ(Roadmap(w, smallBudget(), kTheta, 3, 0.251).milestones(), 76u);
}

TEST(Roadmap, SameSeedSameRoadmapAndPath) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  Roadmap a(w, smallBudget(), kTheta, 5), b(w, smallBudget(), kTheta, 5);
  const geometry::Pose start{10, 5, 0}, goal{-10, -5, 1};
  EXPECT_EQ(a.query(start, goal), b.query(start, goal));
}

// Each pair's cost from its own poses, whatever pairs were asked before (the roadmap keeps what
// it works out about a state's pose, which must never answer for another pose).
TEST(Roadmap, CostIsEquationTenForEachPairAskedInTurn) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  const params::Parameters p = smallBudget();
  Roadmap roadmap(w, p, kTheta, 1);
  reward::RewardModel reward(p.reward, kTheta);
  reward.setWorld(w);
  const geometry::Pose a{0, -4, std::numbers::pi / 2}, b{1, -5, 1.2}, c{-1, -5, 1.4};
  const auto expected = [&](const geometry::Pose& from, const geometry::Pose& to) {
    const double r1 = reward.reward(std::span(&from, 1)), r2 = reward.reward(std::span(&to, 1));
    EXPECT_GT(r1, 0.0);
    EXPECT_GT(r2, 0.0);
    // ½(1/r(a) + 1/r(b)) · (‖Δxy‖ + ½|Δγ|)
    return 0.5 * (1 / r1 + 1 / r2) *
           (geometry::distance(from.position(), to.position()) + 0.5 * std::abs(to.yaw - from.yaw));
  };
  EXPECT_NEAR(roadmap.cost(a, b),
              0.5 * (1 / reward.reward(std::span(&a, 1)) + 1 / reward.reward(std::span(&b, 1))) *
                  (std::sqrt(2.0) + 0.5 * std::abs(1.2 - a.yaw)),
              1e-12);
  for (const auto& [from, to] :
       {std::pair{b, c}, std::pair{c, a}, std::pair{a, c}, std::pair{b, a}}) {
    EXPECT_NEAR(roadmap.cost(from, to), expected(from, to), 1e-12);
  }
}

// Our method's roadmap judges a finely drawn object simplified (camcov.detail), as its rewards
// do, and checks its motions against the object as drawn.
TEST(Roadmap, WithDetailCostsAreOfTheSimplifiedWorldAndMotionsOfTheDrawnOne) {
  kinematics::World w;
  w.boundary = {{-15, -15}, {15, -15}, {15, 15}, {-15, 15}};
  w.targets = {testing::disc({0, 0}, 2.0, 2000)};
  constexpr double kDetail = 0.01;
  const params::Parameters p = smallBudget();
  Roadmap roadmap(w, p, kTheta, 1, 1.0, kDetail);
  reward::RewardModel judged(p.reward, kTheta);
  judged.setDetail(kDetail);
  judged.setWorld(w);
  const geometry::Ring& simple = judged.world().targets[0];
  ASSERT_LT(simple.size(), 100u);

  // eq. (10) between two poses that see the disc, from the simplified world's rewards.
  const geometry::Pose a{0, -6, std::numbers::pi / 2}, b{1, -6.5, 1.4};
  const double ra = judged.reward(std::span(&a, 1)), rb = judged.reward(std::span(&b, 1));
  EXPECT_NEAR(roadmap.cost(a, b),
              0.5 * (1 / ra + 1 / rb) *
                  (geometry::distance(a.position(), b.position()) + 0.5 * std::abs(1.4 - a.yaw)),
              1e-12);

  // A motion along the tangent of the drawn disc at the middle of the longest simplified edge,
  // d1 − 2 mm from the arc there: clear of the chord by d1 and more, too close to the arc.
  std::size_t longest = 0;
  for (std::size_t i = 0; i < simple.size(); ++i) {
    if (geometry::distance(simple[i], simple[(i + 1) % simple.size()]) >
        geometry::distance(simple[longest], simple[(longest + 1) % simple.size()]))
      longest = i;
  }
  const geometry::Vec2 mid =
      geometry::lerp(simple[longest], simple[(longest + 1) % simple.size()], 0.5);
  const geometry::Vec2 out = mid * (1.0 / geometry::norm(mid));
  ASSERT_GT(2.0 - geometry::norm(mid), 0.004) << "the chord lies inside the arc there";
  const double d1 = p.planner.d1;
  const geometry::Vec2 along{-out.y, out.x}, through = out * (2.0 + d1 - 0.002);
  const geometry::Vec2 from = through - along * 3.0, to = through + along * 3.0;
  EXPECT_FALSE(roadmap.motionValid({from.x, from.y, 0}, {to.x, to.y, 0}));
  StateValidity simplified(d1);
  simplified.setWorld(judged.world());
  EXPECT_TRUE(simplified.isValidMotion(from, to)) << "the motion tells the two worlds apart";
}

// The query's A* heuristic against eq. (10) itself: never above the cost of one motion plus the
// bound from its end (consistent, so A* finds the cheapest path), and positive, so it guides.
TEST(Roadmap, CostLowerBoundNeverExceedsAMotionsCostPlusTheBoundFromItsEnd) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  Roadmap roadmap(w, smallBudget(), kTheta, 4);
  testing::SplitMix64 random{7};
  const auto pose = [&] {
    return geometry::Pose{random.uniform(-19, 19), random.uniform(-19, 19),
                          random.uniform(-std::numbers::pi, std::numbers::pi)};
  };
  for (int i = 0; i < 2000; ++i) {
    const geometry::Pose a = pose(), b = pose(), c = pose();
    EXPECT_GT(roadmap.costLowerBound(a, b), 0.0);
    EXPECT_LE(roadmap.costLowerBound(a, b), roadmap.cost(a, b));
    EXPECT_LE(roadmap.costLowerBound(a, c), roadmap.cost(a, b) + roadmap.costLowerBound(b, c));
  }
  // Along a path, ties of the bound included: from a pose to itself it is nothing.
  const geometry::Pose a = pose();
  EXPECT_EQ(roadmap.costLowerBound(a, a), 0.0);
}

// Two targets drawn on one another share every edge, and each counts a seen edge's angle, so a
// camera's utilization passes 1 and its reward the ceiling λ1 + λ2: eq. (10) takes it as the
// ceiling, which keeps the query's bound below every cost.
TEST(Roadmap, ARewardAboveItsCeilingCostsAsTheCeiling) {
  kinematics::World w = testing::roomWithTargetAndObstacle();
  w.obstacles.clear();
  w.targets = {testing::box(-5, -5, 5, 5), testing::box(-5, -5, 5, 5)};
  params::Parameters p = smallBudget();
  p.reward.lambda1 = 0.1;
  p.reward.lambda2 = 1.0;
  p.reward.lambda3 = 0.0;  // no repulsion from the side a metre away
  const double ceiling = 1.1;
  reward::RewardModel reward(p.reward, kTheta);
  reward.setWorld(w);
  // Looking at a side from a metre away: both targets fill the whole field of view.
  const geometry::Pose a{0, -6, std::numbers::pi / 2}, b{0.5, -6, std::numbers::pi / 2};
  ASSERT_GT(reward.reward(std::span(&a, 1)), ceiling);
  ASSERT_GT(reward.reward(std::span(&b, 1)), ceiling);
  Roadmap roadmap(w, p, kTheta, 1);
  EXPECT_DOUBLE_EQ(roadmap.cost(a, b), 0.5 / ceiling);
  EXPECT_LE(roadmap.costLowerBound(a, b), roadmap.cost(a, b));
}

TEST(Roadmap, UnreachableGoalHasNoPath) {
  kinematics::World w = testing::roomWithTargetAndObstacle();
  // A wall of obstacles splits the room in two.
  w.obstacles.push_back({{-0.2, -20}, {0.2, -20}, {0.2, 20}, {-0.2, 20}});
  w.targets.clear();
  Roadmap roadmap(w, smallBudget(), kTheta, 2);
  EXPECT_FALSE(roadmap.query({-10, 0, 0}, {10, 0, 0}));
}

TEST(StateValidity, AStateIsClearWhenEveryObjectMeasuredIsAtLeastD1Away) {
  // Against every object measured, points drawn at random and points exactly d1 (and a hair
  // less) from a side of an axis-aligned square, where the boxes' skip is tightest.
  testing::SplitMix64 random{3};
  for (int world = 0; world < 5; ++world) {
    kinematics::World w = testing::randomWorld(random);
    w.obstacles.push_back({{2, -6}, {4, -6}, {4, -4}, {2, -4}});
    for (const double d1 : {0.0, 0.5, 1.0, 3.0}) {
      StateValidity v(d1);
      v.setWorld(w);
      std::vector<geometry::Vec2> points;
      for (int k = 0; k < 400; ++k)
        points.push_back(testing::randomPose(random).position());
      for (const double gap : {d1, std::nextafter(d1, 0.0)})
        points.insert(points.end(), {{4 + gap, -5}, {2 - gap, -5}, {3, -4 + gap}, {3, -6 - gap}});
      for (const geometry::Vec2 p : points) {
        bool clear = true;
        for (const auto* group : {&w.targets, &w.obstacles}) {
          for (const geometry::Ring& object : *group)
            clear = clear && geometry::distanceToPolygon(object, p) >= d1;
        }
        ASSERT_EQ(v.clearOfObjects(p), clear) << "d1 " << d1 << " at " << p.x << ", " << p.y;
        ASSERT_EQ(v.isValid(p), clear && v.insideBoundary(p));
      }
    }
  }
}

TEST(StateValidity, AMotionBetweenClearEndsIsJudgedAsWhenTheEndsAreMeasured) {
  testing::SplitMix64 random{11};
  int judged = 0, refused = 0;
  for (int world = 0; world < 5; ++world) {
    const kinematics::World w = testing::randomWorld(random);
    for (const double d1 : {0.0, 0.5, 1.5}) {
      StateValidity v(d1);
      v.setWorld(w);
      for (int k = 0; k < 2000; ++k) {
        const geometry::Vec2 a = testing::randomPose(random).position();
        // Short motions as well as long ones, as a roadmap's edges are.
        const geometry::Vec2 b =
            k % 2 == 0 ? testing::randomPose(random).position()
                       : a + geometry::Vec2{random.uniform(-3, 3), random.uniform(-3, 3)};
        if (!v.isValid(a) || !v.isValid(b)) continue;
        ++judged;
        const bool measured = v.staysClear(a, b);
        if (!measured) ++refused;
        ASSERT_EQ(v.staysClear(a, b, true), measured)
            << a.x << ", " << a.y << " to " << b.x << ", " << b.y << " with d1 " << d1;
      }
    }
  }
  EXPECT_GT(judged, 5000);
  EXPECT_GT(refused, 500) << "motions refused, not only passed, are compared";
}

TEST(StateValidity, MotionsMustKeepClearanceD1Exactly) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  StateValidity v(1.0);
  v.setWorld(w);
  // Passing 1.5 m below the obstacle (its bottom edge at y = -0.5): fine; 0.9 m: not.
  EXPECT_TRUE(v.isValidMotion({3, -2}, {9, -2}));
  EXPECT_FALSE(v.isValidMotion({3, -1.4}, {9, -1.4}));
  // Ends valid but the segment runs through the target.
  EXPECT_FALSE(v.isValidMotion({-3, 0}, {3, 0}));
  // Leaving the boundary.
  EXPECT_FALSE(v.isValidMotion({15, 15}, {25, 15}));
  // A camera already too close may move away, never closer.
  EXPECT_TRUE(v.isValidMotion({0, -0.9}, {0, -3}));
  EXPECT_FALSE(v.isValidMotion({0, -0.9}, {0, -0.7}));
}

}  // namespace
}  // namespace camcov::planners
