// Culled sweeps (Culling in sweep.h, OcclusionCulling): a query that leaves out the chains it
// proves hidden must answer as the sweep over the whole scene. Random configurations, few and
// many objects, culled from the smallest scenes on with grids of a few cells up to many per
// chain; a large scene where the camera is walled in, so that nearly everything is left out;
// and a long view down an aisle, so that the walk goes far.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "random_scenes.h"
#include "support/small_worlds.h"
#include "visibility/sweep.h"

namespace camcov::visibility {
namespace {

using camcov::testing::box;
using geometry::Ring;
using geometry::Vec2;

constexpr Culling kWhole{std::numeric_limits<std::uint32_t>::max()};

bool near(Vec2 a, Vec2 b, double tol) {
  return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol;
}

// Same segments, each seen by the same cameras, ends equal up to rounding.
void expectSameSegments(const std::vector<Segment>& got, const std::vector<Segment>& want,
                        double tol) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].visibleBy, want[i].visibleBy) << "segment " << i;
    EXPECT_TRUE(near(got[i].a, want[i].a, tol) && near(got[i].b, want[i].b, tol))
        << "segment " << i;
  }
}

void expectSamePolygon(const Ring& got, const Ring& want, double tol) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_TRUE(near(got[i], want[i], tol)) << "vertex " << i;
}

// Same S and masks, omnidirectional and field-of-view polygons, culled and whole, on `cases`
// random configurations; returns the chains culling left out, over all queries.
std::uint64_t compareOnRandomConfigurations(testing::Crowd crowd, int cases, Culling culling) {
  Sweep whole(kWhole), culled(culling);
  Occluders occluders;
  std::vector<Segment> want, got;
  Ring wantPolygon, gotPolygon;
  for (int index = 0; index < cases && !::testing::Test::HasFailure(); ++index) {
    const testing::Case c = testing::randomCase(9041, static_cast<std::uint64_t>(index), crowd);
    occluders.build(c.world);
    const double tol = 1e-9 * occluders.extent();
    SCOPED_TRACE("case " + std::to_string(index) + "\n" + testing::describe(c));

    whole.segments(occluders, c.cameras, c.halfFov, want);
    culled.segments(occluders, c.cameras, c.halfFov, got);
    expectSameSegments(got, want, tol);

    testing::Random random(static_cast<std::uint64_t>(index));
    for (int k = 0; k < 4; ++k) {
      const Vec2 point = testing::randomViewpoint(random, c.world);
      whole.visibilityPolygon(occluders, point, wantPolygon);
      culled.visibilityPolygon(occluders, point, gotPolygon);
      expectSamePolygon(gotPolygon, wantPolygon, tol);
    }

    for (const geometry::Pose& camera : c.cameras) {
      whole.fieldOfViewPolygon(occluders, camera, c.halfFov, wantPolygon);
      culled.fieldOfViewPolygon(occluders, camera, c.halfFov, gotPolygon);
      expectSamePolygon(gotPolygon, wantPolygon, tol);
    }
  }
  EXPECT_EQ(whole.counts().culled, 0u);
  EXPECT_EQ(culled.counts().whole, 0u);
  return culled.counts().chainsLeftOut;
}

TEST(CulledSweep, MatchesTheWholeSweepAmongFewObjects) {
  // A few objects: a fine grid, so that cells are small next to the objects and the walk
  // skips cells behind them.
  EXPECT_GT(compareOnRandomConfigurations(testing::Crowd::Few, 2000, {0, 16.0}), 1000u);
}

TEST(CulledSweep, MatchesTheWholeSweepAmongManyObjects) {
  for (const double cellsPerChain : {0.25, 1.0, 8.0}) {
    SCOPED_TRACE("cells per chain " + std::to_string(cellsPerChain));
    // Most chains are hidden from most viewpoints among 20–60 objects.
    EXPECT_GT(compareOnRandomConfigurations(testing::Crowd::Many, 300, {0, cellsPerChain}), 10000u);
  }
}

// A 400 m room with 2,000 small obstacles around a 20 m cell walled in by four overlapping
// walls: the camera in the cell sees nothing beyond them.
kinematics::World walledInCamera() {
  kinematics::World w;
  w.boundary = box(-200, -200, 200, 200);
  for (int i = 0; i < 2000; ++i) {
    const double x = -190 + 8.5 * (i % 45), y = -190 + 8.5 * (i / 45);
    if (std::abs(x) < 25 && std::abs(y) < 25) continue;
    w.obstacles.push_back(box(x, y, x + 2, y + 2));
  }
  w.obstacles.push_back(box(-12, -12, 12, -10));  // the walls overlap at the corners
  w.obstacles.push_back(box(10, -12, 12, 12));
  w.obstacles.push_back(box(-12, 10, 12, 12));
  w.obstacles.push_back(box(-12, -12, -10, 12));
  w.targets.push_back(box(-2, -2, 2, 2));
  w.targets.push_back(box(60, 60, 64, 64));  // out of sight, so S has unseen segments too
  return w;
}

TEST(CulledSweep, WalledInCameraSweepsOnlyTheInnerRoomExactly) {
  const Occluders occluders(walledInCamera());
  ASSERT_GE(occluders.pieceCount(), Culling{}.fromPieces);
  const std::vector<geometry::Pose> cameras{{-8, -8, std::numbers::pi / 4},
                                            {8, 0, std::numbers::pi}};
  const double halfFov = std::numbers::pi / 6;
  Sweep whole(kWhole), culled;
  std::vector<Segment> want, got;
  whole.segments(occluders, cameras, halfFov, want);
  culled.segments(occluders, cameras, halfFov, got);
  expectSameSegments(got, want, 0.0);
  Ring wantPolygon, gotPolygon;
  whole.visibilityPolygon(occluders, {5, 5}, wantPolygon);
  culled.visibilityPolygon(occluders, {5, 5}, gotPolygon);
  expectSamePolygon(gotPolygon, wantPolygon, 0.0);
  // Three queries, each leaving out all but the boundary, the four walls, the target inside
  // and the few obstacles whose cells the walls' cells share.
  const std::uint64_t chains = occluders.chains().size();
  EXPECT_EQ(culled.counts().culled, 3u);
  EXPECT_EQ(culled.counts().whole, 0u);
  EXPECT_GE(culled.counts().chainsLeftOut, 3 * (chains - 20));
  // The target inside is seen on the sides facing the cameras, the one outside not at all.
  double seenInside = 0.0, seenOutside = 0.0;
  for (const Segment& s : got)
    (s.target == 0 ? seenInside : seenOutside) += !s.visibleBy.empty() ? length(s) : 0.0;
  EXPECT_GT(seenInside, 0.0);
  EXPECT_EQ(seenOutside, 0.0);
}

// Out of the walls, from a corner of the room, the view reaches down the aisles to the far
// walls: the walk goes far, and the result is still the whole scene's.
TEST(CulledSweep, ViewDownLongAislesMatchesTheWholeSweep) {
  const Occluders occluders(walledInCamera());
  const std::vector<geometry::Pose> cameras{{-195, -195, std::numbers::pi / 4}};
  Sweep whole(kWhole), culled;
  std::vector<Segment> want, got;
  whole.segments(occluders, cameras, std::numbers::pi / 3, want);
  culled.segments(occluders, cameras, std::numbers::pi / 3, got);
  expectSameSegments(got, want, 1e-9 * occluders.extent());
  Ring wantPolygon, gotPolygon;
  whole.visibilityPolygon(occluders, {-195, -195}, wantPolygon);
  culled.visibilityPolygon(occluders, {-195, -195}, gotPolygon);
  expectSamePolygon(gotPolygon, wantPolygon, 1e-9 * occluders.extent());
  EXPECT_EQ(culled.counts().culled, 2u);
}

// One round target of many vertices in a room: once the target is kept, culling has nothing
// left to leave out and stops. What every camera sees is still the whole sweep's, to the bit.
TEST(CulledSweep, OneLargeTargetIsSeenAsByTheWholeSweepToTheBit) {
  Ring disc;
  for (int k = 0; k < 3000; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 3000;
    disc.push_back({1.0 + 4.0 * std::cos(a), -0.5 + 4.0 * std::sin(a)});
  }
  const Occluders occluders(camcov::testing::world(box(-15, -15, 15, 15), {disc}));
  Sweep whole(kWhole), culled({0, 1.0});
  testing::Random random(17);
  for (int k = 0; k < 200; ++k) {
    const geometry::Pose camera{random.uniform(-14.0, 14.0), random.uniform(-14.0, 14.0),
                                random.uniform(-std::numbers::pi, std::numbers::pi)};
    const scene::Lens lens{random.uniform(0.1, 3.0)};
    const auto want = whole.seenBy(occluders, 0, camera, lens);
    const std::vector<SeenInterval> kept(want.begin(), want.end());
    const auto got = culled.seenBy(occluders, 0, camera, lens);
    ASSERT_EQ(got.size(), kept.size()) << "camera " << k;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].edge, kept[i].edge);
      EXPECT_EQ(std::bit_cast<std::uint64_t>(got[i].lo), std::bit_cast<std::uint64_t>(kept[i].lo));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(got[i].hi), std::bit_cast<std::uint64_t>(kept[i].hi));
    }
  }
  EXPECT_EQ(culled.counts().culled, 200u);
  EXPECT_EQ(culled.counts().chainsLeftOut, 0u);
}

}  // namespace
}  // namespace camcov::visibility
