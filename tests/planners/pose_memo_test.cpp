// The roadmap's memo of poses against std::map, the reference: one value per pose, kept
// through the table's growth, and poses that differ in a single coordinate's bits (its last,
// or only its sign, as −0 and 0) kept apart.
#include "planners/pose_memo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include "support/splitmix64.h"

namespace camcov::planners {
namespace {

using geometry::Pose;

TEST(PoseMemo, KeepsOneValuePerPoseThroughGrowthAsAMapDoes) {
  testing::SplitMix64 random{3};
  PoseMemo<int> memo;
  std::map<std::tuple<double, double, double>, int> reference;
  std::vector<Pose> poses;
  for (int i = 0; i < 20000; ++i) {
    Pose p{random.uniform(-10, 10), random.uniform(-10, 10), random.uniform(-3, 3)};
    const double what = random.uniform(0, 1);
    if (what < 0.3 && !poses.empty()) p = poses[static_cast<std::size_t>(i) % poses.size()];
    if (what > 0.9 && !poses.empty()) {  // a neighbour in one coordinate's last bit
      p = poses.back();
      p.yaw = std::nextafter(p.yaw, 10.0);
    }
    poses.push_back(p);
    const auto key = std::make_tuple(p.x, p.y, p.yaw);
    const bool known = reference.contains(key);
    int& value = memo[p];
    ASSERT_EQ(value, known ? reference[key] : 0) << i;
    if (!known) value = reference[key] = i + 1;
  }
  for (const auto& [key, value] : reference)
    EXPECT_EQ((memo[{std::get<0>(key), std::get<1>(key), std::get<2>(key)}]), value);
}

TEST(PoseMemo, NegativeZeroIsKeptApartFromZero) {
  PoseMemo<int> memo;
  memo[{0.0, 1.0, 0.0}] = 7;
  EXPECT_EQ((memo[{-0.0, 1.0, 0.0}]), 0);
  EXPECT_EQ((memo[{0.0, 1.0, -0.0}]), 0);
  EXPECT_EQ((memo[{0.0, -1.0, 0.0}]), 0);
  EXPECT_EQ((memo[{0.0, 1.0, 0.0}]), 7);
}

}  // namespace
}  // namespace camcov::planners
