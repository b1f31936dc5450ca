// The verdict rule (docs/statistics.md): undecided when the seeds cannot reach α, a practical
// minimum below which a difference is a tie, the effect size and the interval beside p — and,
// on the published benchmark's 20 seeds, the same verdicts as before the rule had them.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include <nlohmann/json.hpp>

#include "records/batch_summary.h"
#include "records/batch_summary_file.h"
#include "records/statistics.h"
#include "records/verdicts.h"

namespace camcov::records {
namespace {

std::vector<double> constant(int n, double v) {
  return std::vector<double>(static_cast<std::size_t>(n), v);
}

TEST(VerdictRule, TooFewSeedsAreUndecidedAndSayHowManyWouldDo) {
  // However far apart: 3 seeds against 3 cannot give p < 0.05 (p >= 2 / C(6, 3) = 0.1).
  for (const int n : {1, 2, 3}) {
    std::vector<double> high, low;
    for (int i = 0; i < n; ++i) {
      high.push_back(0.62 + 0.001 * i);
      low.push_back(0.001 * i);
    }
    const RunsComparison c = compareRuns(high, low);
    EXPECT_EQ(c.verdict, Verdict::Undecided) << n << " seeds";
    EXPECT_EQ(c.seedsNeeded, 4) << n << " seeds";
  }
  const std::vector<double> high{0.62, 0.63, 0.64, 0.65}, low{0.0, 0.01, 0.02, 0.03};
  const RunsComparison four = compareRuns(high, low);
  EXPECT_EQ(four.verdict, Verdict::Better) << "2 / C(8, 4) = 0.029";
  EXPECT_EQ(four.seedsNeeded, 0);
}

TEST(VerdictRule, SmallestPValueIsWhatTheExactTestGivesSeparatedSamples) {
  for (int n1 = 1; n1 <= 6; ++n1) {
    for (int n2 = 1; n2 <= 6; ++n2) {
      std::vector<double> a, b;
      for (int i = 0; i < n1; ++i)
        a.push_back(10.0 + i);
      for (int i = 0; i < n2; ++i)
        b.push_back(i);
      EXPECT_DOUBLE_EQ(mannWhitneyU(a, b).pValue, smallestPValue(n1, n2)) << n1 << " " << n2;
    }
  }
}

TEST(VerdictRule, ADifferenceBelowThePracticalMinimumIsATieWhateverP) {
  std::vector<double> a, b;
  for (int i = 0; i < 10; ++i) {
    a.push_back(0.99994 + 1e-7 * i);
    b.push_back(0.99995 + 1e-7 * i);
  }
  const RunsComparison c = compareRuns(a, b);
  EXPECT_LT(c.pValue, kSignificance);
  EXPECT_EQ(c.verdict, Verdict::Tie);
  // And just above the minimum, the same evidence is a loss.
  for (double& v : a)
    v -= 2 * kPracticalDifference;
  EXPECT_EQ(compareRuns(a, b).verdict, Verdict::Worse);
}

TEST(VerdictRule, RunsThatMostlyBeatTheOthersWithALowerMeanNeitherWinNorLose) {
  // 18 of 20 runs above every run of the other, two far below it: the test is sure the runs
  // differ (A12 = 0.9) and the means differ the other way by more than the minimum. Neither
  // method is the better one; before the direction had to agree this read as a loss.
  std::vector<double> mostlyAbove = constant(18, 0.523), steady = constant(20, 0.519);
  mostlyAbove.push_back(0.256);
  mostlyAbove.push_back(0.256);
  const RunsComparison c = compareRuns(mostlyAbove, steady);
  EXPECT_LT(c.pValue, kSignificance);
  EXPECT_LT(c.meanDifference, -kPracticalDifference);
  EXPECT_NEAR(c.a12, 0.9, 1e-12);
  EXPECT_EQ(c.verdict, Verdict::Tie);
  EXPECT_EQ(compareRuns(steady, mostlyAbove).verdict, Verdict::Tie) << "either way round";
  // The same runs without the two far below win.
  EXPECT_EQ(compareRuns(constant(18, 0.523), steady).verdict, Verdict::Better);
}

TEST(VerdictRule, EffectSizeIsTheShareOfPairsAboveWithTiesCountingHalf) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> value(0, 6);  // small range: many ties
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> a(3 + trial % 9), b(2 + trial % 7);
    for (double& v : a)
      v = value(rng) / 6.0;
    for (double& v : b)
      v = value(rng) / 6.0;
    double above = 0.0;
    for (const double x : a)
      for (const double y : b)
        above += x > y ? 1.0 : x == y ? 0.5 : 0.0;
    EXPECT_NEAR(varghaDelaneyA12(a, b), above / static_cast<double>(a.size() * b.size()), 1e-12);
  }
  EXPECT_EQ(varghaDelaneyA12(constant(5, 0.3), constant(5, 0.3)), 0.5);
}

TEST(VerdictRule, WelchIntervalMatchesStudentsTableForEqualVariances) {
  // Equal variances and sizes 6 and 6: Welch's degrees of freedom are exactly 10, and
  // t(0.975, 10) = 2.228138851986 (tables). Means 3.5 and 4.5, variances 3.5 each.
  const std::vector<double> a{1, 2, 3, 4, 5, 6}, b{2, 3, 4, 5, 6, 7};
  const Interval ci = welchInterval(a, b);
  const double halfWidth = 2.228138851986 * std::sqrt(3.5 / 6 + 3.5 / 6);
  EXPECT_NEAR(ci.low, -1.0 - halfWidth, 1e-9);
  EXPECT_NEAR(ci.high, -1.0 + halfWidth, 1e-9);
  EXPECT_TRUE(std::isnan(welchInterval(std::vector<double>{1.0}, b).low)) << "one value";
  const Interval flat = welchInterval(constant(4, 0.7), constant(4, 0.2));
  EXPECT_DOUBLE_EQ(flat.low, 0.5);
  EXPECT_DOUBLE_EQ(flat.high, 0.5);
}

TEST(VerdictRule, SummaryCountsUndecidedScenesAndWritesTheSeedsNeeded) {
  std::vector<JobOutcome> jobs;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    for (const auto& [method, coverage] : {std::pair{"paper", 0.622}, std::pair{"local", 0.0}}) {
      JobOutcome o{"s", method, seed, false, "", {}};
      o.summary.averageCoverage = coverage;
      jobs.push_back(o);
    }
  }
  const BatchSummary summary = summarize(jobs, "local");
  ASSERT_EQ(summary.comparisons.size(), 1u);
  EXPECT_EQ(summary.comparisons[0].winner, "undecided");
  EXPECT_EQ(verdictText(summary.comparisons[0]), "undecided: needs ≥ 4 seeds");
  ASSERT_EQ(summary.tallies.size(), 1u);
  EXPECT_EQ(summary.tallies[0].undecided, 1);
  EXPECT_EQ(summary.tallies[0].ties, 0);
  const nlohmann::json j = summaryToJson(summary);
  EXPECT_EQ(j.at("comparisons").at(0).at("seedsNeeded"), 4);
  const Comparison back = summaryFromJson(j, "test").comparisons[0];
  EXPECT_EQ(back.seedsNeeded, 4);
  EXPECT_EQ(back.verdict, Verdict::Undecided) << "the verdict read back from its name";
}

TEST(VerdictRule, PublishedBenchmarkKeepsItsTwentySeedVerdicts) {
  std::ifstream in(CAMCOV_TEST_DATA_DIR "/published_verdicts_20_seeds.json");
  ASSERT_TRUE(in);
  const nlohmann::json golden = nlohmann::json::parse(in);
  std::vector<JobOutcome> jobs;
  for (const auto& [scene, byMethod] : golden.at("coverage").items()) {
    for (const auto& [method, values] : byMethod.items()) {
      std::uint64_t seed = 0;
      for (const double v : values) {
        JobOutcome o{scene, method, ++seed, false, "", {}};
        o.summary.averageCoverage = v;
        jobs.push_back(o);
      }
    }
  }
  const auto order = golden.at("methods").get<std::vector<std::string>>();
  const BatchSummary summary = summarize(jobs, golden.at("reference"), order);
  std::size_t checked = 0;
  for (const auto& v : golden.at("verdicts")) {
    const std::string scene = v.at("scene"), method = v.at("method"), against = v.at("against");
    const Comparison* c = nullptr;
    if (against == summary.reference) {
      c = summary.comparison(scene, method);
    } else {
      for (const auto& p : summary.pairs) {
        if (p.against == against && p.comparison.scene == scene && p.comparison.method == method)
          c = &p.comparison;
      }
    }
    ASSERT_NE(c, nullptr) << scene << " " << method << " against " << against;
    EXPECT_EQ(c->winner, v.at("winner").get<std::string>())
        << scene << " " << method << " against " << against;
    EXPECT_GE(c->a12, 0.0);
    EXPECT_LE(c->a12, 1.0);
    ++checked;
  }
  EXPECT_EQ(checked, 96u) << "32 scenes x (2 against the reference + 1 pair)";
}

}  // namespace
}  // namespace camcov::records
