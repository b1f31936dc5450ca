#include "records/batch_summary.h"
#include "records/batch_summary_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "util/input_error.h"

namespace camcov::records {
namespace {

JobOutcome job(std::string scene, std::string method, std::uint64_t seed, double coverage) {
  JobOutcome o{std::move(scene), std::move(method), seed, false, "", {}};
  o.summary.averageCoverage = coverage;
  o.summary.averageUtilization = coverage / 2;
  o.summary.minObjectDistance = 1.0 + coverage;
  o.summary.minCameraDistance = std::numeric_limits<double>::infinity();
  // Runs of higher coverage in these tests also spend time near things.
  o.summary.objectCollisionTime = coverage > 0.5 ? 0.3 : 0.0;
  o.summary.avoidableContactTime = coverage > 0.5 ? 0.2 : 0.0;
  o.summary.unavoidableContactTime = coverage > 0.5 ? 0.1 : 0.0;
  return o;
}

TEST(Summarize, GroupsBySceneAndMethodInNaturalOrderAndPicksWinners) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 5; ++s) {
    jobs.push_back(job("scene10", "paper", s, 0.8 + 0.01 * s));
    jobs.push_back(job("scene10", "local", s, 0.3 + 0.01 * s));
    jobs.push_back(job("scene2", "paper", s, 0.5));
    jobs.push_back(job("scene2", "local", s, 0.5));
  }
  jobs.push_back({"scene2", "paper", 6, true, "boom", {}});
  const BatchSummary summary = summarize(jobs, "local");
  ASSERT_EQ(summary.methods.size(), 4u);
  EXPECT_EQ(summary.methods[0].scene, "scene2");
  EXPECT_EQ(summary.methods[0].method, "local");
  EXPECT_EQ(summary.methods[1].failed, 1);
  EXPECT_EQ(summary.methods[1].runs, 5);
  EXPECT_EQ(summary.scenes, (std::vector<std::string>{"scene2", "scene10"}));
  EXPECT_EQ(summary.reference, "local");
  ASSERT_EQ(summary.comparisons.size(), 2u);
  EXPECT_EQ(summary.comparisons[0].winner, "tie");
  EXPECT_EQ(summary.comparisons[1].winner, "paper");
  EXPECT_EQ(summary.comparison("scene10", "paper"), &summary.comparisons[1]);
  EXPECT_EQ(summary.comparison("scene10", "local"), nullptr) << "the reference is no comparison";
  EXPECT_NEAR(summary.comparisons[1].pValue, 2.0 / 252.0, 1e-12);  // exact, fully separated 5 v 5
  ASSERT_EQ(summary.tallies.size(), 1u);
  EXPECT_EQ(summary.tallies[0].method, "paper");
  EXPECT_EQ(summary.tallies[0].wins, 1);
  EXPECT_EQ(summary.tallies[0].ties, 1);
  EXPECT_EQ(summary.tallies[0].losses, 0);
  ASSERT_EQ(summary.failures.size(), 1u);
  EXPECT_EQ(summary.failures[0].error, "boom");
  // Median seed: coverages rise with the seed, so seed 3 is the median of five.
  EXPECT_EQ(summary.methods[3].medianSeed, 3u);
  EXPECT_EQ(summary.methods[3].bestSeed, 5u);
}

TEST(Summarize, AnyNumberOfMethodsIsComparedWithTheReference) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 5; ++s) {
    jobs.push_back(job("a", "local", s, 0.5 + 0.001 * s));
    jobs.push_back(job("a", "better", s, 0.8 + 0.001 * s));
    jobs.push_back(job("a", "worse", s, 0.2 + 0.001 * s));
    jobs.push_back(job("a", "same", s, 0.5 + 0.001 * s));
    jobs.push_back(job("b", "local", s, 0.5));  // only the reference ran on b
  }
  const BatchSummary summary = summarize(jobs, "local");
  EXPECT_EQ(summary.scenes, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(summary.comparisons.size(), 3u);
  EXPECT_EQ(summary.comparison("a", "better")->winner, "better");
  EXPECT_EQ(summary.comparison("a", "worse")->winner, "local");
  EXPECT_EQ(summary.comparison("a", "same")->winner, "tie");
  EXPECT_NEAR(summary.comparison("a", "worse")->meanDifference, -0.3, 1e-12);
  ASSERT_EQ(summary.tallies.size(), 3u);
  for (const Tally& t : summary.tallies)
    EXPECT_EQ(t.wins + t.ties + t.losses, 1) << t.method;
  // The same with another reference: everything is measured against it instead.
  const BatchSummary other = summarize(jobs, "better");
  EXPECT_EQ(other.comparison("a", "local")->winner, "better");
  EXPECT_EQ(other.comparison("b", "local")->winner, "") << "the reference did not run on b";
}

TEST(Summarize, MedianIsTheLowerMiddleAndTiesGoToTheLowerSeed) {
  // Coverages by seed 1..4: 0.4, 0.9, 0.2, 0.9. Ordered: 0.2 (3), 0.4 (1), 0.9 (2), 0.9 (4).
  std::vector<JobOutcome> jobs;
  for (const auto& [seed, coverage] : {std::pair{4u, 0.9}, {3u, 0.2}, {2u, 0.9}, {1u, 0.4}}) {
    jobs.push_back(job("s", "paper", seed, coverage));
  }
  jobs.push_back({"s", "paper", 5, true, "failed runs have no coverage", {}});
  const BatchSummary summary = summarize(jobs, "local");
  ASSERT_EQ(summary.methods.size(), 1u);
  EXPECT_EQ(summary.methods[0].medianSeed, 1u);
  EXPECT_EQ(summary.methods[0].bestSeed, 2u);
}

TEST(Summarize, OutputDoesNotDependOnInputOrder) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 4; ++s) {
    jobs.push_back(job("b", "paper", s, 0.1 * s));
    jobs.push_back(job("a", "local", s, 0.2 * s));
  }
  std::vector<JobOutcome> reversed(jobs.rbegin(), jobs.rend());
  EXPECT_EQ(summaryToJson(summarize(jobs, "local")).dump(),
            summaryToJson(summarize(reversed, "local")).dump());
  EXPECT_EQ(summaryToCsv(summarize(jobs, "local")), summaryToCsv(summarize(reversed, "local")));
}

TEST(Summarize, EachScenesRowsAndComparisonsFollowTheListingOrder) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 5; ++s) {
    for (const char* scene : {"a", "b"}) {
      jobs.push_back(job(scene, "camcov", s, 0.7 + 0.001 * s));
      jobs.push_back(job(scene, "local", s, 0.1 + 0.001 * s));
      jobs.push_back(job(scene, "paper", s, 0.5 + 0.001 * s));
    }
  }
  const std::vector<std::string> order{"paper", "local", "camcov"};
  const BatchSummary summary = summarize(jobs, "local", order);
  std::vector<std::string> rows, compared;
  for (const MethodSummary& m : summary.methods)
    rows.push_back(m.scene + " " + m.method);
  for (const Comparison& c : summary.comparisons)
    compared.push_back(c.scene + " " + c.method);
  EXPECT_EQ(rows, (std::vector<std::string>{"a paper", "a local", "a camcov", "b paper", "b local",
                                            "b camcov"}));
  EXPECT_EQ(compared, (std::vector<std::string>{"a paper", "a camcov", "b paper", "b camcov"}));
}

TEST(Summarize, MethodsOtherThanTheReferenceAreComparedPairwiseInTheBatchOrder) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 5; ++s) {
    jobs.push_back(job("a", "local", s, 0.1 + 0.001 * s));
    jobs.push_back(job("a", "paper", s, 0.5 + 0.001 * s));
    jobs.push_back(job("a", "camcov", s, 0.7 + 0.001 * s));
    jobs.push_back(job("b", "local", s, 0.1 + 0.001 * s));
    jobs.push_back(job("b", "paper", s, 0.5 + 0.001 * s));
    jobs.push_back(job("b", "camcov", s, 0.5 + 0.001 * s));
    jobs.push_back(job("c", "paper", s, 0.9 + 0.001 * s));  // camcov did not run on c
  }
  const std::vector<std::string> order{"paper", "local", "camcov"};
  const BatchSummary summary = summarize(jobs, "local", order);
  ASSERT_EQ(summary.tallies.size(), 2u);
  EXPECT_EQ(summary.tallies[0].method, "paper") << "tallies follow the batch's order";
  EXPECT_EQ(summary.tallies[1].method, "camcov");
  // One pair: the later method against the earlier, on the scenes where both ran.
  ASSERT_EQ(summary.pairs.size(), 2u) << "none on c, where camcov did not run";
  EXPECT_EQ(summary.pairs[0].against, "paper");
  EXPECT_EQ(summary.pairs[0].comparison.method, "camcov");
  EXPECT_EQ(summary.pairs[0].comparison.winner, "camcov");
  EXPECT_NEAR(summary.pairs[0].comparison.meanDifference, 0.2, 1e-12);
  EXPECT_EQ(summary.pairs[1].comparison.winner, "tie");
  ASSERT_EQ(summary.pairTallies.size(), 1u);
  const Tally& t = summary.pairTallies[0];
  EXPECT_EQ(std::tie(t.method, t.against, t.wins, t.ties, t.losses),
            std::make_tuple(std::string("camcov"), std::string("paper"), 1, 1, 0));
  // The reference's tallies say nothing of the pairs.
  EXPECT_EQ(summary.tallies[1].against, "");
}

TEST(Summarize, GroupsCountTheSameVerdictsPerGroupAndAddUpToTheTotals) {
  std::vector<JobOutcome> jobs;
  // Scenes a1..a3 in group A, b1..b2 in group B, c in none: camcov beats paper on a1, a2 and
  // b1, ties on a3, loses on b2; both beat local everywhere.
  const std::vector<std::pair<std::string, double>> camcovOver{
      {"a1", 0.1}, {"a2", 0.1}, {"a3", 0.0}, {"b1", 0.1}, {"b2", -0.1}, {"c", 0.1}};
  for (std::uint64_t s = 1; s <= 5; ++s) {
    for (const auto& [scene, delta] : camcovOver) {
      jobs.push_back(job(scene, "local", s, 0.1 + 0.001 * s));
      jobs.push_back(job(scene, "paper", s, 0.5 + 0.001 * s));
      jobs.push_back(job(scene, "camcov", s, 0.5 + delta + 0.001 * s));
    }
  }
  const std::vector<std::string> order{"paper", "local", "camcov"};
  const std::map<std::string, std::string> groupOf{{"a1", "A"}, {"a2", "A"}, {"a3", "A"},
                                                   {"b1", "B"}, {"b2", "B"}, {"c", ""}};
  const BatchSummary summary = summarize(jobs, "local", order, groupOf);
  ASSERT_EQ(summary.groups.size(), 2u) << "c has no group";
  const GroupSummary &a = summary.groups[0], &b = summary.groups[1];
  EXPECT_EQ(a.name, "A");
  EXPECT_EQ(a.scenes, (std::vector<std::string>{"a1", "a2", "a3"}));
  EXPECT_EQ(b.scenes, (std::vector<std::string>{"b1", "b2"}));
  ASSERT_EQ(a.pairTallies.size(), 1u);
  const auto wtl = [](const Tally& t) { return std::make_tuple(t.wins, t.ties, t.losses); };
  EXPECT_EQ(wtl(a.pairTallies[0]), std::make_tuple(2, 1, 0));
  EXPECT_EQ(wtl(b.pairTallies[0]), std::make_tuple(1, 0, 1));
  EXPECT_EQ(a.pairTallies[0].against, "paper");
  ASSERT_EQ(a.tallies.size(), summary.tallies.size());
  for (std::size_t i = 0; i < a.tallies.size(); ++i) {
    EXPECT_EQ(a.tallies[i].method, summary.tallies[i].method);
    EXPECT_EQ(a.tallies[i].wins + b.tallies[i].wins + 1, summary.tallies[i].wins) << "c's win";
  }
  // Means over the group's scenes, by hand: paper 0.503 on every scene, camcov + its deltas.
  const auto meanOf = [](const GroupSummary& g, const std::string& method) {
    for (const auto& [m, mean] : g.meanCoverage) {
      if (m == method) return mean;
    }
    return -1.0;
  };
  EXPECT_NEAR(meanOf(a, "paper"), 0.503, 1e-12);
  EXPECT_NEAR(meanOf(a, "camcov"), 0.503 + 0.2 / 3, 1e-12);
  EXPECT_NEAR(meanOf(b, "camcov"), 0.503, 1e-12);
  EXPECT_NEAR(meanOf(b, "local"), 0.103, 1e-12);
  // And the file keeps them.
  const BatchSummary back = summaryFromJson(summaryToJson(summary), "test");
  EXPECT_EQ(summaryToJson(back).dump(), summaryToJson(summary).dump());
  EXPECT_TRUE(summarize(jobs, "local", order).groups.empty()) << "no groups asked for";
}

TEST(Summarize, FinalCoverageIsDescribedAndRunsWithoutItAreLeftOut) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 3; ++s) {
    JobOutcome o = job("a", "paper", s, 0.5);
    o.summary.finalCoverage = 0.1 * static_cast<double>(s);
    jobs.push_back(o);
  }
  JobOutcome old = job("a", "paper", 4, 0.5);
  old.summary.finalCoverage =
      std::numeric_limits<double>::quiet_NaN();  // a run from before final coverage was recorded
  jobs.push_back(old);
  const BatchSummary summary = summarize(jobs, "local");
  ASSERT_EQ(summary.methods.size(), 1u);
  EXPECT_EQ(summary.methods[0].runs, 4);
  EXPECT_EQ(summary.methods[0].finalCoverage.count, 3);
  EXPECT_NEAR(summary.methods[0].finalCoverage.median, 0.2, 1e-12);
}

TEST(SummaryFile, ReadsBackWhatTheSummaryWrote) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 4; ++s) {
    jobs.push_back(job("static2", "paper", s, 0.6 + 0.01 * s));
    jobs.push_back(job("static2", "local", s, 0.4));
    jobs.push_back(job("dynamic10", "paper", s, 0.3 * s));
  }
  jobs.push_back({"dynamic10", "local", 1, true, "it broke", {}});
  for (std::uint64_t s = 1; s <= 4; ++s) {
    jobs.push_back(job("static2", "camcov", s, 0.7 + 0.01 * s));
    jobs.back().summary.finalCoverage = 0.75;
  }
  const std::vector<std::string> order{"paper", "local", "camcov"};
  const nlohmann::json written = summaryToJson(summarize(jobs, "local", order));
  ASSERT_EQ(written.at("pairTotals").size(), 1u);
  const BatchSummary read = summaryFromJson(written, "summary.json");
  EXPECT_EQ(summaryToJson(read), written);
  EXPECT_TRUE(std::isinf(read.methods[0].minCameraDistance)) << "null reads back as infinity";
  ASSERT_EQ(read.failures.size(), 1u);
  EXPECT_TRUE(read.failures[0].failed);
}

TEST(SummaryFile, ReadsSummariesWrittenBeforePairsAndFinalCoverage) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 3; ++s)
    jobs.push_back(job("a", "paper", s, 0.5));
  nlohmann::json old = summaryToJson(summarize(jobs, "local"));
  old.erase("pairs");
  old.erase("pairTotals");
  for (auto& m : old.at("methods"))
    m.erase("finalCoverage");
  const BatchSummary read = summaryFromJson(old, "summary.json");
  EXPECT_TRUE(read.pairs.empty());
  EXPECT_EQ(read.methods.at(0).finalCoverage.count, 0);
}

TEST(SummaryFile, RefusesAKeyItNeverWritesNamingTheKeyAndWhere) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t s = 1; s <= 4; ++s) {
    jobs.push_back(job("a", "paper", s, 0.6));
    jobs.push_back(job("a", "local", s, 0.4));
  }
  jobs.push_back({"a", "local", 5, true, "it broke", {}});
  const std::vector<std::string> order{"paper", "local"};
  const nlohmann::json written = summaryToJson(summarize(jobs, "local", order));
  ASSERT_NO_THROW(summaryFromJson(written, "summary.json"));
  // One misspelling in each kind of object the file holds.
  const std::vector<std::pair<nlohmann::json::json_pointer, std::string>> places{
      {nlohmann::json::json_pointer(""), "the summary"},
      {nlohmann::json::json_pointer("/methods/0"), "methods[]"},
      {nlohmann::json::json_pointer("/methods/0/averageCoverage"), "a description of runs"},
      {nlohmann::json::json_pointer("/comparisons/0"), "comparisons[]"},
      {nlohmann::json::json_pointer("/totals/0"), "a tally"},
      {nlohmann::json::json_pointer("/failures/0"), "failures[]"}};
  for (const auto& [where, named] : places) {
    nlohmann::json edited = written;
    edited[where]["meanCoverge"] = 0.9;
    try {
      summaryFromJson(edited, "x/summary.json");
      ADD_FAILURE() << "accepted a misspelled key in " << named;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("x/summary.json"), std::string::npos) << message;
      EXPECT_NE(message.find(named), std::string::npos) << message;
      EXPECT_NE(message.find("\"meanCoverge\""), std::string::npos) << message;
    }
  }
  // Only a pair names what it is compared with.
  nlohmann::json edited = written;
  edited["comparisons"][0]["against"] = "paper";
  EXPECT_THROW(summaryFromJson(edited, "summary.json"), InputError);
}

TEST(SummaryFile, RejectsOtherDocumentsNamingTheFile) {
  try {
    summaryFromJson(nlohmann::json{{"format", "camcov-run/2"}}, "x/summary.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x/summary.json"), std::string::npos);
  }
  EXPECT_THROW(summaryFromJson(nlohmann::json{{"format", "camcov-summary/2"}}, "s"), InputError);
}

}  // namespace
}  // namespace camcov::records
