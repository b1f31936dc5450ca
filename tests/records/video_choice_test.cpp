#include "records/video_choice.h"

#include <gtest/gtest.h>

#include "util/input_error.h"

namespace camcov::records {
namespace {

JobOutcome finished(std::string scene, std::string method, std::uint64_t seed, double coverage) {
  JobOutcome o{std::move(scene), std::move(method), seed, false, "", {}};
  o.summary.averageCoverage = coverage;
  return o;
}

// Two scenes; on "b" the local method failed every run. Coverage falls with the seed for
// paper and rises for local, so their median seeds agree but their best ones do not.
std::vector<JobOutcome> batch() {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    jobs.push_back(finished("a", "paper", seed, 1.0 - 0.1 * static_cast<double>(seed)));
    jobs.push_back(finished("a", "local", seed, 0.1 * static_cast<double>(seed)));
    jobs.push_back(finished("b", "paper", seed, 0.5));
    jobs.push_back({"b", "local", seed, true, "boom", {}});
  }
  return jobs;
}

std::vector<VideoRun> choose(VideoChoice choice) {
  const auto jobs = batch();
  return chooseVideoRuns(summarize(jobs, "local"), jobs, choice);
}

TEST(VideoChoice, ParsesItsFourNamesAndRejectsOthers) {
  EXPECT_EQ(parseVideoChoice("none", "--videos"), VideoChoice::None);
  EXPECT_EQ(parseVideoChoice("median", "--videos"), VideoChoice::Median);
  EXPECT_EQ(parseVideoChoice("best", "--videos"), VideoChoice::Best);
  EXPECT_EQ(parseVideoChoice("all", "--videos"), VideoChoice::All);
  EXPECT_THROW(parseVideoChoice("Median", "--videos"), InputError);
  EXPECT_THROW(parseVideoChoice("", "--videos"), InputError);
  try {
    parseVideoChoice("bogus", "--explorer");
    ADD_FAILURE() << "took bogus";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--explorer bogus:", 0), 0u) << e.what();
  }
}

TEST(VideoChoice, MedianIsOneRunPerSceneAndMethodWithRunsInSummaryOrder) {
  const std::vector<VideoRun> expected{{"a", "local", 2}, {"a", "paper", 2}, {"b", "paper", 2}};
  EXPECT_EQ(choose(VideoChoice::Median), expected);
}

TEST(VideoChoice, BestIsTheHighestCoverageAndOfEqualsTheLowestSeed) {
  const std::vector<VideoRun> expected{{"a", "local", 3}, {"a", "paper", 1}, {"b", "paper", 1}};
  EXPECT_EQ(choose(VideoChoice::Best), expected);
}

TEST(VideoChoice, AllIsEveryFinishedRunAndNoneIsNothing) {
  const auto all = choose(VideoChoice::All);
  EXPECT_EQ(all.size(), 9u) << "3 methods-with-runs x 3 seeds; the failed ones are left out";
  for (const VideoRun& run : all)
    EXPECT_FALSE(run.scene == "b" && run.method == "local");
  EXPECT_EQ(all.front(), (VideoRun{"a", "local", 1}));
  EXPECT_EQ(all.back(), (VideoRun{"b", "paper", 3}));
  EXPECT_TRUE(choose(VideoChoice::None).empty());
}

}  // namespace
}  // namespace camcov::records
