#include "records/verdicts.h"

#include <fmt/format.h>

#include <cmath>

namespace camcov::records {

int seedsToReachSignificance() {
  int n = 1;
  while (smallestPValue(n, n) >= kSignificance)
    ++n;
  return n;
}

std::string verdictRuleText() {
  return fmt::format(
      "two-sided Mann-Whitney U test over seeds; a method wins when p < {}, the means differ by "
      "at least {} and its runs are the larger by the test (A12 > 0.5), else a tie; undecided "
      "where the seeds are too few for any p to reach {}",
      kSignificance, kPracticalDifference, kSignificance);
}

RunsComparison compareRuns(std::span<const double> runs, std::span<const double> reference) {
  const MannWhitney test = mannWhitneyU(runs, reference);
  RunsComparison c;
  c.pValue = test.pValue;
  c.exact = test.exact;
  c.meanDifference = describe(runs).mean - describe(reference).mean;
  c.a12 = varghaDelaneyA12(runs, reference);
  c.meanDifferenceCI = welchInterval(runs, reference);
  const int n1 = static_cast<int>(runs.size()), n2 = static_cast<int>(reference.size());
  if (smallestPValue(n1, n2) >= kSignificance) {
    c.verdict = Verdict::Undecided;
    c.seedsNeeded = seedsToReachSignificance();
  } else if (c.pValue < kSignificance && std::abs(c.meanDifference) >= kPracticalDifference &&
             (c.meanDifference > 0.0) == (c.a12 > 0.5)) {
    c.verdict = c.meanDifference > 0.0 ? Verdict::Better : Verdict::Worse;
  }
  return c;
}

void count(Tally& tally, const Comparison& c, const std::string& against) {
  tally.wins += c.winner == c.method;
  tally.ties += c.winner == "tie";
  tally.losses += c.winner == against;
  tally.undecided += c.winner == "undecided";
}

std::string verdictText(const Comparison& c) {
  if (c.winner.empty()) return "-";
  // "needs ≥ 4 seeds", not "(4 seeds)": read as the seeds that were run.
  if (c.seedsNeeded > 0) return fmt::format("{}: needs ≥ {} seeds", c.winner, c.seedsNeeded);
  return fmt::format("{} (p {:.3g})", c.winner, c.pValue);
}

}  // namespace camcov::records
