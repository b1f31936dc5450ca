#include "records/statistics.h"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace camcov::records {

double quantileOfSorted(std::span<const double> sorted, double p) {
  if (sorted.empty()) return 0.0;
  const double h = (static_cast<double>(sorted.size()) - 1.0) * p;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

Description describe(std::span<const double> values) {
  Description d;
  if (values.empty()) return d;
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  d.count = static_cast<int>(sorted.size());
  d.mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / d.count;
  double squares = 0.0;
  for (const double v : sorted)
    squares += (v - d.mean) * (v - d.mean);
  d.sd = d.count > 1 ? std::sqrt(squares / (d.count - 1)) : 0.0;
  d.min = sorted.front();
  d.max = sorted.back();
  d.q1 = quantileOfSorted(sorted, 0.25);
  d.median = quantileOfSorted(sorted, 0.5);
  d.q3 = quantileOfSorted(sorted, 0.75);
  return d;
}

namespace {

// Mid-ranks (1-based) of the pooled sample; equal values share the mean of their ranks.
std::vector<double> midRanks(const std::vector<double>& pooled) {
  std::vector<std::size_t> order(pooled.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](auto i, auto j) { return pooled[i] < pooled[j]; });
  std::vector<double> ranks(pooled.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && pooled[order[j + 1]] == pooled[order[i]])
      ++j;
    const double rank = 0.5 * static_cast<double>(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k)
      ranks[order[k]] = rank;
    i = j + 1;
  }
  return ranks;
}

double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i)
    c = c * (n - k + i) / i;
  return c;
}

// Visits every choice of n1 of the pooled ranks as "the first sample", passing its rank sum.
template <typename Visit>
void forEachSplit(const std::vector<double>& ranks, int n1, int start, double sum, Visit& visit) {
  if (n1 == 0) {
    visit(sum);
    return;
  }
  for (int i = start; i <= static_cast<int>(ranks.size()) - n1; ++i) {
    forEachSplit(ranks, n1 - 1, i + 1, sum + ranks[i], visit);
  }
}

}  // namespace

MannWhitney mannWhitneyU(std::span<const double> a, std::span<const double> b) {
  MannWhitney result;
  const int n1 = static_cast<int>(a.size()), n2 = static_cast<int>(b.size());
  if (n1 == 0 || n2 == 0) return result;
  std::vector<double> pooled(a.begin(), a.end());
  pooled.insert(pooled.end(), b.begin(), b.end());
  const std::vector<double> ranks = midRanks(pooled);
  const double rankSum = std::accumulate(ranks.begin(), ranks.begin() + n1, 0.0);
  const double offset = 0.5 * n1 * (n1 + 1.0);
  result.u = rankSum - offset;
  const double meanU = 0.5 * n1 * n2;
  const double observed = std::abs(result.u - meanU);

  if (binomial(n1 + n2, n1) <= kExactLimit) {
    // Exact: the share of all equally likely splits at least as far from the mean.
    double extreme = 0.0, total = 0.0;
    auto visit = [&](double sum) {
      total += 1.0;
      if (std::abs(sum - offset - meanU) >= observed - 1e-9) extreme += 1.0;
    };
    forEachSplit(ranks, n1, 0, 0.0, visit);
    result.pValue = extreme / total;
    result.exact = true;
    return result;
  }
  // Normal approximation; ties shrink the variance by Σ(t³ − t) / ((n)(n − 1)).
  const double n = n1 + n2;
  std::vector<double> sorted = pooled;
  std::sort(sorted.begin(), sorted.end());
  double tieTerm = 0.0;
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i;
    while (j + 1 < sorted.size() && sorted[j + 1] == sorted[i])
      ++j;
    const double t = static_cast<double>(j - i + 1);
    tieTerm += t * t * t - t;
    i = j + 1;
  }
  const double variance = n1 * n2 / 12.0 * ((n + 1.0) - tieTerm / (n * (n - 1.0)));
  if (!(variance > 0.0)) return result;  // all values equal
  const double z = std::max(observed - 0.5, 0.0) / std::sqrt(variance);
  result.pValue = std::min(1.0, std::erfc(z / std::sqrt(2.0)));
  return result;
}

double smallestPValue(int n1, int n2) {
  if (n1 == 0 || n2 == 0) return 1.0;
  return std::min(1.0, 2.0 / binomial(n1 + n2, n1));
}

double varghaDelaneyA12(std::span<const double> a, std::span<const double> b) {
  if (a.empty() || b.empty()) return 0.5;
  return mannWhitneyU(a, b).u / (static_cast<double>(a.size()) * static_cast<double>(b.size()));
}

Interval welchInterval(std::span<const double> a, std::span<const double> b, double confidence) {
  const Description da = describe(a), db = describe(b);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (da.count < 2 || db.count < 2) return {nan, nan};
  const double difference = da.mean - db.mean;
  const double va = da.sd * da.sd / da.count, vb = db.sd * db.sd / db.count;
  const double se = std::sqrt(va + vb);
  if (!(se > 0.0)) return {difference, difference};  // both samples constant
  // Welch–Satterthwaite degrees of freedom.
  const double df =
      (va + vb) * (va + vb) / (va * va / (da.count - 1.0) + vb * vb / (db.count - 1.0));
  const double t = boost::math::quantile(boost::math::students_t(df), 0.5 + 0.5 * confidence);
  return {difference - t * se, difference + t * se};
}

}  // namespace camcov::records
