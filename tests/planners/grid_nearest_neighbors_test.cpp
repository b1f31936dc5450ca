// The roadmap's grid neighbours against OMPL's exhaustive search, the independent reference:
// the same neighbours in the same order, for k-nearest and radius queries, under the SE(2)
// distance PRM* uses (‖Δxy‖ + ½|Δγ|), with points clustered, spread, off the grid's cells and
// coincident in the plane.
#include "planners/grid_nearest_neighbors.h"

#include <gtest/gtest.h>

#include <ompl/datastructures/NearestNeighborsLinear.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "support/splitmix64.h"

namespace camcov::planners {
namespace {

struct Pose {
  double x, y, yaw;
};

double se2(const Pose& a, const Pose& b) {
  const double d = std::abs(a.yaw - b.yaw);
  return std::hypot(a.x - b.x, a.y - b.y) +
         0.5 * (d > std::numbers::pi ? 2 * std::numbers::pi - d : d);
}

TEST(GridNearestNeighbors, FindsWhatTheExhaustiveSearchFindsInTheSameOrder) {
  testing::SplitMix64 random{17};
  std::vector<Pose> poses;
  const auto distance = [&poses](std::size_t a, std::size_t b) { return se2(poses[a], poses[b]); };
  for (const double cell : {0.5, 3.0, 40.0}) {
    SCOPED_TRACE(cell);
    poses.clear();
    GridNearestNeighbors<std::size_t> grid(cell, [&poses](std::size_t i) {
      return geometry::Vec2{poses[i].x, poses[i].y};
    });
    ompl::NearestNeighborsLinear<std::size_t> linear;
    grid.setDistanceFunction(distance);
    linear.setDistanceFunction(distance);
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
