#include "safety/lipschitz_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace camcov::safety {
namespace {

Sampled of(std::function<double(double)> f, double h, double lipschitz) {
  const double f0 = f(0.0), f1 = f(h);
  return {std::move(f), h, f0, f1, lipschitz, {}};
}

TEST(LipschitzSearch, FindsTheMinimumOfRandomWavesAsADenseGridDoes) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> amplitude(-1, 1), frequency(1, 60), phase(0, 6.3);
  for (int trial = 0; trial < 200; ++trial) {
    // A sum of three sines: |f'| ≤ Σ |a_k| ω_k, an honest Lipschitz constant.
    double a[3], w[3], p[3], lipschitz = 0;
    for (int k = 0; k < 3; ++k) {
      a[k] = amplitude(rng), w[k] = frequency(rng), p[k] = phase(rng);
      lipschitz += std::abs(a[k]) * w[k];
    }
    const auto f = [&](double t) {
      return a[0] * std::sin(w[0] * t + p[0]) + a[1] * std::sin(w[1] * t + p[1]) +
             a[2] * std::sin(w[2] * t + p[2]) + 2.0;
    };
    const double h = 0.1;
    // A smooth minimum to 1e-7 takes more samples than a run's default budget.
    const double m = lipschitzMinimum(of(f, h, lipschitz), 1e-7,
                                      std::numeric_limits<double>::infinity(), 1 << 24);
    double grid = std::numeric_limits<double>::infinity();
    constexpr int kSamples = 200000;
    for (int i = 0; i <= kSamples; ++i)
      grid = std::min(grid, f(h * i / kSamples));
    // The grid misses at most L·(spacing)/2; the search at most its tolerance.
    EXPECT_LE(m, grid + 1e-7) << "trial " << trial;
    EXPECT_GE(m, grid - lipschitz * h / kSamples / 2 - 1e-12) << "trial " << trial;
  }
}

TEST(LipschitzSearch, ASearchOutOfSamplesStopsWithALowerBoundOfTheMinimum) {
  // A distance swinging at 1e9 rad/s: proving its minimum to 1e-6 would take ~1e14 samples.
  int samples = 0;
  const auto f = [&samples](double t) {
    ++samples;
    return 3.0 + 2.0 * std::sin(1e9 * t);
  };
  const double m =
      lipschitzMinimum(of(f, 0.1, 2e9), 1e-6, std::numeric_limits<double>::infinity(), 1000);
  EXPECT_LE(samples, 1000 + 2);  // the budget, and the two ends sampled by of()
  EXPECT_LE(m, 1.0) << "never above the true minimum, 1";
  EXPECT_TRUE(std::isfinite(m));
}

TEST(LipschitzSearch, FirstInstantBelowALevelIsFoundFromTheLeft) {
  // |t − 0.03| dips below 0.01 on (0.02, 0.04), and 5 |t − 0.08| on (0.078, 0.082).
  const auto f = [](double t) { return std::min(std::abs(t - 0.03), 5 * std::abs(t - 0.08)); };
  const double first = firstBelow(of(f, 0.1, 5.0), 0.01, 12);
  // Where f is flatter than L an undecided interval or two before the crossing count as below.
  EXPECT_GE(first, 0.02 - 4 * 0.1 / 4096);
  EXPECT_LE(first, 0.02);
  EXPECT_EQ(firstBelow(of(f, 0.1, 5.0), -0.001, 12), -1.0) << "never below −0.001";
  EXPECT_EQ(firstBelow(of([](double t) { return t; }, 0.1, 1.0), 0.05, 12), 0.0);
}

TEST(LipschitzSearch, TimeBelowALevelMatchesTheExactMeasure) {
  // |t − c| < r on an interval of length 2r (clipped to [0, h]): measure known exactly.
  for (const auto& [c, r] : {std::pair{0.05, 0.01}, std::pair{0.0, 0.03}, std::pair{0.099, 0.02},
                             std::pair{0.5, 0.1}, std::pair{0.05, 1.0}}) {
    const auto f = [c = c](double t) { return std::abs(t - c); };
    const double h = 0.1;
    const double exact = std::max(0.0, std::min(h, c + r) - std::max(0.0, c - r));
    const double measured = timeBelow(of(f, h, 1.0), r, 12);
    EXPECT_GE(measured, exact - 1e-15) << "never undercounts";
    EXPECT_LE(measured, exact + 2 * h / 4096 + 1e-15) << "c = " << c << ", r = " << r;
  }
}

TEST(LipschitzSearch, ZeroLipschitzConstantTrustsTheEnds) {
  const Sampled constant = of([](double) { return 0.7; }, 0.1, 0.0);
  EXPECT_EQ(lipschitzMinimum(constant, 1e-9), 0.7);
  EXPECT_EQ(timeBelow(constant, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(timeBelow(constant, 0.8), 0.1);
}

}  // namespace
}  // namespace camcov::safety
