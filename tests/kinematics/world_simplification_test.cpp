// A world with its finely drawn objects redrawn coarser (kinematics/world_simplification.h).
#include "kinematics/world_simplification.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/ring.h"
#include "support/rings.h"

namespace camcov::kinematics {
namespace {

using camcov::testing::disc;
using geometry::Ring;
using geometry::Vec2;

World room() {
  World w;
  w.time = 3.5;
  w.boundary = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};
  return w;
}

TEST(WorldSimplification, FineObjectsAreRedrawnAndTheRestStays) {
  World w = room();
  w.targets = {disc({-5, 0}, 2, 1000), {{1, 1}, {2, 1}, {2, 2}}};
  w.targetIds = {7, 9};
  w.obstacles = {disc({5, 5}, 1, 500)};
  w.obstacleIds = {3};
  World out;
  SimplificationScratch scratch;
  ASSERT_TRUE(simplifyObjects(w, 0.01, out, scratch));
  EXPECT_LT(out.targets[0].size(), 100u);
  EXPECT_LT(out.obstacles[0].size(), 100u);
  EXPECT_EQ(out.targets[1], w.targets[1]) << "a triangle has nothing to lose";
  EXPECT_EQ(out.boundary, w.boundary);
  EXPECT_EQ(out.targetIds, w.targetIds);
  EXPECT_EQ(out.obstacleIds, w.obstacleIds);
  EXPECT_EQ(out.time, w.time);
  for (const Vec2 v : w.targets[0])
    EXPECT_LE(geometry::distanceToBoundary(out.targets[0], v), 0.01 * (1 + 1e-12));

  // A world with nothing fine comes back as it was, and says so.
  World coarse = room();
  coarse.targets = {w.targets[1]};
  EXPECT_FALSE(simplifyObjects(coarse, 0.01, out, scratch));
  EXPECT_EQ(out.targets, coarse.targets);
  EXPECT_EQ(out.boundary, coarse.boundary);
  EXPECT_TRUE(hasFinelyDrawnObjects(w));
  EXPECT_FALSE(hasFinelyDrawnObjects(coarse));
}

TEST(WorldSimplification, OnlyRingsOfSixVerticesOrMoreCountAsFinelyDrawn) {
  // Keeping at least 3 vertices and at most half, a pentagon can lose none; a hexagon three,
  // whether it is the target or the obstacle.
  World w = room();
  w.targets = {disc({0, 0}, 1.0, 5)};
  EXPECT_FALSE(hasFinelyDrawnObjects(w));
  w.obstacles = {disc({5, 5}, 1.0, 6)};
  EXPECT_TRUE(hasFinelyDrawnObjects(w));
  w.obstacles.clear();
  w.targets.push_back(disc({5, 5}, 1.0, 6));
  EXPECT_TRUE(hasFinelyDrawnObjects(w));
}

TEST(WorldSimplification, EdgeWeightsFollowTheirEdges) {
  // A disc of 400 edges: weight 1 on the first quarter, 0.5 on the next, 0.25 on the rest but
  // for one edge of weight 0 in the middle of it.
  World w = room();
  w.targets = {disc({0, 0}, 3, 400)};
  std::vector<double> weights(400, 0.25);
  for (int e = 0; e < 100; ++e)
    weights[e] = 1.0;
  for (int e = 100; e < 200; ++e)
    weights[e] = 0.5;
  weights[300] = 0.0;
  w.targetEdgeWeights = {weights};
  World out;
  SimplificationScratch scratch;
  ASSERT_TRUE(simplifyObjects(w, 0.01, out, scratch));
  const Ring& simple = out.targets[0];
  const std::vector<double>& simpleWeights = out.targetEdgeWeights[0];
  ASSERT_EQ(simpleWeights.size(), simple.size());
  // Each simplified edge starts at an original vertex; every original edge from there to the
  // next kept vertex has the simplified edge's weight.
  std::size_t k = 0;
  std::vector<std::size_t> keptAt;
  for (std::size_t v = 0; v < w.targets[0].size(); ++v) {
    if (k < simple.size() && w.targets[0][v] == simple[k]) {
      keptAt.push_back(v);
      ++k;
    }
  }
  ASSERT_EQ(keptAt.size(), simple.size());
  for (std::size_t s = 0; s < keptAt.size(); ++s) {
    const std::size_t end = s + 1 < keptAt.size() ? keptAt[s + 1] : keptAt.front() + 400;
    for (std::size_t e = keptAt[s]; e < end; ++e)
      EXPECT_EQ(weights[e % 400], simpleWeights[s]) << "edge " << e % 400;
  }
  // The lone edge of weight 0 stays an edge of its own.
  EXPECT_EQ(std::count(simpleWeights.begin(), simpleWeights.end(), 0.0), 1);
}

}  // namespace
}  // namespace camcov::kinematics
