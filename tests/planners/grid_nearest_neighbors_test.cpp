// The roadmap's grid neighbours against OMPL's exhaustive search under OMPL's own SE(2)
// distance, the independent reference: the same distances to the bit, the same neighbours in
// the same order, for k-nearest and radius queries, with points clustered, spread, off the
// grid's cells, far outside the box it was laid out over, and coincident in the plane.
#include "planners/grid_nearest_neighbors.h"

#include <gtest/gtest.h>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "planners/se2_distance.h"
#include "support/splitmix64.h"

namespace camcov::planners {
namespace {

using geometry::Pose;
namespace ob = ompl::base;

// OMPL's SE(2) distance between two poses, as PRM* measures its milestones.
double omplDistance(const Pose& a, const Pose& b) {
  static const auto space = std::make_shared<ob::SE2StateSpace>();
  ob::ScopedState<ob::SE2StateSpace> s(space), t(space);
  s->setXY(a.x, a.y);
  s->setYaw(a.yaw);
  t->setXY(b.x, b.y);
  t->setYaw(b.yaw);
  return space->distance(s.get(), t.get());
}

TEST(Se2Distance, IsWhatOmplsSe2SpaceMeasuresToTheBit) {
  testing::SplitMix64 random{5};
  for (int i = 0; i < 100000; ++i) {
    const Pose a{random.uniform(-1e3, 1e3), random.uniform(-1e-3, 1e-3),
                 random.uniform(-std::numbers::pi, std::numbers::pi)};
    const Pose b{a.x + random.uniform(-50, 50), random.uniform(-1e3, 1e3),
                 i % 7 == 0 ? a.yaw : random.uniform(-std::numbers::pi, std::numbers::pi)};
    ASSERT_EQ(se2Distance(a, b), omplDistance(a, b))
        << a.x << " " << a.y << " " << a.yaw << " / " << b.x << " " << b.y << " " << b.yaw;
  }
}

TEST(GridNearestNeighbors, FindsWhatTheExhaustiveSearchFindsInTheSameOrder) {
  testing::SplitMix64 random{17};
  std::vector<Pose> poses;
  for (const double cell : {0.5, 3.0, 40.0}) {
    SCOPED_TRACE(cell);
    poses.clear();
    GridNearestNeighbors<std::size_t> grid(cell, geometry::Box{{-30, -30}, {30, 30}},
                                           [&poses](std::size_t i) { return poses[i]; });
    ompl::NearestNeighborsLinear<std::size_t> linear;
    linear.setDistanceFunction(
        [&poses](std::size_t a, std::size_t b) { return omplDistance(poses[a], poses[b]); });
    std::vector<std::size_t> fromGrid, fromLinear;
    for (std::size_t i = 0; i < 1500; ++i) {
      // Most spread over a 60 m square, some in a tight cluster, a few far outside it, some on
      // the same spot with other yaws.
      const double what = random.uniform(0, 1);
      Pose p{random.uniform(-30, 30), random.uniform(-30, 30), random.uniform(-3.14, 3.14)};
      if (what < 0.2) p = {random.uniform(5, 5.3), random.uniform(-2, -1.9), p.yaw};
      if (what > 0.98) p = {random.uniform(200, 300), random.uniform(-300, -200), p.yaw};
      if (what > 0.9 && what <= 0.98 && i > 0) p = {poses[i - 1].x, poses[i - 1].y, p.yaw};
      poses.push_back(p);
      // Queried before being added, as PRM asks for a new milestone's neighbours.
      const std::size_t k = 1 + i % 30;
      grid.nearestK(i, k, fromGrid);
      linear.nearestK(i, k, fromLinear);
      ASSERT_EQ(fromGrid, fromLinear) << "k = " << k << ", point " << i;
      const double radius = random.uniform(0, 8);
      grid.nearestR(i, radius, fromGrid);
      linear.nearestR(i, radius, fromLinear);
      ASSERT_EQ(fromGrid, fromLinear) << "r = " << radius << ", point " << i;
      grid.add(i);
      linear.add(i);
    }
    EXPECT_EQ(grid.size(), linear.size());
    EXPECT_EQ(grid.nearest(7), linear.nearest(7));
    EXPECT_TRUE(grid.remove(7));
    EXPECT_FALSE(grid.remove(7));
    linear.remove(7);
    grid.nearestK(7, 12, fromGrid);
    linear.nearestK(7, 12, fromLinear);
    EXPECT_EQ(fromGrid, fromLinear);
  }
}

}  // namespace
}  // namespace camcov::planners
