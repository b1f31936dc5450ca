#include "records/run_files.h"

#include <gtest/gtest.h>

#include <functional>

#include "util/input_error.h"

namespace camcov::records {
namespace {

RunRecord sampleRun() {
  RunRecord run;
  run.metadata = {"scene_a", "scenes/scene_a.json", 0x0123456789abcdefull, "paper", 7, {}, "9.9.9"};
  run.metadata.parameters.global.K = 123;
  run.summary.steps = 2;
  run.summary.duration = 0.1;
  run.summary.averageCoverage = 0.25;
  run.summary.minCameraDistance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    StepRow row;
    row.time = 0.1 * k;
    row.terms.coverage = row.terms.weightedCoverage = 0.2 + k * 0.1;
    row.terms.utilization = 0.5;
    row.terms.reward = 0.3;
    row.minObjectDistance = 2.5;
    row.minCameraDistance = std::numeric_limits<double>::infinity();
    row.minObjectDistanceInStep = 2.25;
    row.minCameraDistanceInStep = std::numeric_limits<double>::infinity();
    row.avoidableContactTime = 0.0;
    row.unavoidableContactTime = 0.05 * k;
    row.cameras = {{1.0, 2.0 + k, 0.5}};
    row.goals = {k ? std::optional(geometry::Pose{4, 5, 6}) : std::nullopt};
    run.steps.push_back(row);
  }
  run.events.push_back({0.0, "plan", 0, "3 waypoints", {{1, 2, 0.5}, {3, 4, 0}, {4, 5, 6}}, {}});
  run.events.push_back({0.05, "unavoidable-contact", 0, "target 0 closes fast", {}, "outpaced"});
  return run;
}

TEST(RunFiles, JsonRoundTripsEveryField) {
  const RunRecord run = sampleRun();
  const nlohmann::json j = runToJson(run);
  EXPECT_EQ(j["scene"]["hash"], "0123456789abcdef");
  EXPECT_TRUE(j["summary"]["minCameraDistance"].is_null()) << "JSON has no infinity";
  const RunRecord back = runFromJson(j, "memory");
  EXPECT_EQ(runToJson(back), j);
  EXPECT_EQ(back.metadata.parameters.global.K, 123);
  ASSERT_EQ(back.steps.size(), 2u);
  EXPECT_FALSE(back.steps[0].goals[0].has_value());
  EXPECT_EQ(*back.steps[1].goals[0], (geometry::Pose{4, 5, 6}));
  EXPECT_EQ(back.events.at(0).path.size(), 3u);
  EXPECT_EQ(back.events.at(1).reason, "outpaced");
  EXPECT_FALSE(j["events"][0].contains("reason")) << "an event without a reason has no key";
  EXPECT_EQ(back.steps[1].unavoidableContactTime, 0.05);
  EXPECT_TRUE(j["series"]["minCameraDistanceInStep"][1].is_null());
}

TEST(RunFiles, TextIsNlohmannsPrintingOfTheSameDocument) {
  // Every optional column and event field present: the streamed text has each key where
  // nlohmann's sorted objects put it, and its layout, to the byte.
  RunRecord run = sampleRun();
  run.summary.averageWeightedCoverage = 0.3;
  run.summary.averageResolutionCoverage = 0.2;
  run.summary.messages = sim::MessageCounts{3, 2, 1};
  for (StepRow& row : run.steps) {
    row.resolutionCoverage = 0.125;
    row.targetsPresent = 4;
    row.heard = {{0, 1, row.time}, {1, 0, -0.0}};
    row.cameras.push_back({-7.5, 1e-7, -3.14});
    row.goals.push_back(std::nullopt);
  }
  run.steps.back().heard.clear();
  const std::string text = runJsonText(run);
  EXPECT_EQ(text, nlohmann::json::parse(text).dump(1) + "\n");
  const nlohmann::json j = runToJson(run);
  for (const char* column : {"weightedCoverage", "resolutionCoverage", "targetsPresent", "heard"})
    EXPECT_TRUE(j["series"].contains(column)) << column;
  EXPECT_EQ(j["series"]["heard"][1], nlohmann::json::array());
  EXPECT_EQ(j["series"]["cameras"][1][0], nlohmann::json({-7.5, 1e-7, -3.14}));
}

TEST(RunFiles, CsvHasOneRowPerStepAndAColumnPerPoseComponent) {
  const std::string csv = runToCsv(sampleRun());
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "time,coverage,utilization,repulsion,reward,min_object_distance,min_camera_distance,"
            "min_object_distance_in_step,min_camera_distance_in_step,avoidable_contact_time,"
            "unavoidable_contact_time,cam0_x,cam0_y,cam0_yaw");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_NE(csv.find("0.1,0.30000000000000004,0.5,0,0.3,2.5,inf,2.25,inf,0,0.05,1,3,0.5"),
            std::string::npos)
      << csv;
}

TEST(RunFiles, AResolutionRunRecordsItsSeriesSummaryAndCsvColumn) {
  RunRecord run = sampleRun();
  run.summary.averageResolutionCoverage = 0.125;
  run.summary.finalResolutionCoverage = 0.25;
  run.steps[0].resolutionCoverage = 0.0;
  run.steps[1].resolutionCoverage = 0.25;
  const nlohmann::json j = runToJson(run);
  EXPECT_EQ(j["summary"]["averageResolutionCoverage"], 0.125);
  EXPECT_EQ(j["series"]["resolutionCoverage"], nlohmann::json::array({0.0, 0.25}));
  const RunRecord back = runFromJson(j, "memory");
  EXPECT_EQ(runToJson(back), j);
  EXPECT_EQ(back.steps[1].resolutionCoverage, 0.25);
  const std::string csv = runToCsv(run);
  EXPECT_NE(csv.find("unavoidable_contact_time,resolution_coverage,cam0_x"), std::string::npos);
  // A run without a resolution has none of it.
  EXPECT_FALSE(runToJson(sampleRun())["series"].contains("resolutionCoverage"));
  EXPECT_FALSE(runToJson(sampleRun())["summary"].contains("averageResolutionCoverage"));
}

// Each class of impossible run, as a hand edit or a cut makes it: refused naming the column
// and step, never drawn, encoded or summarized.
TEST(RunFiles, RejectsSeriesNoRunCanRecord) {
  const nlohmann::json good = runToJson(sampleRun());
  const auto refused = [&](const std::function<void(nlohmann::json&)>& edit,
                           const std::string& fragment) {
    nlohmann::json j = good;
    edit(j);
    try {
      runFromJson(j, "edited.json");
      ADD_FAILURE() << "accepted: " << fragment;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  refused([](auto& j) { j["series"]["time"][1] = 0.0; }, "series.time[1] = 0 does not come after");
  refused([](auto& j) { j["series"]["time"][1] = -0.1; }, "series.time[1] = -0.1 lies outside");
  refused([](auto& j) { j["series"]["coverage"][1] = 5; }, "series.coverage[1] = 5 lies outside");
  refused([](auto& j) { j["series"]["utilization"][0] = "a"; }, "series.utilization[0] is not a");
  refused([](auto& j) { j["series"]["cameras"][0][1][0] = 1e308; },
          "series.cameras[0][1][0] = 1e+308 lies outside");
  refused([](auto& j) { j["series"]["reward"].erase(1); }, "series.reward has 1 entries for 2");
  refused([](auto& j) { j["series"]["minObjectDistance"][0] = -1; },
          "series.minObjectDistance[0] = -1 lies outside");
  refused([](auto& j) { j["summary"]["steps"] = 3; }, "the summary says 3 steps");
  refused([](auto& j) { j["events"][0]["time"] = 7.0; }, "an event at 7 s of camera 0 lies");
  refused([](auto& j) { j["events"][0]["camera"] = 4; }, "of camera 4 lies outside");
  // A key no camcov writes (here a misspelled one) would be left unread: refused, named.
  refused([](auto& j) { j["summary"]["finalCoveHage"] = j["summary"]["finalCoverage"]; },
          "summary: unknown key \"finalCoveHage\"");
  refused([](auto& j) { j["series"]["coverages"] = j["series"]["coverage"]; },
          "series: unknown key \"coverages\"");
  refused([](auto& j) { j["scene"]["hashes"] = "0"; }, "scene: unknown key \"hashes\"");
  refused([](auto& j) { j["comment"] = "edited"; }, "the run file: unknown key \"comment\"");
}

TEST(RunFiles, ARunWrittenBeforeFinalCoverageWasRecordedReadsAndWritesBackWithout) {
  nlohmann::json old = runToJson(sampleRun());
  old["summary"].erase("finalCoverage");
  const nlohmann::json written = runToJson(runFromJson(old, "old.json"));
  EXPECT_FALSE(written["summary"].contains("finalCoverage"));
  EXPECT_EQ(written, old);
}

TEST(RunFiles, RejectsDocumentsThatAreNotRuns) {
  EXPECT_THROW(runFromJson(nlohmann::json::parse(R"({"format": "other"})"), "x"), InputError);
  EXPECT_THROW(runFromJson(nlohmann::json::parse(R"({"a": 1})"), "x"), InputError);
  EXPECT_THROW(loadRunFile("/nonexistent/run.json"), InputError);
}

TEST(RunStem, NamesSceneMethodAndSeed) {
  EXPECT_EQ(runStem(sampleRun().metadata), "scene_a-paper-seed7");
}

}  // namespace
}  // namespace camcov::records
