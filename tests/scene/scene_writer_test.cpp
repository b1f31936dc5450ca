// The writer against the loader, the independent reader of the same format: everything a
// written scene holds reads back as written (rings, paths, tracks, deformations, colours, the
// pitch, cameras), and the forms are the published files' (rings open).
#include "scene/scene_writer.h"

#include <gtest/gtest.h>

#include <numbers>

#include "scene/scene_loader.h"

namespace camcov::scene {
namespace {

using geometry::Vec2;

MovingObject still(geometry::Ring shape, Vec2 at) {
  MovingObject o;
  o.shape = std::move(shape);
  o.path = {at};
  return o;
}

WrittenScene everyKind() {
  WrittenScene w;
  w.description = "one of each";
  w.boundary = {{0, 0}, {40, 0}, {40, 30}, {0, 30}};
  w.pitch = Pitch{40, 30};
  w.halfFovDegrees = 25;
  const geometry::Ring square{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  w.targets.push_back(still(square, {5, 5}));
  MovingObject looping = still(square, {10, 10});
  looping.path = {{10, 10}, {14, 10}, {14, 13.25}};
  looping.velocity = 0.75;
  looping.angularVelocity = -0.125;
  looping.color = "#a01020";
  w.targets.push_back(looping);
  MovingObject deforming = still(square, {20, 20});
  deforming.deformation = Deformation{4.0, {{1.5, {{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}}}}};
  w.targets.push_back(deforming);
  MovingObject walking = still(square, {3, 4});
  walking.track = Track{{0.0, 0.4, 0.8}, {{3, 4}, {3.5, 4}, {4, 4.25}}, {}};
  w.obstacles.push_back(walking);
  w.obstacles.push_back(still({{30, 2}, {32, 2}, {32, 4}, {30, 4}}, {0, 0}));
  w.cameras.push_back(cameraEntry({1, 29}, -45.0, 1.5, 0.5));
  w.cameras.push_back(cameraEntry({39, 1}, 135.0, 2.0, 1.0));
  return w;
}

TEST(SceneWriter, WritesRingsOpenAsThePublishedFilesDo) {
  EXPECT_EQ(wktPolygon(std::vector<Vec2>{{0, 0}, {1.5, 0}, {0, -2}}), "POLYGON((0 0,1.5 0,0 -2))");
  EXPECT_EQ(wktPolygon(std::vector<Vec2>{{3, 4}}), "POLYGON((3 4))");
  EXPECT_EQ(wktPoint({0.1, 1e-7}), "POINT(0.1 1e-07)");
}

TEST(SceneWriter, EveryPartReadsBackAsWritten) {
  const WrittenScene w = everyKind();
  const Scene s = parseScene(sceneJson(w).dump(), "every_kind.json");
  EXPECT_EQ(s.description, w.description);
  EXPECT_EQ(s.boundary, w.boundary);  // written counter-clockwise: kept as it is
  ASSERT_TRUE(s.pitch.has_value());
  EXPECT_EQ(s.pitch->length, 40);
  ASSERT_EQ(s.targets.size(), 3u);
  EXPECT_EQ(s.targets[0].path, w.targets[0].path);
  EXPECT_TRUE(s.targets[0].isStatic());
  EXPECT_EQ(s.targets[1].path, w.targets[1].path);
  EXPECT_EQ(s.targets[1].velocity, 0.75);
  EXPECT_EQ(s.targets[1].angularVelocity, -0.125);
  EXPECT_EQ(s.targets[1].color, "#a01020");
  ASSERT_TRUE(s.targets[2].deformation.has_value());
  EXPECT_EQ(s.targets[2].deformation->period, 4.0);
  EXPECT_EQ(s.targets[2].deformation->keyframes[0].time, 1.5);
  EXPECT_EQ(s.targets[2].deformation->keyframes[0].shape,
            w.targets[2].deformation->keyframes[0].shape);
  ASSERT_EQ(s.obstacles.size(), 2u);
  ASSERT_TRUE(s.obstacles[0].track.has_value());
  EXPECT_EQ(s.obstacles[0].track->times, w.obstacles[0].track->times);
  EXPECT_EQ(s.obstacles[0].track->positions, w.obstacles[0].track->positions);
  EXPECT_EQ(s.obstacles[1].shape, w.obstacles[1].shape);
  ASSERT_EQ(s.cameras.size(), 2u);
  EXPECT_EQ(s.cameras[0].initial.position(), (Vec2{1, 29}));
  EXPECT_DOUBLE_EQ(s.cameras[0].initial.yaw, -std::numbers::pi / 4);
  EXPECT_DOUBLE_EQ(s.cameras[1].initial.yaw, 3 * std::numbers::pi / 4);
  EXPECT_EQ(s.cameras[1].maxVelocity, 2.0);
  EXPECT_EQ(s.cameras[1].maxAngularVelocity, 1.0);
  for (const CameraSpec& c : s.cameras)
    EXPECT_DOUBLE_EQ(c.lens.halfFov, 25 * std::numbers::pi / 180);
}

TEST(SceneWriter, ATrackWithHeadingsWritesThemInDegrees) {
  WrittenScene w = everyKind();
  w.obstacles[0].track->headings = {0.0, std::numbers::pi / 2, -std::numbers::pi / 4};
  const nlohmann::json j = sceneJson(w);
  EXPECT_DOUBLE_EQ(j["obstacles"][0]["track"]["samples"][1][3].get<double>(), 90.0);
  const Scene s = parseScene(j.dump(), "headings.json");
  ASSERT_EQ(s.obstacles[0].track->headings.size(), 3u);
  EXPECT_DOUBLE_EQ(s.obstacles[0].track->headings[2], -std::numbers::pi / 4);
}

TEST(SceneWriter, ACameraModelReadsBackAsWritten) {
  WrittenScene w = everyKind();
  w.resolution = ResolutionRequirement{62.5, true};
  for (CameraEntry& c : w.cameras) {
    c[CameraKeyId::sensingRange] = 35.25;
    c[CameraKeyId::imageWidth] = 1920;
  }
  const Scene s = parseScene(sceneJson(w).dump(), "camera_model.json");
  ASSERT_TRUE(s.resolution.has_value());
  EXPECT_EQ(s.resolution->minDensity, 62.5);
  EXPECT_TRUE(s.resolution->proportional);
  for (const CameraSpec& c : s.cameras) {
    EXPECT_EQ(c.lens.range, 35.25);
    EXPECT_EQ(c.lens.imageWidth, 1920);
    EXPECT_DOUBLE_EQ(c.lens.pixelsPerRadian(), 1920 / (50 * std::numbers::pi / 180));
  }
}

}  // namespace
}  // namespace camcov::scene
