#pragma once
// The summary of a batch (SPEC section 6): per (scene, method) the distribution over seeds
// of average coverage and utilization, safety figures; per scene the winner and the two-sided
// Mann-Whitney p-value of paper vs local. Built from the runs' summaries only, and written
// with sorted keys and shortest round-trip numbers, so one process and N shards plus a merge
// give the same bytes.
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "records/statistics.h"
#include "sim/simulator.h"

namespace camcov::records {

// What the summary needs of one finished (or failed) job.
struct JobOutcome {
  std::string scene;
  std::string method;
  std::uint64_t seed = 0;
  bool failed = false;
  std::string error;        // for failed jobs
  sim::RunSummary summary;  // for finished jobs
};

struct MethodSummary {
  std::string scene;
  std::string method;
  int runs = 0;
  int failed = 0;
  Description coverage;       // of the runs' average coverage, eq. (4)
  Description utilization;    // of the runs' average utilization
  Description finalCoverage;  // of the runs' coverage at the last step
  // Of the runs' average weighted coverage (sim::RunSummary): a weighted scene's; count 0
  // elsewhere.
  Description weightedCoverage;
  // Of the runs' average resolution coverage: a scene's with a resolution; count 0 elsewhere.
  Description resolutionCoverage;
  double meanObjectCollisionTime = 0.0;  // s below δ, mean over runs
  double meanCameraCollisionTime = 0.0;
  int runsWithCollision = 0;  // runs with any time below δ
  // The time below δ split by the safety layer's verdict (sim::RunSummary), mean over runs,
  // and the runs with any of each kind.
  double meanAvoidableContactTime = 0.0;
  double meanUnavoidableContactTime = 0.0;
  int runsWithAvoidableContact = 0;
  int runsWithUnavoidableContact = 0;
  double minObjectDistance = 0.0;  // over all runs (infinity: no object)
  double minCameraDistance = 0.0;  // over all runs (infinity: one camera)
  // Runs ordered by (coverage, seed): the seed of the median (the lower middle one) and of
  // the best (the highest coverage, of equals the lowest seed). 0 without runs.
  std::uint64_t medianSeed = 0;
  std::uint64_t bestSeed = 0;
};

// The verdict rule (docs/statistics.md), the one every table of camcov uses: on one scene,
// one method's runs against another's, by their average coverage.
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

// A comparison of two methods other than the reference, and its tally (BatchSummary::pairs).
struct PairComparison {
  std::string against;
  Comparison comparison;
};

// One group of scenes (a generated family, or the folder the scenes came from): how each
// method fared there, so a reader sees where a method is strong and where it is weak.
struct GroupSummary {
  std::string name;
  std::vector<std::string> scenes;  // in the summary's order
  // Per method, by name: the mean over the group's scenes of its mean average coverage (the
  // scenes where it ran).
  std::vector<std::pair<std::string, double>> meanCoverage;
  std::vector<Tally> tallies;      // against the reference, as BatchSummary::tallies
  std::vector<Tally> pairTallies;  // as BatchSummary::pairTallies
};

struct BatchSummary {
  std::vector<MethodSummary> methods;   // sorted by scene, then method
  std::vector<std::string> scenes;      // every scene with a job, natural order
  std::string reference;                // what every other method is compared with
  std::vector<Comparison> comparisons;  // by scene, then method; none for the reference
  std::vector<Tally> tallies;           // in the batch's order; none for the reference
  // The methods other than the reference against each other: for each pair, the later one in
  // the batch's order against the earlier (e.g. ours against the paper's), by scene.
  std::vector<PairComparison> pairs;
  std::vector<Tally> pairTallies;    // by `against`, then method, in the batch's order
  std::vector<JobOutcome> failures;  // sorted by scene, method, seed
  // By group, in the order of each group's first scene; empty when no scene has a group.
  std::vector<GroupSummary> groups;

  // The comparison of `method` on `scene`, or nullptr (the reference, or a method not run).
  const Comparison* comparison(const std::string& scene, const std::string& method) const;
};

// Compares every method with `reference` (the baseline, by default), and the others pairwise,
// and groups the scenes by `groupOf` (scene name to group; scenes it lacks are in no group).
// Each scene's rows, comparisons and pairs, and the tallies, follow `order` (the batch's
// methods in control::inMethodOrder; names it lacks come after, by name).
BatchSummary summarize(std::vector<JobOutcome> outcomes, const std::string& reference,
                       std::span<const std::string> order = {},
                       const std::map<std::string, std::string>& groupOf = {});
nlohmann::json summaryToJson(const BatchSummary& summary);
// The inverse of summaryToJson, so a report shows exactly the numbers the batch wrote.
// Throws InputError naming `source` if the document is not a camcov summary.
BatchSummary summaryFromJson(const nlohmann::json& j, const std::string& source);
BatchSummary loadSummaryFile(const std::filesystem::path& file);
std::string summaryToCsv(const BatchSummary& summary);

}  // namespace camcov::records
