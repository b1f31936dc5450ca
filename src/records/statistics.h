#pragma once
// Descriptive statistics over seeds and the two-sided Mann-Whitney U test used to compare the
// methods per scene (our addition: the paper reports box plots only, section VI-B).
#include <span>

namespace camcov::records {

struct Description {
  int count = 0;
  double mean = 0.0;
  double sd = 0.0;  // sample standard deviation (n − 1); 0 for a single value
  double min = 0.0;
  double q1 = 0.0;  // quartiles by linear interpolation between order statistics
  double median = 0.0;
  double q3 = 0.0;
  double max = 0.0;
};

// All zeros for an empty sample.
Description describe(std::span<const double> values);
// Quantile p ∈ [0, 1] of sorted values, interpolating linearly (Hyndman & Fan type 7).
double quantileOfSorted(std::span<const double> sorted, double p);

struct MannWhitney {
  double u = 0.0;       // U of the first sample
  double pValue = 1.0;  // two-sided
  bool exact = false;   // from the full permutation distribution (small samples)
};

// Exact permutation p-value (mid-ranks for ties) while the number of splits C(n1 + n2, n1)
// is at most kExactLimit, else the normal approximation with tie and continuity corrections.
// p = 1 when either sample is empty or every value is equal.
MannWhitney mannWhitneyU(std::span<const double> a, std::span<const double> b);
inline constexpr double kExactLimit = 200000;

// The smallest two-sided p-value the U test can give for samples of n1 and n2 values, 2 /
// C(n1 + n2, n1) (every value of one above every value of the other): with 3 seeds against
// 3 it is 0.1, so no difference can be significant at 0.05 however large.
double smallestPValue(int n1, int n2);

// Vargha and Delaney's A₁₂ ("A critique and improvement of the CL common language effect size
// statistics", J. Educ. Behav. Stat. 2000): the probability that a value of `a` is above one
// of `b`, ties counting half; 0.5 is no effect, 0.71 and above (or 0.29 and below) large.
double varghaDelaneyA12(std::span<const double> a, std::span<const double> b);

// The two-sided 95 % confidence interval of mean(a) − mean(b) by Welch's t (no equal-variance
// assumption). {NaN, NaN} when either sample has fewer than two values.
struct Interval {
  double low = 0.0, high = 0.0;
};
Interval welchInterval(std::span<const double> a, std::span<const double> b,
                       double confidence = 0.95);

}  // namespace camcov::records
