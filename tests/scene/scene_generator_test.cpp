// The large-scene generator: seeded to the byte, the counts and sizes asked for,
// and the placement it promises checked on the loaded scene through kinematics, as a run
// would move it: no camera ever within the clearance of a target, none near the boundary,
// targets never overlapping. Bad options and fields too crowded are InputErrors.
#include "scene/scene_generator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "geometry/ring.h"
#include "kinematics/kinematics.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace camcov::scene {
namespace {

using geometry::Vec2;

Scene load(const GeneratorOptions& o) {
  return parseScene(generateScene(o).dump(), "generated.json");
}

GeneratorOptions crowd() {
  GeneratorOptions o;
  o.targets = 40;
  o.cameras = 12;
  o.vertices = 5;
  o.fieldWidth = 40.0;
  o.fieldHeight = 30.0;
  o.targetLength = 1.2;
  o.targetWidth = 0.5;
  o.loopSize = 1.5;
  o.targetSpeed = 0.7;
  o.seed = 3;
  return o;
}

TEST(GenerateScene, TheSameSeedGivesTheSameBytesAndAnotherSeedAnotherScene) {
  GeneratorOptions o = crowd();
  const std::string first = generateScene(o).dump();
  EXPECT_EQ(generateScene(o).dump(), first);
  o.seed = 4;
  EXPECT_NE(generateScene(o).dump(), first);
}

TEST(GenerateScene, AnotherNumberOfCamerasKeepsTheTargets) {
  GeneratorOptions o = crowd();
  const nlohmann::json few = generateScene(o);
  o.cameras = 20;
  const nlohmann::json more = generateScene(o);
  EXPECT_EQ(few["targets"], more["targets"]);
  EXPECT_NE(few["cameras"], more["cameras"]);
}

TEST(GenerateScene, HasTheCountsLimitsAndFieldAskedFor) {
  GeneratorOptions o = crowd();
  o.vertices = 7;
  o.cameraSpeed = 3.0;
  o.cameraTurnRate = 1.5;
  o.cameraHalfFovDeg = 25.0;
  const Scene s = load(o);
  EXPECT_EQ(s.targets.size(), 40u);
  EXPECT_EQ(s.cameras.size(), 12u);
  EXPECT_TRUE(s.obstacles.empty());
  EXPECT_FALSE(s.description.empty());
  for (const auto& t : s.targets) {
    EXPECT_EQ(t.shape.size(), 7u);
    EXPECT_EQ(t.path.size(), 4u);
    EXPECT_DOUBLE_EQ(t.velocity, 0.7);
    EXPECT_NEAR(geometry::perimeter(t.path), 4 * 1.5, 4e-3);  // a square, to the mm
  }
  for (const auto& c : s.cameras) {
    EXPECT_DOUBLE_EQ(c.maxVelocity, 3.0);
    EXPECT_DOUBLE_EQ(c.maxAngularVelocity, 1.5);
    EXPECT_DOUBLE_EQ(c.lens.halfFov, geometry::degToRad(25.0));
  }
  const geometry::Box field = geometry::boundingBox(s.boundary);
  EXPECT_EQ(s.boundary.size(), 4u);
  EXPECT_DOUBLE_EQ(field.min.x, -20.0);
  EXPECT_DOUBLE_EQ(field.max.y, 15.0);
  o.description = "my crowd";
  EXPECT_EQ(load(o).description, "my crowd");
}

TEST(GenerateScene, RectanglesHaveExactlyTheBoundingBoxAskedFor) {
  GeneratorOptions o = crowd();
  o.vertices = 4;
  o.targetLength = 0.6;
  o.targetWidth = 0.4;
  for (const auto& t : load(o).targets) {
    ASSERT_EQ(t.shape.size(), 4u);
    for (const Vec2 p : t.shape) {  // every corner on the box: axis-aligned
      EXPECT_EQ(std::abs(p.x), 0.3);
      EXPECT_EQ(std::abs(p.y), 0.2);
    }
    const geometry::Box box = geometry::boundingBox(t.shape);
    EXPECT_EQ(box.max.x - box.min.x, 0.6);
    EXPECT_EQ(box.max.y - box.min.y, 0.4);
  }
}

TEST(GenerateScene, EveryPolygonSpansTheBoundingBoxAskedFor) {
  GeneratorOptions o;
  o.targets = 1;
  o.targetLength = 2.5;
  o.targetWidth = 1.5;
  for (const int v : {3, 5, 6, 17, 4000}) {
    SCOPED_TRACE(v);
    o.vertices = v;
    const Scene s = load(o);
    ASSERT_EQ(s.targets[0].shape.size(), static_cast<std::size_t>(v));
    const geometry::Box box = geometry::boundingBox(s.targets[0].shape);
    EXPECT_NEAR(box.max.x - box.min.x, 2.5, 1e-12);
    EXPECT_NEAR(box.max.y - box.min.y, 1.5, 1e-12);
    EXPECT_NEAR(box.max.x + box.min.x, 0.0, 1e-12);  // about the reference point
    EXPECT_NEAR(box.max.y + box.min.y, 0.0, 1e-12);
  }
}

// Over one lap of each loop (they differ only by rounding), sampled finely.
TEST(GenerateScene, CamerasKeepTheClearanceFromEveryTargetAtEveryTimeAndTargetsNeverMeet) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    GeneratorOptions o = crowd();
    o.seed = seed;
    o.clearance = 1.5;
    const Scene s = load(o);
    const kinematics::Kinematics k(s);
    const geometry::Box field = geometry::boundingBox(s.boundary);
    for (const auto& c : s.cameras) {
      const Vec2 p = c.initial.position();
      EXPECT_GE(
          std::min({p.x - field.min.x, field.max.x - p.x, p.y - field.min.y, field.max.y - p.y}),
          1.5);
    }
    double lap = 0.0;
    for (const auto& t : s.targets)
      lap = std::max(lap, geometry::perimeter(t.path) / t.velocity);
    kinematics::World w;
    for (int step = 0; step <= 400; ++step) {
      k.worldAt(lap * step / 400, w);
      for (std::size_t i = 0; i < w.targets.size(); ++i) {
        for (const auto& c : s.cameras)
          ASSERT_GE(geometry::distanceToPolygon(w.targets[i], c.initial.position()), 1.5);
        for (const Vec2 p : w.targets[i]) {
          ASSERT_GE(std::min({p.x - field.min.x, field.max.x - p.x, p.y - field.min.y,
                              field.max.y - p.y}),
                    1.5);
        }
        for (std::size_t j = i + 1; j < w.targets.size(); ++j)
          ASSERT_GT(geometry::distanceBetweenPolygons(w.targets[i], w.targets[j]), 0.0);
      }
    }
    for (std::size_t a = 0; a < s.cameras.size(); ++a) {
      for (std::size_t b = a + 1; b < s.cameras.size(); ++b) {
        EXPECT_GE(
            geometry::distance(s.cameras[a].initial.position(), s.cameras[b].initial.position()),
            1.5);
      }
    }
  }
}

TEST(GenerateScene, LoopSizeZeroMakesStaticTargets) {
  GeneratorOptions o = crowd();
  o.loopSize = 0.0;
  const nlohmann::json j = generateScene(o);
  EXPECT_FALSE(j["targets"][0].contains("velocity"));
  for (const auto& t : load(o).targets)
    EXPECT_TRUE(t.isStatic());
}

TEST(GenerateScene, BadOptionsAreInputErrors) {
  const std::vector<std::pair<const char*, std::function<void(GeneratorOptions&)>>> bad{
      {"no targets", [](auto& o) { o.targets = 0; }},
      {"too many targets", [](auto& o) { o.targets = 10001; }},
      {"no cameras", [](auto& o) { o.cameras = 0; }},
      {"129 cameras", [](auto& o) { o.cameras = 129; }},
      {"2 vertices", [](auto& o) { o.vertices = 2; }},
      {"too many vertices", [](auto& o) { o.vertices = 100001; }},
      {"field width 0", [](auto& o) { o.fieldWidth = 0.0; }},
      {"field height NaN", [](auto& o) { o.fieldHeight = std::nan(""); }},
      {"target length < 0", [](auto& o) { o.targetLength = -1.0; }},
      {"target width infinite",
       [](auto& o) { o.targetWidth = std::numeric_limits<double>::infinity(); }},
      {"negative loop", [](auto& o) { o.loopSize = -1.0; }},
      {"target speed 0", [](auto& o) { o.targetSpeed = 0.0; }},
      {"camera speed 0", [](auto& o) { o.cameraSpeed = 0.0; }},
      {"turn rate < 0", [](auto& o) { o.cameraTurnRate = -1.0; }},
      {"fov 0", [](auto& o) { o.cameraHalfFovDeg = 0.0; }},
      {"fov 180", [](auto& o) { o.cameraHalfFovDeg = 180.0; }},
      {"negative clearance", [](auto& o) { o.clearance = -0.5; }},
      {"field smaller than a target", [](auto& o) { o.fieldWidth = 3.0; }},
      {"edges under 10 µm",
       [](auto& o) {
         o.vertices = 100000;
         o.targetLength = 0.1;
       }},
  };
  for (const auto& [what, change] : bad) {
    SCOPED_TRACE(what);
    GeneratorOptions o;
    change(o);
    EXPECT_THROW(generateScene(o), InputError);
  }
}

TEST(GenerateScene, AFieldTooCrowdedIsAnInputErrorSayingSo) {
  GeneratorOptions targets;
  targets.targets = 200;  // regions of radius 2.1 m: at most ~50 fit in 30 x 30 m
  GeneratorOptions cameras;
  cameras.cameras = 64;  // 10 m apart in 30 x 30 m: at most 9 fit
  cameras.clearance = 10.0;
  cameras.targets = 1;
  cameras.loopSize = 0.0;
  for (const GeneratorOptions& o : {targets, cameras}) {
    try {
      generateScene(o);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("too crowded"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace camcov::scene
