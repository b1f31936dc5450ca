// The speeds a frame writes beside the objects' paths touch nothing: not each other, a wall,
// an object, a path or a camera, in frames of every published scene and every scene of ours at
// several instants. Checked with the tests' own geometry (support/label_checks.h), which a
// planted collision shows can fail.
#include <gtest/gtest.h>

#include <cairo.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_loader.h"
#include "support/label_checks.h"
#include "support/test_paths.h"
#include "viz/frame_drawing.h"
#include "viz/path_labels.h"

namespace camcov::viz {
namespace {

namespace fs = std::filesystem;
using geometry::Box;
using geometry::Vec2;

struct PlacedFrame {
  Frame frame;
  FrameLayout layout;
  std::vector<PathLabel> labels;
};

PlacedFrame placedFrame(const scene::Scene& s, double time) {
  PlacedFrame out;
  std::vector<geometry::Pose> poses;
  for (const auto& c : s.cameras)
    poses.push_back(c.initial);
  FrameBuilder(s).build(time, poses, out.frame);
  out.layout = layoutFor(out.frame, 1280, 720);
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1280, 720));
  Context cr(cairo_create(surface.get()));
  const Painter painter(cr.get(), out.layout.toImage, out.layout.em);
  out.labels = placePathLabels(painter, out.frame, out.layout.worldArea);
  return out;
}

std::vector<Vec2> image(const FrameLayout& layout, const std::vector<Vec2>& world) {
  std::vector<Vec2> out;
  for (const Vec2 p : world)
    out.push_back(layout.toImage(p));
  return out;
}

// "label '1 m/s' meets a wall", one line per collision.
std::vector<std::string> collisions(const PlacedFrame& f) {
  const FrameLayout& l = f.layout;
  const PixelRect& area = l.worldArea;
  std::vector<std::string> out;
  for (std::size_t i = 0; i < f.labels.size(); ++i) {
    const Box& b = f.labels[i].box;
    const auto report = [&](const std::string& what) {
      out.push_back("label '" + f.labels[i].text + "' " + what);
    };
    if (b.min.x < area.x || b.min.y < area.y || b.max.x > area.x + area.width ||
        b.max.y > area.y + area.height)
      report("sticks out of the world's area");
    for (std::size_t k = i + 1; k < f.labels.size(); ++k) {
      if (testing::boxesTouch(b, f.labels[k].box))
        report("overlaps label '" + f.labels[k].text + "'");
    }
    if (testing::boxMeetsLine(b, image(l, f.frame.world.boundary), true)) report("meets a wall");
    for (const auto* rings : {&f.frame.world.obstacles, &f.frame.world.targets}) {
      for (const auto& ring : *rings) {
        if (testing::boxMeetsArea(b, image(l, ring))) report("meets an object");
      }
    }
    for (std::size_t k = 0; k < f.frame.paths.size(); ++k) {
      if (testing::boxMeetsLine(b, image(l, f.frame.paths[k].waypoints), true))
        report("meets path " + std::to_string(k));
    }
    for (std::size_t j = 0; j < f.frame.cameras.size(); ++j) {
      // The marker: a disc of 0.6 em and a nose to 1.3 em from the camera.
      if (testing::boxMeetsDisc(b, l.toImage(f.frame.cameras[j].pose.position()), 1.3 * l.em))
        report("meets camera " + std::to_string(j));
    }
  }
  return out;
}

void expectNoCollisions(const std::vector<fs::path>& files) {
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    const scene::Scene s = scene::loadScene(file);
    for (const double time : {0.0, 5.0, 10.0}) {
      const PlacedFrame f = placedFrame(s, time);
      const auto found = collisions(f);
      EXPECT_TRUE(found.empty()) << file.filename() << " at t = " << time << ":\n  "
                                 << found.front();
    }
  }
}

TEST(PathLabels, TouchNothingInFramesOfThePublishedScenes) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  expectNoCollisions(testing::jsonFilesIn(testing::publishedScenesDir()));
}

TEST(PathLabels, TouchNothingInFramesOfOurOwnScenes) {
  expectNoCollisions(testing::jsonFilesIn(testing::ownScenesDir()));
}

TEST(PathLabels, AreWrittenBesideTheirPathsWhereThereIsRoom) {
  // dynamic_loops_speeds: four loops in an uncrowded room, each labelled with its speed.
  const PlacedFrame f =
      placedFrame(scene::loadScene(testing::ownScenesDir() / "dynamic_loops_speeds.json"), 0.0);
  ASSERT_EQ(f.labels.size(), f.frame.paths.size());
  for (const PathLabel& label : f.labels) {
    EXPECT_EQ(label.text, f.frame.paths[label.path].speedLabel());
    const Vec2 centre = (label.box.min + label.box.max) * 0.5;
    EXPECT_LT(
        geometry::distanceToBoundary(image(f.layout, f.frame.paths[label.path].waypoints), centre),
        3.5 * f.layout.em)
        << label.text << " is far from its path";
  }
}

TEST(PathLabels, TheCheckCatchesALabelOnAnotherAndOnItsObject) {
  PlacedFrame f =
      placedFrame(scene::loadScene(testing::ownScenesDir() / "dynamic_loops_speeds.json"), 0.0);
  ASSERT_TRUE(collisions(f).empty());
  ASSERT_GE(f.labels.size(), 2u);
  f.labels[1].box = f.labels[0].box;  // two labels at one spot
  EXPECT_FALSE(collisions(f).empty());
  f.labels.resize(1);
  const Vec2 object = f.layout.toImage(f.frame.world.targets[0][0]);
  f.labels[0].box = {object - Vec2{20.0, 6.0}, object + Vec2{20.0, 6.0}};
  const auto found = collisions(f);
  EXPECT_TRUE(std::any_of(found.begin(), found.end(), [](const std::string& s) {
    return s.find("meets an object") != std::string::npos;
  })) << found.size();
}

}  // namespace
}  // namespace camcov::viz
