#pragma once
// The batch's results in OMPL's benchmark log format (ompl::tools::Benchmark), so OMPL's own
// tools read them: `ompl_benchmark_statistics ompl/*.log -d benchmark.db` builds the database
// that Planner Arena shows. One experiment per scene; the methods are its "planners"; per run
// the average coverage and utilization, collision times, minimum distances and run time; the
// coverage over simulated time as progress properties.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "records/batch_folder.h"

namespace camcov::records {

// What a scene's log takes of one of its runs: whose it is, its summary, and its time,
// coverage and utilization at each step.
struct OmplRun {
  std::string method;
  std::uint64_t seed = 0;
  std::string toolVersion;
  sim::RunSummary summary;
  std::vector<std::array<double, 3>> progress;
};
OmplRun omplRunOf(const RunRecord& run);

// The log text of one scene's runs (all methods, all seeds).
std::string omplBenchmarkLog(const std::string& scene, std::vector<OmplRun> runs,
                             const std::map<std::string, JobTiming>& timings,
                             const params::Parameters& parameters);

// Writes <out>/ompl/<scene>.log for every scene with runs in the folder (of the manifest's
// methods, and of those whose results an earlier batch left there: its methodIdentities),
// `workers` scenes at a time; returns the files in scene order. A run in `kept` (by stem: the
// batch just made it) is taken from there, any other read back from its file (most of the
// time when none is kept).
std::vector<std::filesystem::path> writeOmplBenchmarkLogs(
    const BatchFolder& folder, const BatchManifest& manifest, unsigned workers = 1,
    const std::map<std::string, OmplRun>& kept = {});

}  // namespace camcov::records
