#pragma once
// The batch's results in OMPL's benchmark log format (ompl::tools::Benchmark), so OMPL's own
// tools read them: `ompl_benchmark_statistics ompl/*.log -d benchmark.db` builds the database
// that Planner Arena shows. One experiment per scene; the methods are its "planners"; per run
// the average coverage and utilization, collision times, minimum distances and run time; the
// coverage over simulated time as progress properties.
#include <map>
#include <string>
#include <vector>

#include "records/batch_folder.h"

namespace camcov::records {

// The log text of one scene's runs (all methods, all seeds).
std::string omplBenchmarkLog(const std::string& scene, const std::vector<RunRecord>& runs,
                             const std::map<std::string, JobTiming>& timings,
                             const params::Parameters& parameters);

// Writes <out>/ompl/<scene>.log for every scene with runs in the folder (of the manifest's
// methods, and of those whose results an earlier batch left there: its methodIdentities),
// `workers` scenes at a time (reading a scene's run files back is most of the time); returns
// the files in scene order.
std::vector<std::filesystem::path> writeOmplBenchmarkLogs(const BatchFolder& folder,
                                                          const BatchManifest& manifest,
                                                          unsigned workers = 1);

}  // namespace camcov::records
