#include "scene/scene_loader.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <regex>

#include "geometry/ring.h"
#include "kinematics/kinematics.h"
#include "scene/motion_containment.h"
#include "scene/scene_error.h"
#include "support/test_paths.h"
#include "util/fnv1a.h"

namespace camcov::scene {
namespace {

using geometry::Vec2;

TEST(LoadScene, LoadsEveryPublishedScene) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const auto files = testing::jsonFilesIn(testing::publishedScenesDir());
  EXPECT_EQ(files.size(), 32u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const Scene s = loadScene(file);
    EXPECT_EQ(s.name, file.stem().string());
    EXPECT_GT(geometry::signedArea(s.boundary), 0.0);
    for (const auto& t : s.targets)
      EXPECT_GT(geometry::signedArea(t.shape), 0.0);
    // Only dynamic9's triangle pokes out of its room (by 1 m at (14 14)): a warning.
    if (s.name == "dynamic9") {
      ASSERT_EQ(s.warnings.size(), 1u);
      EXPECT_NE(s.warnings[0].find("targets[3]: leaves the boundary"), std::string::npos)
          << s.warnings[0];
      EXPECT_NE(s.warnings[0].find("lies 1 m outside"), std::string::npos) << s.warnings[0];
    } else {
      EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    }
  }
}

TEST(LoadScene, LoadsEveryOwnScene) {
  const auto files = testing::jsonFilesIn(testing::ownScenesDir());
  EXPECT_GE(files.size(), 12u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    EXPECT_TRUE(loadScene(file).warnings.empty()) << "every object stays in its room";
  }
}

// The published names say which scenes hold still; holdsStill must agree with every one, and
// a recorded scene (its people come and go) never holds still.
TEST(Scene, HoldsStillExactlyWhenNothingMovesTurnsDeformsOrComesAndGoes) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  for (const auto& file : testing::jsonFilesIn(testing::publishedScenesDir())) {
    SCOPED_TRACE(file.string());
    EXPECT_EQ(loadScene(file).holdsStill(), file.stem().string().starts_with("static"));
  }
  EXPECT_FALSE(
      loadScene(testing::testDataDir() / "scenes_tracks" / "comes_and_goes.json").holdsStill());
  Scene turning = loadScene(testing::testDataDir() / "scenes" / "tiny_static.json");
  ASSERT_TRUE(turning.holdsStill());
  turning.targets.at(0).angularVelocity = 0.1;
  EXPECT_FALSE(turning.holdsStill());
}

TEST(LoadSceneFile, FingerprintsTheFilesBytesSoAnyEditChangesIt) {
  const auto dir = std::filesystem::temp_directory_path() / "camcov-scene-file";
  std::filesystem::create_directories(dir);
  const auto source = testing::ownScenesDir() / "fig1_example.json";
  const SceneFile original = loadSceneFile(source);
  EXPECT_EQ(original.scene.name, "fig1_example");
  // FNV-1a 64, checked against its published test vectors.
  EXPECT_EQ(fnv1a(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a("foobar"), 0x85944171f73967e8ull);
  // The same bytes elsewhere: the same fingerprint; one more space: another.
  std::filesystem::copy_file(source, dir / "fig1_example.json",
                             std::filesystem::copy_options::overwrite_existing);
  EXPECT_EQ(loadSceneFile(dir / "fig1_example.json").hash, original.hash);
  { std::ofstream(dir / "fig1_example.json", std::ios::app) << " "; }
  EXPECT_NE(loadSceneFile(dir / "fig1_example.json").hash, original.hash);
  // The hash alone is the reading's, and needs no valid scene.
  EXPECT_EQ(sceneFileHash(source), original.hash);
  { std::ofstream(dir / "broken.json") << "foobar"; }
  EXPECT_EQ(sceneFileHash(dir / "broken.json"), fnv1a("foobar"));
  std::filesystem::remove_all(dir);
}

TEST(LoadScene, NormalisesClockwiseShapesAndAppliesDefaults) {
  // Published static1 writes its triangle clockwise; the defaults fill velocity.
  const Scene s = parseScene(R"js({
    "boundary": "POLYGON((-15 -15,15 -15,15 15,-15 15))",
    "targets": [{"shape": "POLYGON((-2 -1,2 1,2 -1))", "path": "POLYGON((0 0))"}],
    "obstacles": [],
    "cameraFoV": 30,
    "cameras": [{"pos": "POINT(0 -10)", "angle": 310, "maxVelocity": 2.0,
                 "maxAngularVelocity": 1.0}]})js",
                             "static_like.json");
  EXPECT_EQ(s.name, "static_like");
  ASSERT_EQ(s.targets.size(), 1u);
  const auto& shape = s.targets[0].shape;
  ASSERT_EQ(shape.size(), 3u);
  EXPECT_DOUBLE_EQ(geometry::signedArea(shape), 4.0);
  EXPECT_EQ(s.targets[0].velocity, 1.0);
  EXPECT_EQ(s.targets[0].angularVelocity, 0.0);
  EXPECT_TRUE(s.targets[0].isStatic());
  for (const auto& c : s.cameras)
    EXPECT_NEAR(c.lens.halfFov, std::numbers::pi / 6, 1e-15);
  EXPECT_NEAR(s.cameras[0].initial.yaw, -50.0 * std::numbers::pi / 180.0, 1e-12);  // 310° wraps
  EXPECT_TRUE(s.obstacles.empty());
}

TEST(LoadScene, ACamerasOwnFieldOfViewOverridesTheScenes) {
  const Scene s = parseScene(R"js({
    "boundary": "POLYGON((-5 -5,5 -5,5 5,-5 5))",
    "targets": [{"shape": "POLYGON((0 0,1 0,1 1,0 1))", "path": "POLYGON((0 0))"}],
    "cameraFoV": 30,
    "cameras": [{"pos": "POINT(-4 -4)", "angle": 45, "maxVelocity": 1, "maxAngularVelocity": 1},
                {"pos": "POINT(4 -4)", "angle": 135, "maxVelocity": 1, "maxAngularVelocity": 1,
                 "cameraFoV": 60}]})js",
                             "unlike.json");
  EXPECT_NEAR(s.cameras[0].lens.halfFov, std::numbers::pi / 6, 1e-15);
  EXPECT_NEAR(s.cameras[1].lens.halfFov, std::numbers::pi / 3, 1e-15);
  EXPECT_EQ(lenses(s), (std::vector<Lens>{s.cameras[0].lens, s.cameras[1].lens}));
}

TEST(LoadScene, ObstaclesKeyIsOptionalAndDescriptionIsKept) {
  const Scene s = parseScene(R"js({
    "description": "one square",
    "boundary": "POLYGON((-5 -5,5 -5,5 5,-5 5))",
    "targets": [{"shape": "POLYGON((0 0,1 0,1 1,0 1))", "path": "POLYGON((0 0))"}],
    "cameraFoV": 45,
    "cameras": [{"pos": "POINT(-4 -4)", "angle": 45, "maxVelocity": 1, "maxAngularVelocity": 1}]})js",
                             "x.json");
  EXPECT_EQ(s.description, "one square");
  EXPECT_TRUE(s.obstacles.empty());
}

TEST(LoadScene, CameraOnTheBoundaryOrOnAnObjectEdgeIsAllowed) {
  EXPECT_NO_THROW(parseScene(R"js({
    "boundary": "POLYGON((-5 -5,5 -5,5 5,-5 5))",
    "targets": [{"shape": "POLYGON((0 0,1 0,1 1,0 1))", "path": "POLYGON((0 0))"}],
    "cameraFoV": 30,
    "cameras": [{"pos": "POINT(-5 0)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1},
                {"pos": "POINT(0.5 0)", "angle": -90, "maxVelocity": 1, "maxAngularVelocity": 1}]})js",
                             "edge.json"));
}

TEST(LoadScene, MissingFileIsAnInputErrorNamingTheFile) {
  try {
    loadScene("/nonexistent/scene.json");
    FAIL() << "expected SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.json"), std::string::npos);
  }
}

// Loading is near-linear in the file's size: 100,000 keyframes or a 100,000-vertex boundary
// load in well under a second here (docs/reliability.md); a quadratic step would take a
// minute. The bound is generous for the sanitizer build and a busy machine: it catches the
// quadratic, not a slow day.
TEST(SceneLoader, HundredThousandKeyframesAndBoundaryVerticesLoadInLinearTime) {
  constexpr int kCount = 100000;
  std::string keyframes;
  for (int k = 1; k <= kCount; ++k) {
    keyframes += fmt::format("{}{{\"time\": {}, \"shape\": \"POLYGON((0 0,1 0,1 {},0 1))\"}}",
                             k == 1 ? "" : ",", k, 1 + k % 2);
  }
  std::string boundary;
  for (int k = 0; k < kCount; ++k) {
    const double a = 2 * std::numbers::pi * k / kCount;
    boundary +=
        fmt::format("{}{:.6f} {:.6f}", k == 0 ? "" : ",", 1000 * std::cos(a), 1000 * std::sin(a));
  }
  const auto scene = [](const std::string& boundaryWkt, const std::string& deformation) {
    return R"js({"boundary": "POLYGON(()js" + boundaryWkt + R"js())",
      "targets": [{"shape": "POLYGON((0 0,1 0,1 1,0 1))", "path": "POLYGON((0 0))")js" +
           deformation + R"js(}],
      "cameraFoV": 45,
      "cameras": [{"pos": "POINT(-4 -4)", "angle": 45, "maxVelocity": 1, "maxAngularVelocity": 1}]})js";
  };
  const auto seconds = [](const std::string& text) {
    const auto start = std::chrono::steady_clock::now();
    const Scene s = parseScene(text, "big.json");
    EXPECT_FALSE(s.targets.empty());
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  EXPECT_LT(seconds(scene("-5 -5,5 -5,5 5,-5 5",
                          ", \"deformation\": {\"period\": " + std::to_string(kCount + 1) +
                              ", \"keyframes\": [" + keyframes + "]}")),
            30.0);
  EXPECT_LT(seconds(scene(boundary, "")), 30.0);
}

}  // namespace
}  // namespace camcov::scene

namespace camcov::scene {
namespace {

// A triangle that moves onto the L room's reflex corner with all three vertices still inside:
// only the corner's own trace into the object shows that the room's outside passes through it.
TEST(MotionContainment, ABoundaryCornerEnteringTheObjectIsFoundThoughNoVertexLeaves) {
  Scene scene;
  scene.boundary = geometry::Ring{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
  MovingObject o;
  o.shape =
      geometry::Ring{{0, 0}, {11, 5}, {5, 11}};  // at (1 1): its far edge x + y = 18 misses (10 10)
  o.path = std::vector<geometry::Vec2>{{1, 1}, {3, 3}};  // at (3 3): x + y = 22, past the corner
  scene.targets = {o};
  const MotionCheck check = checkMotion(scene);
  ASSERT_EQ(check.errors.size() + check.warnings.size(), 1u);
  const std::string problem =
      (check.errors.empty() ? check.warnings : check.errors).front().problem;
  EXPECT_NE(problem.find("the boundary's vertex 3 (10 10)"), std::string::npos) << problem;
}

// The whole-motion check against sampling the motion densely, on random objects shuttling in
// a non-convex room: where the check finds an object out by more than a millimetre, sampling
// must find it out too, and where sampling finds it out by more than a millimetre, so must
// the check.
TEST(MotionContainment, AgreesWithDenseSamplingOnRandomShuttles) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-2, 22), size(0.3, 9.0);
  Scene scene;
  // An L room: the reflex corner at (10 10) is where sampling and traces may disagree.
  scene.boundary = geometry::Ring{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
  int out = 0, in = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    MovingObject o;
    const double w = size(rng), h = size(rng);
    o.shape = geometry::Ring{{-w, -h}, {w, -h}, {0.3 * w, h}};
    const Vec2 from{coordinate(rng), coordinate(rng)}, to{coordinate(rng), coordinate(rng)};
    o.path = std::vector<geometry::Vec2>{from, to};
    // As the loader has it before this check: the object inside at t = 0.
    geometry::Ring start = o.shape;
    geometry::transformRing(start, 0.0, from);
    const auto within = [&](const geometry::Ring& placed) {
      for (const Vec2 v : placed)
        if (geometry::locate(scene.boundary, v) == geometry::Containment::Outside) return false;
      for (const Vec2 b : scene.boundary)
        if (geometry::locate(placed, b) == geometry::Containment::Inside) return false;
      return true;
    };
    if (!within(start)) continue;
    scene.targets = {o};
    const MotionCheck check = checkMotion(scene);
    double sampled = 0.0;  // the deepest sampled vertex outside, or boundary vertex inside
    for (int k = 0; k <= 2000; ++k) {
      const Vec2 p = from + (to - from) * (k / 2000.0);
      geometry::Ring placed = o.shape;
      geometry::transformRing(placed, 0.0, p);
      for (const Vec2 v : placed) {
        if (geometry::locate(scene.boundary, v) == geometry::Containment::Outside)
          sampled = std::max(sampled, geometry::distanceToBoundary(scene.boundary, v));
      }
      for (const Vec2 b : scene.boundary) {
        if (geometry::locate(placed, b) == geometry::Containment::Inside)
          sampled = std::max(sampled, geometry::distanceToBoundary(placed, b));
      }
    }
    const bool found = !check.errors.empty() || !check.warnings.empty();
    if (sampled > 1e-3) {
      EXPECT_TRUE(found) << "trial " << trial << ": sampled " << sampled;
    }
    if (found) {
      // The depth the check reports ("lies 0.42 m outside"): a deep one sampling must see.
      const std::string problem =
          (check.errors.empty() ? check.warnings : check.errors).front().problem;
      std::smatch m;
      ASSERT_TRUE(std::regex_search(problem, m, std::regex(R"(lies ([0-9.e+-]+) m)"))) << problem;
      if (std::stod(m[1]) > 0.05) {
        EXPECT_GT(sampled, 0.0) << "trial " << trial << ": " << problem;
      }
    }
    (found ? out : in)++;
  }
  EXPECT_GT(out, 20);
  EXPECT_GT(in, 10);
}

}  // namespace
}  // namespace camcov::scene

// Paths written as POINT (a static object) and LINESTRING (back and forth along a polyline),
// placed by the kinematics at times worked out by hand.
namespace camcov::scene {
namespace {

const Scene& pathForms() {
  static const Scene s =
      loadScene(testing::testDataDir() / "path_forms" / "shuttle_and_still.json");
  return s;
}

void expectAt(Vec2 actual, Vec2 expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-9);
  EXPECT_NEAR(actual.y, expected.y, 1e-9);
}

TEST(PathForms, APointPathIsStatic) {
  const MovingObject& still = pathForms().targets[0];
  EXPECT_EQ(still.path, (std::vector<Vec2>{{9, 5}}));
  EXPECT_TRUE(still.isStatic());
  const kinematics::Kinematics k(pathForms());
  for (double t : {0.0, 3.7, 29.9})
    expectAt(k.targetPose(0, t).reference, {9, 5});
}

TEST(PathForms, ALineStringOfTwoPointsShuttlesBetweenThem) {
  // LINESTRING(3 11,17 11) at 2 m/s: 14 m out in 7 s, 14 m back, a lap of 14 s.
  const kinematics::Kinematics k(pathForms());
  const std::pair<double, Vec2> expected[] = {{0.0, {3, 11}},  {3.5, {10, 11}},  {7.0, {17, 11}},
                                              {8.0, {15, 11}}, {10.5, {10, 11}}, {14.0, {3, 11}},
                                              {15.0, {5, 11}}};
  for (const auto& [t, where] : expected) {
    SCOPED_TRACE(t);
    expectAt(k.targetPose(1, t).reference, where);
  }
}

TEST(PathForms, ALineStringPolylineGoesOutAlongItAndBackContinuously) {
  // LINESTRING(15 3,15 7,12 7) at the default 1 m/s: 4 m up, 3 m left, then back, 14 s a lap.
  const kinematics::Kinematics k(pathForms());
  const std::pair<double, Vec2> expected[] = {{2.0, {15, 5}},  {4.0, {15, 7}}, {5.0, {14, 7}},
                                              {7.0, {12, 7}},  {9.0, {14, 7}}, {11.0, {15, 6}},
                                              {14.0, {15, 3}}, {16.0, {15, 5}}};
  for (const auto& [t, where] : expected) {
    SCOPED_TRACE(t);
    expectAt(k.obstaclePose(0, t).reference, where);
  }
  // Continuous: no step of 0.01 s moves it more than 0.01 m (turning round included).
  Vec2 before = k.obstaclePose(0, 0.0).reference;
  for (int i = 1; i <= 2800; ++i) {
    const Vec2 now = k.obstaclePose(0, i * 0.01).reference;
    EXPECT_LE(geometry::distance(before, now), 0.01 + 1e-9) << "at t = " << i * 0.01;
    before = now;
  }
}

TEST(PathForms, ATwoPointLineStringIsThePublishedTwoPointPolygon) {
  // The published format's back-and-forth ("POLYGON((a, b))") and the LINESTRING that says it.
  const auto load = [](const std::string& path) {
    const std::string text =
        R"json({"boundary": "POLYGON((-8 -8,8 -8,8 8,-8 8))", "cameraFoV": 30,
          "cameras": [{"pos": "POINT(0 -6)", "angle": 0, "maxVelocity": 1,
                       "maxAngularVelocity": 1}],
          "targets": [{"shape": "POLYGON((-1 -1,1 -1,0 1))", "path": ")json" +
        path + R"json("}]})json";
    return parseScene(text, "t.json");
  };
  EXPECT_EQ(load("LINESTRING(-4 0,4 0)").targets[0].path,
            load("POLYGON((-4 0,4 0))").targets[0].path);
  EXPECT_EQ(load("POINT(2 2)").targets[0].path, load("POLYGON((2 2))").targets[0].path);
}

}  // namespace
}  // namespace camcov::scene
