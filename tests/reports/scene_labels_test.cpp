// The labels of the scene pictures (Fig. 3) touch nothing: not each other, not the boundary,
// an object, a path, a camera or its view, on every published scene and every scene of our
// own. The check is the tests' own geometry (support/label_checks.h), not the placer's, and a
// self-check shows it catches planted collisions.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/ring.h"
#include "reports/scene_drawing.h"
#include "scene/scene_loader.h"
#include "support/label_checks.h"
#include "support/test_paths.h"

namespace camcov::reports {
namespace {

namespace fs = std::filesystem;
using geometry::Box;
using geometry::Vec2;

// "label 'cam 0 · …' meets the boundary", one line per collision.
std::vector<std::string> collisions(const SceneDrawing& d) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < d.labels.size(); ++i) {
    const Box& b = d.labels[i].box;
    const auto report = [&](const std::string& what) {
      out.push_back("label '" + d.labels[i].text() + "' " + what);
    };
    if (b.min.x < 0 || b.min.y < 0 || b.max.x > d.width || b.max.y > d.height)
      report("sticks out of the picture");
    for (std::size_t k = i + 1; k < d.labels.size(); ++k) {
      const Box& o = d.labels[k].box;
      if (testing::boxesTouch(b, o)) report("overlaps label '" + d.labels[k].text() + "'");
    }
    if (testing::boxMeetsLine(b, d.boundary, true)) report("meets the boundary");
    for (std::size_t k = 0; k < d.objects.size(); ++k) {
      if (testing::boxMeetsArea(b, d.objects[k].ring)) report("meets object " + std::to_string(k));
    }
    for (std::size_t k = 0; k < d.paths.size(); ++k) {
      if (testing::boxMeetsLine(b, d.paths[k], true)) report("meets path " + std::to_string(k));
      if (testing::boxMeetsDisc(b, d.pathStarts[k], SceneDrawing::kDotRadius))
        report("meets the start of path " + std::to_string(k));
    }
    for (std::size_t j = 0; j < d.cameras.size(); ++j) {
      const DrawnCamera& c = d.cameras[j];
      if (testing::boxMeetsArea(b, c.wedge) ||
          testing::boxMeetsDisc(b, c.at, DrawnCamera::kBodyRadius) ||
          testing::boxMeetsSegment(b, c.at, c.head))
        report("meets camera " + std::to_string(j));
    }
  }
  return out;
}

std::vector<fs::path> ownScenes() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(testing::ownScenesDir())) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void expectNoCollisions(const std::vector<fs::path>& files) {
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    const SceneDrawing d = drawScene(scene::loadScene(file));
    const auto found = collisions(d);
    EXPECT_TRUE(found.empty()) << file.filename() << ":\n  " << found.front();
    EXPECT_FALSE(d.labels.empty()) << file.filename() << ": nothing labelled at all";
  }
}

TEST(SceneLabels, TouchNothingInThePublishedScenes) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const auto files = testing::jsonFilesIn(testing::publishedScenesDir());
  EXPECT_EQ(files.size(), 32u);
  expectNoCollisions(files);
}

TEST(SceneLabels, TouchNothingInOurOwnScenes) {
  expectNoCollisions(ownScenes());
}

// Each camera's values are on the picture beside its number or listed under the picture,
// once; with `numbered`, every camera's number is on the picture even where its values are not.
void expectEveryCameraAccountedFor(const std::vector<fs::path>& files, bool numbered) {
  for (const fs::path& file : files) {
    const scene::Scene s = scene::loadScene(file);
    const SceneDrawing d = drawScene(s);
    for (std::size_t j = 0; j < s.cameras.size(); ++j) {
      const std::string name = "cam " + std::to_string(j);
      const auto withValues = [&](const std::string& text) {
        return text.rfind(name + " · ", 0) == 0;
      };
      const auto drawn = [&](const auto& pred) {
        return std::count_if(d.labels.begin(), d.labels.end(),
                             [&](const DrawnLabel& l) { return pred(l.text()); });
      };
      const auto listed = std::count_if(d.leftOut.begin(), d.leftOut.end(), withValues);
      EXPECT_EQ(drawn(withValues) + listed, 1) << file.filename() << ": " << name << "'s values";
      if (numbered) {
        EXPECT_EQ(drawn([&](const std::string& t) { return t == name || withValues(t); }), 1)
            << file.filename() << ": " << name << " on the picture";
      }
    }
  }
}

TEST(SceneLabels, EveryCameraIsNumberedOnThePictureWithItsValuesBesideItOrUnderIt) {
  expectEveryCameraAccountedFor(testing::jsonFilesIn(testing::ownScenesDir()), true);
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  expectEveryCameraAccountedFor(testing::jsonFilesIn(testing::publishedScenesDir()), true);
}

TEST(SceneLabels, CrowdedLargeScenesListWhatFindsNoRoomUnderThePicture) {
  // 30 cameras in 340 px (scenes/large): not every number fits, every value is somewhere.
  expectEveryCameraAccountedFor(ownScenes(), false);
}

TEST(SceneLabels, HeadingsReadFrom0To359Degrees) {
  EXPECT_EQ(headingDegrees(0.0), 0);
  EXPECT_EQ(headingDegrees(-3.0 * std::numbers::pi / 4.0), 225) << "not -135";
  EXPECT_EQ(headingDegrees(std::numbers::pi), 180);
  EXPECT_EQ(headingDegrees(-std::numbers::pi), 180);
  EXPECT_EQ(headingDegrees(-0.001), 0) << "rounds to 360, which is 0";
  EXPECT_EQ(headingDegrees(-std::numbers::pi / 2.0), 270);
}

TEST(SceneLabels, TheCheckCatchesPlantedCollisions) {
  const SceneDrawing good =
      drawScene(scene::loadScene(testing::testDataDir() / "scenes" / "tiny_dynamic.json"));
  ASSERT_TRUE(collisions(good).empty());
  ASSERT_GE(good.labels.size(), 2u);
  const auto movedTo = [&](Vec2 at) {
    SceneDrawing d = good;
    const Vec2 size = d.labels[0].box.max - d.labels[0].box.min;
    d.labels[0].box = {at - size * 0.5, at + size * 0.5};
    return collisions(d);
  };
  const auto mentions = [](const std::vector<std::string>& found, const std::string& what) {
    return std::any_of(found.begin(), found.end(),
                       [&](const std::string& f) { return f.find(what) != std::string::npos; });
  };
  SceneDrawing twice = good;
  twice.labels[1].box = twice.labels[0].box;  // two labels at one spot
  EXPECT_TRUE(mentions(collisions(twice), "overlaps label"));
  EXPECT_TRUE(mentions(movedTo(good.boundary[0]), "meets the boundary"));
  const Vec2 target = (good.objects.back().ring[0] + good.objects.back().ring[2]) * 0.5;
  EXPECT_TRUE(mentions(movedTo(target), "meets object"));
  EXPECT_TRUE(mentions(movedTo(good.cameras[0].at), "meets camera 0"));
  ASSERT_FALSE(good.paths.empty());
  EXPECT_TRUE(mentions(movedTo(good.pathStarts[0]), "meets path 0"));
  EXPECT_TRUE(mentions(movedTo({-5.0, -5.0}), "sticks out"));
}

}  // namespace
}  // namespace camcov::reports
