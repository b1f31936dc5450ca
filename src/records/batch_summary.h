#pragma once
// The summary of a batch (SPEC section 6): per (scene, method) the distribution over seeds
// of average coverage and utilization, safety figures; per scene every method's verdict
// against the reference and the others' against each other (records/verdicts.h), tallied
// overall and per group of scenes. Built from the runs' summaries only, and sorted in natural
// order, so one process and N shards plus a merge summarize alike; the file it is written to
// and read back from is records/batch_summary_file.h.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "records/statistics.h"
#include "records/verdicts.h"
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

}  // namespace camcov::records
