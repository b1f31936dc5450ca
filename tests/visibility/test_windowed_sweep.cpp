// Windowed sweeps (Windowing in sweep.h): a query answered inside a window must be the query
// answered over the whole scene. Random configurations with windows forced down to a few
// pieces, so that windows are both kept and outgrown; and a large scene where the camera is
// walled in, so that the first window must hold.
#include <gtest/gtest.h>

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

constexpr Windowing kWhole{std::numeric_limits<std::uint32_t>::max(), 0};
// Windows from the smallest scenes on, the first one holding about four pieces.
constexpr Windowing kTiny{0, 4};

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

TEST(WindowedSweep, MatchesTheWholeSweepOnRandomConfigurations) {
  Sweep whole(kWhole), windowed(kTiny);
  Occluders occluders;
  std::vector<Segment> want, got;
  Ring wantPolygon, gotPolygon;
  for (std::uint64_t index = 0; index < 3000 && !HasFailure(); ++index) {
    const testing::Case c = testing::randomCase(9041, index);
    occluders.build(c.world);
    const double tol = 1e-9 * occluders.extent();
    SCOPED_TRACE("case " + std::to_string(index) + "\n" + testing::describe(c));

    whole.segments(occluders, c.cameras, c.halfFov, want);
    windowed.segments(occluders, c.cameras, c.halfFov, got);
    expectSameSegments(got, want, tol);

    testing::Random random(index);
    const Vec2 point = testing::randomViewpoint(random, c.world);
    whole.visibilityPolygon(occluders, point, wantPolygon);
    windowed.visibilityPolygon(occluders, point, gotPolygon);
    expectSamePolygon(gotPolygon, wantPolygon, tol);

    whole.fieldOfViewPolygon(occluders, c.cameras[0], c.halfFov, wantPolygon);
    windowed.fieldOfViewPolygon(occluders, c.cameras[0], c.halfFov, gotPolygon);
    expectSamePolygon(gotPolygon, wantPolygon, tol);
  }
  // Both ways out of a window were taken many times.
  const WindowCounts& n = windowed.counts();
  EXPECT_GT(n.kept, 1000u);
  EXPECT_GT(n.windows - n.kept, 1000u);
  EXPECT_GT(n.whole, 1000u);
  EXPECT_EQ(whole.counts().windows, 0u);
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

TEST(WindowedSweep, WalledInCameraIsAnsweredByTheFirstWindowExactly) {
  const Occluders occluders(walledInCamera());
  ASSERT_GE(occluders.pieceCount(), Windowing{}.fromPieces);
  const std::vector<geometry::Pose> cameras{{-8, -8, std::numbers::pi / 4},
                                            {8, 0, std::numbers::pi}};
  const double halfFov = std::numbers::pi / 6;
  Sweep whole(kWhole), windowed;
  std::vector<Segment> want, got;
  whole.segments(occluders, cameras, halfFov, want);
  windowed.segments(occluders, cameras, halfFov, got);
  expectSameSegments(got, want, 0.0);
  Ring wantPolygon, gotPolygon;
  whole.visibilityPolygon(occluders, {5, 5}, wantPolygon);
  windowed.visibilityPolygon(occluders, {5, 5}, gotPolygon);
  expectSamePolygon(gotPolygon, wantPolygon, 0.0);
  // The inner room, walls included, is 24 m wide: the first window, about 1,024 pieces' worth of
  // the 400 m room, is wider.
  EXPECT_EQ(windowed.counts().windows, 3u);
  EXPECT_EQ(windowed.counts().kept, 3u);
  EXPECT_EQ(windowed.counts().whole, 0u);
  // The target inside is seen on the sides facing the cameras, the one outside not at all.
  double seenInside = 0.0, seenOutside = 0.0;
  for (const Segment& s : got)
    (s.target == 0 ? seenInside : seenOutside) += s.visibleBy != 0 ? length(s) : 0.0;
  EXPECT_GT(seenInside, 0.0);
  EXPECT_EQ(seenOutside, 0.0);
}

// Out of the walls, the view reaches beyond any small window: windows are outgrown and the
// result is still the whole scene's.
TEST(WindowedSweep, ViewDownALongAisleOutgrowsTheWindows) {
  const Occluders occluders(walledInCamera());
  const std::vector<geometry::Pose> cameras{{-195, -195, std::numbers::pi / 4}};
  Sweep whole(kWhole), windowed;
  std::vector<Segment> want, got;
  whole.segments(occluders, cameras, std::numbers::pi / 3, want);
  windowed.segments(occluders, cameras, std::numbers::pi / 3, got);
  expectSameSegments(got, want, 1e-9 * occluders.extent());
  EXPECT_GE(windowed.counts().windows, 1u);
  EXPECT_EQ(windowed.counts().kept + windowed.counts().whole, 1u);
}

}  // namespace
}  // namespace camcov::visibility
