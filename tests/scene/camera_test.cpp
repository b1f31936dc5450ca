// The camera type (scene/camera.h): the lens's view and range against numbers worked out by
// hand, the movement rules, the loader's sensingRange, and the one description of a camera.
#include "scene/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/small_worlds.h"

namespace camcov::scene {
namespace {

using geometry::Vec2;
using testing::rangedLens;
constexpr double kPi = std::numbers::pi;

TEST(Lens, WithoutARangeSeesTheWholeWedgeAtAnyDistance) {
  const Lens lens(kPi / 6);
  EXPECT_FALSE(lens.limited());
  EXPECT_TRUE(lens.sees({1e8, 0}, 0.0));
  EXPECT_TRUE(lens.sees({std::cos(kPi / 6), std::sin(kPi / 6)}, 0.0));  // on the wedge's ray
  EXPECT_FALSE(lens.sees({0, 1}, 0.0));
  double t0 = -1, t1 = -1;
  EXPECT_TRUE(lens.rangeOnSegment({0, 0}, {1e6, -3}, {1e6, 3}, t0, t1));
  EXPECT_EQ(t0, 0.0);
  EXPECT_EQ(t1, 1.0);
}

TEST(Lens, ARangeCutsAtItsCircleInclusive) {
  const Lens lens = rangedLens(kPi / 6, 5.0);
  EXPECT_TRUE(lens.sees({5, 0}, 0.0));
  EXPECT_FALSE(lens.sees({5.000001, 0}, 0.0));
  EXPECT_TRUE(lens.sees({3, 1}, 0.0));
  EXPECT_FALSE(lens.sees({-3, 0}, 0.0));  // near, but behind
}

TEST(Lens, RangeOnSegmentIsTheChordOfTheCircle) {
  const Lens lens = rangedLens(kPi / 6, 5.0);
  double t0 = 0, t1 = 0;
  // x = 3 from y = −8 to y = 8: inside for |y| ≤ 4, t = (y + 8) / 16 in [0.25, 0.75].
  ASSERT_TRUE(lens.rangeOnSegment({0, 0}, {3, -8}, {3, 8}, t0, t1));
  EXPECT_NEAR(t0, 0.25, 1e-15);
  EXPECT_NEAR(t1, 0.75, 1e-15);
  // The same segment written the other way: the same chord, from the other end.
  ASSERT_TRUE(lens.rangeOnSegment({0, 0}, {3, 8}, {3, -8}, t0, t1));
  EXPECT_NEAR(t0, 0.25, 1e-15);
  EXPECT_NEAR(t1, 0.75, 1e-15);
  // Starting inside: from (0, 0) along +x to (10, 0), inside up to x = 5.
  ASSERT_TRUE(lens.rangeOnSegment({0, 0}, {0, 0}, {10, 0}, t0, t1));
  EXPECT_EQ(t0, 0.0);
  EXPECT_NEAR(t1, 0.5, 1e-15);
  // Wholly inside.
  ASSERT_TRUE(lens.rangeOnSegment({1, 1}, {0, 0}, {2, 2}, t0, t1));
  EXPECT_EQ(t0, 0.0);
  EXPECT_EQ(t1, 1.0);
  // Wholly beyond, tangent (a single point, no length), and a point segment.
  EXPECT_FALSE(lens.rangeOnSegment({0, 0}, {6, -1}, {6, 1}, t0, t1));
  EXPECT_FALSE(lens.rangeOnSegment({0, 0}, {5, -1}, {5, 1}, t0, t1));
  EXPECT_FALSE(lens.rangeOnSegment({0, 0}, {7, 7}, {7, 7}, t0, t1));
  // Far from the camera's origin, many digits in each coordinate: the chord still to 1e-9.
  ASSERT_TRUE(
      lens.rangeOnSegment({1e6 + 0.5, -2e6}, {1e6 + 3.5, -2e6 - 8}, {1e6 + 3.5, -2e6 + 8}, t0, t1));
  EXPECT_NEAR(t0, 0.25, 1e-9);
  EXPECT_NEAR(t1, 0.75, 1e-9);
}

TEST(Lens, ARangeBeyondWhatSquaresToADoubleSeesAllItWouldWithout) {
  // r² overflows from about 1e154 on: such a lens must not read as seeing nothing.
  double t0 = 0, t1 = 0;
  for (const double range : {1e150, 1e155, 1e200, 1e308}) {
    ASSERT_TRUE(rangedLens(kPi / 6, range).rangeOnSegment({0, 0}, {3e8, -8}, {-1e9, 1e9}, t0, t1))
        << range;
    EXPECT_EQ(t0, 0.0);
    EXPECT_EQ(t1, 1.0);
  }
}

TEST(Lens, CachesTellARangeApartToTheBit) {
  EXPECT_TRUE(sameBits(rangedLens(0.5, 3.0), rangedLens(0.5, 3.0)));
  EXPECT_FALSE(sameBits(rangedLens(0.5, 3.0), rangedLens(0.5, std::nextafter(3.0, 4.0))));
  EXPECT_FALSE(sameBits(Lens(0.5), rangedLens(0.5, 3.0)));
  EXPECT_NE(Lens(0.5), rangedLens(0.5, 3.0));
}

TEST(CameraSpec, SaturatesToItsLimitsAndStopsWhatIsNotFinite) {
  CameraSpec c;
  c.maxVelocity = 2.0;
  c.maxAngularVelocity = 0.5;
  const CameraCommand fast = c.saturate({{3, 4}, -2.0});
  EXPECT_NEAR(fast.velocity.x, 1.2, 1e-15);
  EXPECT_NEAR(fast.velocity.y, 1.6, 1e-15);
  EXPECT_EQ(fast.angularVelocity, -0.5);
  const CameraCommand bad = c.saturate({{NAN, 1}, INFINITY});
  EXPECT_EQ(bad.velocity, (Vec2{0, 0}));
  EXPECT_EQ(bad.angularVelocity, 0.0);
  EXPECT_FALSE((CameraCommand{{0, NAN}, 0}).isFinite());
  const StepLimits step = c.stepLimits(0.1);
  EXPECT_DOUBLE_EQ(step.maxTranslation, 0.2);
  EXPECT_DOUBLE_EQ(step.maxRotation, 0.05);
  EXPECT_DOUBLE_EQ(c.travelTime({0, 0, 0}, {6, 8, 1.0}), 5.0);   // 10 m at 2 m/s
  EXPECT_DOUBLE_EQ(c.travelTime({0, 0, 0}, {1, 0, -3.0}), 6.0);  // 3 rad at 0.5 rad/s
}

TEST(CameraSpec, MovedIsOneEulerStepWithTheYawWrapped) {
  const geometry::Pose p = moved({1, 2, 3.0}, {{1, -1}, 2.0}, 0.5);
  EXPECT_DOUBLE_EQ(p.x, 1.5);
  EXPECT_DOUBLE_EQ(p.y, 1.5);
  EXPECT_NEAR(p.yaw, 4.0 - 2 * kPi, 1e-15);
}

TEST(SceneLoader, ACameraMayHaveASensingRangeAndWithoutOneSeesWithoutLimit) {
  std::string json = testing::kOneTargetScene;
  const Scene plain = testing::sceneFromJson(json);
  ASSERT_FALSE(plain.cameras.empty());
  EXPECT_FALSE(plain.cameras[0].lens.limited());
  const auto at = json.find("\"maxVelocity\"");
  ASSERT_NE(at, std::string::npos);
  json.insert(at, "\"sensingRange\": 7.5, ");
  const Scene ranged = testing::sceneFromJson(json);
  EXPECT_EQ(ranged.cameras[0].lens.range, 7.5);
  EXPECT_EQ(ranged.cameras[0].lens.halfFov, plain.cameras[0].lens.halfFov);
}

// The description speaks the file's keys and units: written back as a camera entry of a scene
// file (pos as WKT), it loads to the same camera, lens and all.
TEST(DescribeCamera, IsTheFilesCameraEntryAndReadsBackAsTheSameCamera) {
  std::string json = testing::kOneTargetScene;
  json.insert(json.find("\"maxVelocity\""), "\"sensingRange\": 7.5, \"cameraFoV\": 40, ");
  const Scene scene = testing::sceneFromJson(json);
  const CameraSpec& camera = scene.cameras.at(0);
  nlohmann::json entry = describeCamera(camera);
  EXPECT_EQ(entry["cameraFoV"], 40.0);  // degrees as written, not 39.99999999999999
  EXPECT_EQ(entry["sensingRange"], 7.5);
  entry["pos"] = fmt::format("POINT({} {})", entry["x"].get<double>(), entry["y"].get<double>());
  entry.erase("x");
  entry.erase("y");
  nlohmann::json file = nlohmann::json::parse(json);
  file["cameras"] = nlohmann::json::array({entry});
  const CameraSpec back = testing::sceneFromJson(file.dump()).cameras.at(0);
  EXPECT_EQ(back.initial.x, camera.initial.x);
  EXPECT_EQ(back.initial.y, camera.initial.y);
  EXPECT_NEAR(back.initial.yaw, camera.initial.yaw, 1e-15);
  EXPECT_EQ(back.maxVelocity, camera.maxVelocity);
  EXPECT_EQ(back.maxAngularVelocity, camera.maxAngularVelocity);
  EXPECT_NEAR(back.lens.halfFov, camera.lens.halfFov, 1e-15);
  EXPECT_EQ(back.lens.range, camera.lens.range);
  EXPECT_FALSE(describeCamera(CameraSpec{}).contains("sensingRange"));  // unlimited: no key
}

}  // namespace
}  // namespace camcov::scene
