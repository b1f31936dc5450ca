// What the report reads: the scene groups, the runs folded into per-seed values and bands,
// and the scene drawings of Fig. 3.
#include <gtest/gtest.h>

#include <limits>

#include "report_fixture.h"
#include "reports/report_data.h"
#include "reports/scene_gallery.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace camcov::reports {
namespace {

namespace fs = std::filesystem;
using testing::countOf;

TEST(SceneGroups, PublishedNamesOrWhetherAnythingMoves) {
  EXPECT_EQ(sceneGroup("static7", nullptr), SceneGroup::Static);
  EXPECT_EQ(sceneGroup("dynamic9", nullptr), SceneGroup::Dynamic);
  EXPECT_EQ(sceneGroup("crowd", nullptr), SceneGroup::Other);
  const auto still = scene::loadScene(testing::testDataDir() / "scenes" / "tiny_static.json");
  const auto moving = scene::loadScene(testing::testDataDir() / "scenes" / "tiny_dynamic.json");
  EXPECT_EQ(sceneGroup("tiny_static", &still), SceneGroup::Static);
  EXPECT_EQ(sceneGroup("tiny_dynamic", &moving), SceneGroup::Dynamic);
  EXPECT_EQ(sceneGroup("static_but_named", &moving), SceneGroup::Static) << "names win";
}

TEST(SceneSvg, DrawsBoundaryObjectsPathsAndCamerasWithSpeeds) {
  const auto s = scene::loadScene(testing::testDataDir() / "scenes" / "tiny_dynamic.json");
  const std::string svg = sceneSvg(s);
  EXPECT_EQ(svg.rfind("<svg class=\"scene\"", 0), 0u);
  EXPECT_EQ(countOf(svg, "class=\"boundary\""), 1);
  EXPECT_EQ(countOf(svg, "class=\"target\""), 1);
  EXPECT_EQ(countOf(svg, "class=\"path\""), 1) << "the target shuttles";
  EXPECT_EQ(countOf(svg, "class=\"camera\""), 1);
  EXPECT_NE(svg.find(">1.5 m/s<"), std::string::npos) << "the target's speed";
  EXPECT_NE(svg.find(">cam 0 · 1 m/s · 0.5 rad/s · 0°<"), std::string::npos)
      << "number, v_max, γ̇_max, heading";

  const auto still = scene::loadScene(testing::testDataDir() / "scenes" / "tiny_static.json");
  const std::string stillSvg = sceneSvg(still);
  EXPECT_EQ(countOf(stillSvg, "class=\"path\""), 0) << "static objects have no path";
  EXPECT_EQ(countOf(stillSvg, "class=\"obstacle\""), 1);
  EXPECT_EQ(countOf(stillSvg, "class=\"camera\""), 2);
  EXPECT_EQ(countOf(stillSvg, "class=\"view\""), 2);
}

TEST(ReportData, FoldsEverySeedAndKeepsTheMedianRun) {
  const testing::ScratchDir dir;
  ASSERT_EQ(testing::benchFixture(dir / "results", "--no-report").exitCode, 0);
  const ReportData data = loadReportData(dir / "results", dir / "results" / "report.html");
  EXPECT_EQ(data.manifest.seeds, 3u);
  ASSERT_EQ(data.scenes.size(), 2u);
  EXPECT_EQ(data.scenes[0].name, "tiny_dynamic");
  EXPECT_EQ(data.scenes[0].group, SceneGroup::Dynamic);
  EXPECT_EQ(data.scenes[1].group, SceneGroup::Static);
  for (const auto& scene : data.scenes) {
    ASSERT_TRUE(scene.scene.has_value()) << scene.sceneNote;
    EXPECT_EQ(scene.sceneNote, "");
    ASSERT_EQ(scene.methods.size(), 3u) << "paper, local and ours";
    for (const auto& [method, runs] : scene.methods) {
      EXPECT_EQ(runs.averageCoverage.size(), 3u) << scene.name << " " << method;
      EXPECT_EQ(runs.time.size(), 21u) << "2 s at dt = 0.1 s, t = 0 included";
      for (const SeriesBand* band : {&runs.coverage, &runs.utilization}) {
        ASSERT_EQ(band->median.size(), runs.time.size());
        ASSERT_EQ(band->min.size(), runs.time.size());
        for (std::size_t k = 0; k < runs.time.size(); ++k) {
          EXPECT_LE(band->min[k], band->median[k]);
          EXPECT_GE(band->max[k], band->median[k]);
        }
      }
      for (const auto& e : runs.events)
        EXPECT_TRUE(e.path.empty()) << "paths are dropped";
    }
  }
  EXPECT_TRUE(data.videos.empty());
}

TEST(ReportData, AMissingSceneFileIsANoteNotAnError) {
  const testing::ScratchDir dir;
  fs::copy(testing::testDataDir() / "scenes", dir / "scenes");
  ASSERT_EQ(testing::runCamcov("bench --scenes " + (dir / "scenes").string() +
                               " --seeds 1 --duration 0.5 --set global.K=30 --no-report --out " +
                               (dir / "results").string())
                .exitCode,
            0);
  fs::remove(dir / "scenes" / "tiny_static.json");
  const ReportData data = loadReportData(dir / "results", dir / "report.html");
  ASSERT_EQ(data.scenes.size(), 2u);
  EXPECT_FALSE(data.scenes[1].scene.has_value());
  EXPECT_NE(data.scenes[1].sceneNote.find("not found"), std::string::npos);
  EXPECT_EQ(data.scenes[1].group, SceneGroup::Other);
  EXPECT_THROW(loadReportData(dir / "scenes", dir / "report.html"), InputError);
}

}  // namespace
}  // namespace camcov::reports
