#pragma once
// The summary of a batch (SPEC section 6): per (scene, method) the distribution over seeds
// of average coverage and utilization, safety figures; per scene the winner and the two-sided
// Mann-Whitney p-value of paper vs local. Built from the runs' summaries only, and written
// with sorted keys and shortest round-trip numbers, so one process and N shards plus a merge
// give the same bytes.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
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
  Description coverage;                  // of the runs' average coverage, eq. (4)
  Description utilization;               // of the runs' average utilization
  Description finalCoverage;             // of the runs' coverage at the last step
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

inline constexpr double kSignificance = 0.05;

// One method against another (the reference, or for pairs the other) on one scene: the
// two-sided Mann-Whitney U test of their runs' average coverage.
struct Comparison {
  std::string scene;
  std::string method;
  std::string winner;  // the method, the other, "tie" (p >= α), or "" when either is missing
  double pValue = 1.0;
  bool exact = false;
  double meanDifference = 0.0;  // mean coverage of the method minus the reference's
};

// One sample of runs' average coverage against a reference sample: the two-sided Mann-Whitney
// U test and the verdict the summary and the report of settings both use. A difference counts
// when p < kSignificance and the means differ; otherwise it is a tie.
enum class Verdict { Better, Tie, Worse };
struct RunsComparison {
  Verdict verdict = Verdict::Tie;
  double pValue = 1.0;
  bool exact = false;
  double meanDifference = 0.0;  // mean of the runs minus the reference's
};
// Both samples must be non-empty.
RunsComparison compareRuns(std::span<const double> runs, std::span<const double> reference);

// How one method fared against the reference (or `against`) over the scenes where both ran.
struct Tally {
  std::string method;
  int wins = 0, ties = 0, losses = 0;
  std::string against;  // pairs only; the reference's tallies leave it empty
};

// A comparison of two methods other than the reference, and its tally (BatchSummary::pairs).
struct PairComparison {
  std::string against;
  Comparison comparison;
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

  // The comparison of `method` on `scene`, or nullptr (the reference, or a method not run).
  const Comparison* comparison(const std::string& scene, const std::string& method) const;
};

// Compares every method with `reference` (the baseline, by default), and the others pairwise
// in the order of `order` (the batch's methods; names it lacks come after, by name).
BatchSummary summarize(std::vector<JobOutcome> outcomes, const std::string& reference,
                       std::span<const std::string> order = {});
nlohmann::json summaryToJson(const BatchSummary& summary);
// The inverse of summaryToJson, so a report shows exactly the numbers the batch wrote.
// Throws InputError naming `source` if the document is not a camcov summary.
BatchSummary summaryFromJson(const nlohmann::json& j, const std::string& source);
BatchSummary loadSummaryFile(const std::filesystem::path& file);
std::string summaryToCsv(const BatchSummary& summary);

}  // namespace camcov::records
