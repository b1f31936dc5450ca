// PolarEdges' culling of what lies out of a camera's view: the quick test against the rays
// (boxBeyondARay) may only leave out what the test on the keys (boxArcOutOfView) leaves out,
// and the quicker one on a box's disc (discView) only decide what those two decide, so the
// sweep's output cannot depend on which of them decided.
#include "visibility/polar_edges.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "support/small_worlds.h"
#include "support/splitmix64.h"

namespace camcov::visibility {
namespace {

using geometry::Vec2;

TEST(PolarEdges, TheQuickRayTestCullsNoBoxTheKeyTestKeeps) {
  const Occluders occluders(camcov::testing::world(camcov::testing::box(-50, -50, 50, 50), {}));
  camcov::testing::SplitMix64 random{11};
  PolarEdges edges;
  int quick = 0;
  for (int i = 0; i < 200000; ++i) {
    const Vec2 p{random.uniform(-40, 40), random.uniform(-40, 40)};
    // Half-angles up to π/2, the widest the quick test is made for; the rays sometimes just
    // off a box corner, where the two tests are closest to disagreeing.
    const FieldOfView fov{random.uniform(-4, 4), random.uniform(1e-3, 0.5 * std::numbers::pi)};
    geometry::Box box;
    box.min = {random.uniform(-45, 40), random.uniform(-45, 40)};
    box.max = box.min + Vec2{random.uniform(1e-3, 5), random.uniform(1e-3, 5)};
    if (i % 3 == 0) {  // a corner just beyond the right ray, by a few ulps to 1e-5 rad
      const double off = std::pow(10.0, random.uniform(-15, -5));
      const Vec2 corner =
          p + random.uniform(1, 30) * geometry::unitVector(fov.yaw - fov.halfAngle - off);
      box.max = corner;
      box.min = corner - Vec2{random.uniform(1e-3, 2), random.uniform(1e-3, 2)};
    }
    if (geometry::contains(geometry::grown(box, 1e-9), p)) continue;
    edges.build(occluders, p, &fov);
    if (!edges.boxBeyondARay(box)) continue;
    ++quick;
    ASSERT_TRUE(edges.boxArcOutOfView(box))
        << "p (" << p.x << ", " << p.y << "), yaw " << fov.yaw << ", θ " << fov.halfAngle;
  }
  EXPECT_GT(quick, 50000) << "the quick test must decide often enough to be worth it";
}

TEST(PolarEdges, TheDiscTestsDecideOnlyWhatTheCornerAndKeyTestsDecide) {
  const Occluders occluders(camcov::testing::world(camcov::testing::box(-50, -50, 50, 50), {}));
  camcov::testing::SplitMix64 random{12};
  PolarEdges edges;
  int beyond = 0, within = 0;
  for (int i = 0; i < 200000; ++i) {
    const Vec2 p{random.uniform(-40, 40), random.uniform(-40, 40)};
    const FieldOfView fov{random.uniform(-4, 4), random.uniform(1e-3, 0.5 * std::numbers::pi)};
    geometry::Box box;
    box.min = {random.uniform(-45, 40), random.uniform(-45, 40)};
    // Flat and point boxes too (a vertical or horizontal edge's box, a lone vertex's), whose
    // disc is as narrow as the box.
    const double w = i % 5 == 0 ? 0.0 : random.uniform(1e-3, 5);
    const double h = i % 7 == 0 ? 0.0 : random.uniform(1e-3, 5);
    box.max = box.min + Vec2{w, h};
    if (i % 3 == 0) {  // a corner on either ray, off it by a few ulps to 1e-5 rad either way
      // Side and sign drawn apart, so that each ray gets corners just beyond and just inside.
      const double off =
          std::pow(10.0, random.uniform(-15, -5)) * (random.uniform(0, 1) < 0.5 ? 1.0 : -1.0);
      const double side = random.uniform(0, 1) < 0.5 ? -1.0 : 1.0;
      const Vec2 corner =
          p + random.uniform(1, 30) * geometry::unitVector(fov.yaw + side * (fov.halfAngle + off));
      box.min = corner;
      box.max = corner + Vec2{w, h};
    }
    if (geometry::contains(geometry::grown(box, 1e-9), p)) continue;
    edges.build(occluders, p, &fov);
    const auto where = [&] {
      return "p (" + std::to_string(p.x) + ", " + std::to_string(p.y) + "), yaw " +
             std::to_string(fov.yaw) + ", θ " + std::to_string(fov.halfAngle);
    };
    switch (edges.discView(box)) {
      case PolarEdges::DiscView::BeyondARay:
        ++beyond;
        ASSERT_TRUE(edges.boxBeyondARay(box)) << where();
        break;
      case PolarEdges::DiscView::WellInView:
        ++within;
        ASSERT_FALSE(edges.boxBeyondARay(box)) << where();
        ASSERT_FALSE(edges.boxArcOutOfView(box)) << where();
        break;
      case PolarEdges::DiscView::Unsure:
        break;
    }
  }
  EXPECT_GT(beyond, 50000) << "the disc must decide most boxes out of view";
  EXPECT_GT(within, 5000);
}

TEST(PolarEdges, TheQuickRayTestStaysOutOfWideFieldsOfView) {
  const Occluders occluders(camcov::testing::world(camcov::testing::box(-50, -50, 50, 50), {}));
  PolarEdges edges;
  const FieldOfView wide{0.0, 0.6 * std::numbers::pi};
  edges.build(occluders, {0, 0}, &wide);
  EXPECT_FALSE(edges.boxBeyondARay({{-10, -1}, {-9, 1}}));  // behind: for the key test to say
  EXPECT_TRUE(edges.boxOutOfView({{-10, -1}, {-9, 1}}));
}

TEST(PolarEdges, BothSortsByKeyGiveTheSameStableOrder) {
  camcov::testing::SplitMix64 random{3};
  for (int round = 0; round < 2000; ++round) {
    // Keys over a narrow or a full range, with many repeats; refs record the input order.
    const auto n = static_cast<std::size_t>(random.uniform(0, 300));
    const double range = round % 2 == 0 ? 4294967295.0 : random.uniform(1, 1e6);
    const auto base = static_cast<std::uint32_t>(random.uniform(0, 4294967295.0));
    std::vector<PolarEdges::Event> events;
    for (std::size_t i = 0; i < n; ++i) {
      const auto key = base + static_cast<std::uint32_t>(random.uniform(0, range) / 7) * 7;
      events.push_back({key, static_cast<std::uint32_t>(i), 0, PolarEdges::EventKind::Vertex});
    }
    auto radix = events, bucket = events;
    std::vector<PolarEdges::Event> scratch;
    PolarEdges::radixSortByKey(radix, scratch);
    PolarEdges::bucketSortByKey(bucket, scratch);
    ASSERT_EQ(radix.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(bucket[i].key, radix[i].key) << "round " << round << ", event " << i;
      ASSERT_EQ(bucket[i].ref, radix[i].ref) << "round " << round << ", event " << i;
      if (i > 0) {
        ASSERT_LE(radix[i - 1].key, radix[i].key);
        if (radix[i - 1].key == radix[i].key) {
          ASSERT_LT(radix[i - 1].ref, radix[i].ref);
        }
      }
    }
  }
}

}  // namespace
}  // namespace camcov::visibility
