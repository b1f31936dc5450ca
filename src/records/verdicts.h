#pragma once
// The verdict rule (docs/statistics.md) on its own: one method's runs against another's on one
// scene, the verdict's wording and the tallies of verdicts. The batch summary, the bench's
// table, the report and the settings report all judge with it, and the settings report needs
// nothing else of the summary.
#include <span>
#include <string>

#include "records/statistics.h"

namespace camcov::records {

// The rule, the one every table of camcov uses: on one scene, one method's runs against
// another's, by their average coverage.
//   undecided  the seed counts cannot reach α: even runs all above all others would give
//              p ≥ α (3 seeds against 3: p ≥ 0.1); the verdict says how many seeds would do
//   better / worse  the two-sided Mann-Whitney U test gives p < α AND the means differ by at
//              least kPracticalDifference AND in the direction the test found (A12 on the
//              same side of 1/2): a method whose runs mostly beat the other's but whose mean
//              is lower (a few runs far below) has neither won nor lost
//   tie        otherwise: no evidence, or a difference too small to matter
inline constexpr double kSignificance = 0.05;  // α
// Average coverage is a fraction of the targets' boundary: a difference below 0.2 % of it is
// below what any reader would act on (two methods at 0.99994 and 0.99995 tie), and below the
// smallest significant difference on the published benchmark (0.004, 20 seeds).
inline constexpr double kPracticalDifference = 0.002;

enum class Verdict { Better, Tie, Worse, Undecided };
struct RunsComparison {
  Verdict verdict = Verdict::Tie;
  double pValue = 1.0;
  bool exact = false;
  double meanDifference = 0.0;  // mean of the runs minus the reference's
  double a12 = 0.5;             // Vargha–Delaney: P(a run above a reference run)
  Interval meanDifferenceCI;    // 95 %, Welch; NaN with fewer than 2 runs on a side
  int seedsNeeded = 0;          // undecided only: seeds per method that could reach α
};
// The rule in one sentence, for the reports' and tables' captions (plain text).
std::string verdictRuleText();
// The fewest seeds per method with which the rule can decide anything (4 at α = 0.05).
int seedsToReachSignificance();
// Both samples must be non-empty.
RunsComparison compareRuns(std::span<const double> runs, std::span<const double> reference);

// One method against another (the reference, or for pairs the other) on one scene: the test
// of their runs, and its verdict named.
struct Comparison : RunsComparison {
  std::string scene;
  std::string method;
  // The method, the other, "tie", "undecided", or "" when either is missing.
  std::string winner;
};

// The verdict as the tables print it: "paper (p 0.003)", "tie (p 0.41)", "undecided: needs ≥ 4
// seeds" (per method, for any p to reach significance), or "-" when there was no comparison.
std::string verdictText(const Comparison& c);

// How one method fared against the reference (or `against`) over the scenes where both ran.
struct Tally {
  std::string method;
  int wins = 0, ties = 0, losses = 0;
  std::string against;  // pairs only; the reference's tallies leave it empty
  int undecided = 0;    // scenes with too few seeds to tell
};

// Counts comparison `c` of `c.method` against `against` in `tally`: a win, tie, loss or
// undecided (nothing when `c` compared nothing).
void count(Tally& tally, const Comparison& c, const std::string& against);

}  // namespace camcov::records
