#include "planners/visibility_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/small_worlds.h"

namespace camcov::planners {
namespace {

// q1 is seen from pose p if it lies in the field of view and the open segment p -> q1 meets
// no edge: an independent check with plain segment tests, not the sweep.
bool sees(const kinematics::World& w, const geometry::Pose& p, geometry::Vec2 q1, double halfFov) {
  const geometry::Vec2 d = q1 - p.position();
  const double off = geometry::wrapAngle(std::atan2(d.y, d.x) - p.yaw);
  if (std::abs(off) > halfFov + 1e-12) return false;
  // Stop just short of q1, which lies on an edge itself.
  const geometry::Vec2 nearlyQ1 = p.position() + d * (1.0 - 1e-9);
  for (const auto* group : {&w.targets, &w.obstacles}) {
    for (const auto& ring : *group) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        if (geometry::segmentsIntersect(p.position(), nearlyQ1, ring[i],
                                        ring[(i + 1) % ring.size()])) {
          return false;
        }
      }
    }
  }
  return true;
}

// Poses the sampler draws for a camera with `lens` in the room of small_worlds.h, ten for each
// of `trials` points q1 on the target, with the q1 each was drawn for.
struct Drawn {
  geometry::Vec2 q1;
  geometry::Pose pose;
};
std::vector<Drawn> drawnPoses(const kinematics::World& w, const scene::Lens& lens, int trials,
                              std::uint64_t seed) {
  reward::RewardModel model(params::RewardParams{}, lens);
  model.setWorld(w);
  StateValidity validity(1.0);
  validity.setWorld(w);
  Random random(seed);
  VisibilitySampler sampler;
  std::vector<Drawn> out;
  for (int trial = 0; trial < trials; ++trial) {
    const auto q1 = samplePointOnRings(w.targets, random);
    if (!q1 || !sampler.focus(model, *q1)) continue;
    for (int k = 0; k < 10; ++k) {
      if (const auto pose = sampler.sample(random, validity, lens)) out.push_back({*q1, *pose});
    }
  }
  return out;
}

TEST(VisibilitySampler, SamplesAreValidAndSeeTheirPoint) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  StateValidity validity(1.0);
  validity.setWorld(w);
  const auto drawn = drawnPoses(w, std::numbers::pi / 6, 200, 7);
  for (const auto& [q1, pose] : drawn) {
    EXPECT_TRUE(validity.isValid(pose.position()));
    EXPECT_TRUE(sees(w, pose, q1, std::numbers::pi / 6))
        << "q1 (" << q1.x << ", " << q1.y << ") pose (" << pose.x << ", " << pose.y << ", "
        << pose.yaw << ")";
  }
  EXPECT_GT(drawn.size(), 1500u) << "the room is mostly free: few samples should fail";
}

TEST(VisibilitySampler, ACameraWithASensingRangeIsPlacedWithinItOfItsPoint) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  const scene::Lens lens = testing::rangedLens(std::numbers::pi / 6, 3.0);
  const auto drawn = drawnPoses(w, lens, 100, 11);
  for (const auto& [q1, pose] : drawn) {
    EXPECT_LE(geometry::distance(pose.position(), q1), 3.0);
    EXPECT_TRUE(sees(w, pose, q1, lens.halfFov));
  }
  // Rejection: most of what the target sees lies farther than 3 m, yet a sample is mostly found.
  EXPECT_GT(drawn.size(), 200u);
}

TEST(SamplePointOnSegments, IsUniformByLength) {
  // Two collinear segments of length 1 and 3: a quarter of the samples on the first.
  std::vector<visibility::Segment> segments(2);
  segments[0].a = {0, 0};
  segments[0].b = {1, 0};
  segments[1].a = {1, 0};
  segments[1].b = {4, 0};
  Random random(3);
  int first = 0;
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    const auto p = samplePointOnSegments(segments, random);
    ASSERT_TRUE(p);
    if (p->x < 1.0) ++first;
  }
  EXPECT_NEAR(first / double(n), 0.25, 0.01);
  EXPECT_FALSE(samplePointOnSegments({}, random));
}

TEST(SampleYawSeeing, KeepsTheTargetPointInsideTheFieldOfView) {
  Random random(11);
  for (int i = 0; i < 1000; ++i) {
    const geometry::Vec2 q2{random.uniform(-5, 5), random.uniform(-5, 5)};
    const geometry::Vec2 q1{random.uniform(-5, 5), random.uniform(-5, 5)};
    const double yaw = sampleYawSeeing(q2, q1, 0.3, random);
    const double toQ1 = std::atan2(q1.y - q2.y, q1.x - q2.x);
    EXPECT_LE(std::abs(geometry::wrapAngle(toQ1 - yaw)), 0.3 + 1e-12);
  }
}

TEST(PolygonSampler, IsUniformByAreaOverAFan) {
  // An L-shaped star polygon seen from the origin: the 2x1 arm holds 2/3 of the area.
  const geometry::Ring l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  PolygonSampler sampler;
  sampler.reset(l, {0, 0});
  EXPECT_NEAR(sampler.area(), 3.0, 1e-12);
  kinematics::World w;
  w.boundary = {{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};
  StateValidity anywhere(0.0);
  anywhere.setWorld(w);
  Random random(5);
  int lower = 0;
  const int n = 30000;
  for (int i = 0; i < n; ++i) {
    const auto p = sampler.sample(random, anywhere, 1);
    ASSERT_TRUE(p);
    EXPECT_EQ(geometry::locate(l, *p, 1e-12) != geometry::Containment::Outside, true);
    if (p->y < 1.0) ++lower;
  }
  EXPECT_NEAR(lower / double(n), 2.0 / 3.0, 0.01);
}

}  // namespace
}  // namespace camcov::planners
