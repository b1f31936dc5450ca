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

}  // namespace camcov::records
