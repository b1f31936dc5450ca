#include "records/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "util/natural_order.h"

namespace camcov::records {
namespace {

TEST(Describe, MatchesHandComputedValues) {
  const std::vector<double> v{4, 1, 3, 2, 5};
  const Description d = describe(v);
  EXPECT_EQ(d.count, 5);
  EXPECT_DOUBLE_EQ(d.mean, 3.0);
  EXPECT_DOUBLE_EQ(d.sd, std::sqrt(2.5));  // Σ(x − 3)² = 10, over n − 1 = 4
  EXPECT_DOUBLE_EQ(d.min, 1);
  EXPECT_DOUBLE_EQ(d.q1, 2);
  EXPECT_DOUBLE_EQ(d.median, 3);
  EXPECT_DOUBLE_EQ(d.q3, 4);
  EXPECT_DOUBLE_EQ(d.max, 5);
  EXPECT_DOUBLE_EQ(describe(std::vector<double>{1, 2, 3, 4}).q1, 1.75);  // type 7
  EXPECT_EQ(describe(std::vector<double>{7}).sd, 0.0);
  EXPECT_EQ(describe({}).count, 0);
}

TEST(MannWhitneyU, ExactForSmallSeparatedSamples) {
  // All of a below all of b: U = 0, and 2 of the C(6, 3) = 20 splits are that extreme.
  const std::vector<double> a{1, 2, 3}, b{4, 5, 6};
  const MannWhitney r = mannWhitneyU(a, b);
  EXPECT_TRUE(r.exact);
  EXPECT_DOUBLE_EQ(r.u, 0.0);
  EXPECT_DOUBLE_EQ(r.pValue, 0.1);
  EXPECT_DOUBLE_EQ(mannWhitneyU(b, a).u, 9.0);
  EXPECT_DOUBLE_EQ(mannWhitneyU(b, a).pValue, 0.1);
}

TEST(MannWhitneyU, IdenticalSamplesAreNoEvidence) {
  const std::vector<double> same(20, 0.5);
  EXPECT_DOUBLE_EQ(mannWhitneyU(same, same).pValue, 1.0);
  const std::vector<double> few(3, 0.5);
  EXPECT_DOUBLE_EQ(mannWhitneyU(few, few).pValue, 1.0);
  EXPECT_DOUBLE_EQ(mannWhitneyU(few, {}).pValue, 1.0);
}

TEST(MannWhitneyU, NormalApproximationForTwentyVersusTwenty) {
  // Completely separated, no ties: z = (200 − 0.5) / sqrt(20·20·41/12) = 5.3963…,
  // p = erfc(z / √2) = 6.80e-8 (computed by hand).
  std::vector<double> a, b;
  for (int i = 0; i < 20; ++i) {
    a.push_back(i);
    b.push_back(100 + i);
  }
  const MannWhitney r = mannWhitneyU(a, b);
  EXPECT_FALSE(r.exact);
  EXPECT_NEAR(r.pValue, 6.80e-8, 0.02e-8);
}

TEST(MannWhitneyU, ExactAndApproximateAgreeRoughlyOnMidsizedSamples) {
  // 8 vs 8 (12870 splits, exact) against the normal approximation computed from the same U.
  const std::vector<double> a{0.61, 0.72, 0.55, 0.70, 0.66, 0.59, 0.74, 0.68};
  const std::vector<double> b{0.52, 0.58, 0.49, 0.63, 0.51, 0.57, 0.60, 0.54};
  const MannWhitney r = mannWhitneyU(a, b);
  ASSERT_TRUE(r.exact);
  const double z = (std::abs(r.u - 32.0) - 0.5) / std::sqrt(8.0 * 8.0 * 17.0 / 12.0);
  EXPECT_NEAR(r.pValue, std::erfc(z / std::sqrt(2.0)), 0.01);
  EXPECT_LT(r.pValue, 0.05);
}

TEST(NaturalLess, OrdersDigitRunsAsNumbers) {
  EXPECT_TRUE(naturalLess("dynamic2", "dynamic10"));
  EXPECT_FALSE(naturalLess("dynamic10", "dynamic2"));
  EXPECT_TRUE(naturalLess("dynamic9", "static1"));
  EXPECT_TRUE(naturalLess("a", "a1"));
  EXPECT_FALSE(naturalLess("a1", "a1"));
  EXPECT_TRUE(naturalLess("scene_007", "scene_10"));
}

}  // namespace
}  // namespace camcov::records
