#pragma once
// The summary of a batch (SPEC section 6): per (scene, method) the distribution over seeds
// of average coverage and utilization, safety figures; per scene the winner and the two-sided
// Mann-Whitney p-value of paper vs local. Built from the runs' summaries only, and written
// with sorted keys and shortest round-trip numbers, so one process and N shards plus a merge
// give the same bytes.
#include <cstdint>
#include <filesystem>
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

struct SceneComparison {
  std::string scene;
  std::string winner;  // "paper", "local", "tie" (p >= alpha), or "" when not both ran
  double pValue = 1.0;
  bool exact = false;
  double meanDifference = 0.0;  // mean coverage of paper minus local
};

struct BatchSummary {
  std::vector<MethodSummary> methods;   // sorted by scene, then method
  std::vector<SceneComparison> scenes;  // sorted by scene
  int paperWins = 0, ties = 0, localWins = 0;
  std::vector<JobOutcome> failures;  // sorted by scene, method, seed
};

inline constexpr double kSignificance = 0.05;

BatchSummary summarize(std::vector<JobOutcome> outcomes);
nlohmann::json summaryToJson(const BatchSummary& summary);
// The inverse of summaryToJson, so a report shows exactly the numbers the batch wrote.
// Throws InputError naming `source` if the document is not a camcov summary.
BatchSummary summaryFromJson(const nlohmann::json& j, const std::string& source);
BatchSummary loadSummaryFile(const std::filesystem::path& file);
std::string summaryToCsv(const BatchSummary& summary);

}  // namespace camcov::records
