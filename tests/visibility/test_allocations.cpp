// The Sweep is a workspace: after warming up on a scene, further queries allocate nothing.
// Checked by replacing the global operator new with a counting one (for this test binary).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <numbers>

#include "random_scenes.h"
#include "visibility/sweep.h"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// The replacements are never inlined: GCC would otherwise see free() meet the pointer of a
// `new` expression in the same function and warn (-Wmismatched-new-delete), though replacing
// both halves of the pair is exactly what the standard allows.
[[gnu::noinline]] void* operator new(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new(std::size_t size, std::align_val_t align) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  const auto a = static_cast<std::size_t>(align);
  if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::align_val_t) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}

namespace camcov::visibility {
namespace {

using geometry::Pose;
using geometry::Vec2;

TEST(Allocations, SteadyStateQueriesAllocateNothing) {
  // A scene with overlapping objects (splits and twins) and many camera poses.
  const testing::Case c = testing::randomCase(20240611, 3);
  const Occluders occluders(c.world);
  testing::Random random(5);
  std::vector<Pose> cameras;
  std::vector<Vec2> points;
  for (int i = 0; i < 200; ++i) {
    cameras.push_back(
        {random.uniform(-1.0, 21.0), random.uniform(-1.0, 21.0), random.uniform(-3.2, 3.2)});
    points.push_back(testing::randomViewpoint(random, c.world));
  }
  // Swept whole (a small scene), and culled first on a fine grid.
  for (const Culling culling : {Culling{}, Culling{0, 16.0}}) {
    Sweep sweep(culling);
    std::vector<Segment> segments;
    geometry::Ring polygon;
    const auto runAll = [&] {
      for (std::size_t i = 0; i + 4 <= cameras.size(); i += 4) {
        sweep.segments(occluders, std::span(cameras).subspan(i, 4), 1.0, segments);
      }
      for (const Vec2 p : points)
        sweep.visibilityPolygon(occluders, p, polygon);
      for (const Pose& pose : cameras)
        sweep.fieldOfViewPolygon(occluders, pose, 2.5, polygon);
    };
    // Warm up: buffers grow to their largest size. A camera slot keeps several sweeps, taken
    // in turn, so a pose may land in another's buffer on the next round: a few rounds, until
    // one allocates nothing.
    const long start = allocations.load();
    long before = start;
    for (int round = 0; round < 8; ++round) {
      before = allocations.load();
      runAll();
      if (allocations.load() == before) break;
    }
    EXPECT_GT(before - start, 0) << "the counting operator new is not in use";
    before = allocations.load();
    runAll();
    EXPECT_EQ(allocations.load() - before, 0) << "culling from " << culling.fromPieces;
    if (culling.fromPieces == 0) {
      EXPECT_GT(sweep.counts().chainsLeftOut, 0u);
    }
  }
}

TEST(Allocations, RebuildingOccludersInPlaceAllocatesNothing) {
  // The per-instant preprocessing reuses its buffers too: replaying a motion it has seen once
  // (so that its buffers have grown to the most crossings on the way) allocates nothing.
  const testing::Case c = testing::randomCase(20240611, 3);
  kinematics::World moving = c.world;
  Occluders occluders;
  const auto replay = [&] {
    for (int step = 0; step < 20; ++step) {
      for (std::size_t i = 0; i < c.world.targets.size(); ++i) {
        for (std::size_t k = 0; k < c.world.targets[i].size(); ++k) {
          moving.targets[i][k] = c.world.targets[i][k] + Vec2{0.1, -0.2} * step;
        }
      }
      occluders.build(moving);
    }
  };
  const long start = allocations.load();
  replay();
  const long before = allocations.load();
  EXPECT_GT(before - start, 0);
  replay();
  EXPECT_EQ(allocations.load() - before, 0);
}

}  // namespace
}  // namespace camcov::visibility
