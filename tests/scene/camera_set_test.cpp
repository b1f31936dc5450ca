// A set of cameras by index (scene/camera_set.h), checked against std::set<std::size_t>.
#include "scene/camera_set.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace camcov::scene {
namespace {

std::vector<std::size_t> members(const CameraSet& s) {
  std::vector<std::size_t> out;
  s.forEach([&](std::size_t j) { out.push_back(j); });
  return out;
}

TEST(CameraSet, HoldsEveryCameraUpToTheLimitAsASetOfIndicesWould) {
  // Cameras on both sides of every word boundary, and the last one.
  const std::vector<std::size_t> picks{0, 1, 62, 63, 64, 65, 100, kMaxCameras - 1};
  CameraSet s;
  std::set<std::size_t> reference;
  for (std::size_t j : picks) {
    s.insert(j);
    reference.insert(j);
    EXPECT_EQ(members(s), std::vector<std::size_t>(reference.begin(), reference.end()));
    EXPECT_EQ(s.size(), reference.size());
  }
  for (std::size_t j = 0; j < kMaxCameras; ++j)
    EXPECT_EQ(s.contains(j), reference.count(j) == 1) << j;
  s.erase(64);
  s.erase(64);  // twice: still out
  reference.erase(64);
  EXPECT_EQ(members(s), std::vector<std::size_t>(reference.begin(), reference.end()));
}

TEST(CameraSet, FirstCamerasIsAPrefixAtAndAcrossWordBoundaries) {
  for (std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{63}, std::size_t{64},
                            std::size_t{65}, std::size_t{127}, kMaxCameras}) {
    const CameraSet s = CameraSet::firstCameras(count);
    EXPECT_EQ(s.size(), count);
    EXPECT_EQ(s.empty(), count == 0);
    if (count > 0) {
      EXPECT_TRUE(s.contains(count - 1));
    }
    if (count < kMaxCameras) {
      EXPECT_FALSE(s.contains(count));
    }
  }
}

TEST(CameraSet, UnionIntersectionAndEqualityAreThoseOfSets) {
  CameraSet low = CameraSet::fromBits(0b1010), high = CameraSet::only(70);
  EXPECT_FALSE(low.intersects(high));
  CameraSet both = low;
  both |= high;
  EXPECT_EQ(members(both), (std::vector<std::size_t>{1, 3, 70}));
  EXPECT_TRUE(both.intersects(high));
  EXPECT_TRUE(both.intersects(CameraSet::only(3)));
  EXPECT_FALSE(both.intersects(CameraSet::only(2)));
  both.erase(70);
  EXPECT_EQ(both, low);
  EXPECT_NE(both, high);
  EXPECT_EQ(both.word(0), 0b1010u);
  EXPECT_EQ(high.word(1), std::uint64_t{1} << 6);
}

}  // namespace
}  // namespace camcov::scene
