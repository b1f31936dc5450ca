#include "records/ompl_benchmark_log.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <exception>
#include <map>
#include <tuple>

#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "records/run_files.h"
#include "util/worker_pool.h"

namespace camcov::records {

namespace fs = std::filesystem;

OmplRun omplRunOf(const RunRecord& run) {
  OmplRun o{run.metadata.method, run.metadata.seed, run.metadata.toolVersion, run.summary, {}};
  o.progress.reserve(run.steps.size());
  for (const auto& step : run.steps)
    o.progress.push_back({step.time, step.terms.coverage, step.terms.utilization});
  return o;
}

std::string omplBenchmarkLog(const std::string& scene, std::vector<OmplRun> runs,
                             const std::map<std::string, JobTiming>& timings,
                             const params::Parameters& parameters) {
  std::sort(runs.begin(), runs.end(), [](const OmplRun& a, const OmplRun& b) {
    return std::tie(a.method, a.seed) < std::tie(b.method, b.seed);
  });
  const auto wallOf = [&](const OmplRun& run) {
    const auto t = timings.find(runStem(scene, run.method, run.seed));
    return t == timings.end() ? 0.0 : t->second.wallSeconds;
  };
  std::map<std::string, std::vector<const OmplRun*>> byMethod;
  for (const auto& run : runs)
    byMethod[run.method].push_back(&run);
  double totalTime = 0.0;
  std::size_t runsPerMethod = 0;
  for (const auto& [method, list] : byMethod) {
    runsPerMethod = std::max(runsPerMethod, list.size());
    for (const OmplRun* run : list)
      totalTime += wallOf(*run);
  }
  char host[256] = "unknown";
  ::gethostname(host, sizeof(host) - 1);

  std::string log;
  auto line = [&log](const std::string& text) { log += text + "\n"; };
  line("camcov version " + (runs.empty() ? std::string("?") : runs.front().toolVersion));
  line("Experiment " + scene);
  line("0 experiment properties");
  line(std::string("Running on ") + host);
  line("Starting at 1970-01-01 00:00:00");  // the runs' own clock is simulated; no wall date
  line("<<<|");
  line("camcov coverage simulation of scene " + scene + "; parameters:");
  line(params::toJson(parameters).dump());
  line("|>>>");
  line("<<<|");
  line("|>>>");
  line("0 is the random seed");  // each run has its own seed; see the runs' properties
  line(fmt::format("{} seconds per run", parameters.sim.duration));
  line("0 MB per run");
  line(fmt::format("{} runs per planner", runsPerMethod));
  line(fmt::format("{} seconds spent to collect the data", totalTime));
  line("0 enum types");
  line(fmt::format("{} planners", byMethod.size()));
  for (const auto& [method, list] : byMethod) {
    line(method);
    line("0 common properties");
    const std::vector<std::string> properties{"seed INTEGER",
                                              "time REAL",
                                              "average_coverage REAL",
                                              "average_utilization REAL",
                                              "average_reward REAL",
                                              "object_collision_time REAL",
                                              "camera_collision_time REAL",
                                              "min_object_distance REAL",
                                              "min_camera_distance REAL"};
    line(fmt::format("{} properties for each run", properties.size()));
    for (const auto& p : properties)
      line(p);
    line(fmt::format("{} runs", list.size()));
    for (const OmplRun* run : list) {
      const auto& s = run->summary;
      // Every value ends with "; ", the format's separator.
      line(fmt::format("{}; {}; {}; {}; {}; {}; {}; {}; {}; ", run->seed, wallOf(*run),
                       s.averageCoverage, s.averageUtilization, s.averageReward,
                       s.objectCollisionTime, s.cameraCollisionTime, s.minObjectDistance,
                       s.minCameraDistance));
    }
    line("3 progress properties for each run");
    line("time REAL");
    line("coverage REAL");
    line("utilization REAL");
    line(fmt::format("{} runs", list.size()));
    for (const OmplRun* run : list) {
      std::string series;
      for (const auto& [time, coverage, utilization] : run->progress)
        series += fmt::format("{},{},{},;", time, coverage, utilization);
      line(series);
    }
    line(".");
  }
  return log;
}

std::vector<fs::path> writeOmplBenchmarkLogs(const BatchFolder& folder,
                                             const BatchManifest& manifest, unsigned workers,
                                             const std::map<std::string, OmplRun>& kept) {
  std::vector<std::string> methods = manifest.methods;
  for (const auto& [method, identity] : manifest.methodIdentities)
    methods.push_back(method);
  // Grouped by scene from the files' names (sceneOfStem), so that one scene a worker is in
  // memory at a time.
  std::map<std::string, std::vector<fs::path>> byScene;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder.runsDir(), ec)) {
    const fs::path& p = entry.path();
    if (p.extension() != ".json" || p.stem().extension() == ".error") continue;
    if (const auto scene = sceneOfStem(p.stem().string(), methods)) byScene[*scene].push_back(p);
  }
  const auto timings = folder.readTimings();
  std::vector<std::pair<std::string, std::vector<fs::path>>> scenes(byScene.begin(), byScene.end());
  std::vector<fs::path> written(scenes.size());
  std::vector<std::exception_ptr> errors(scenes.size());
  forEachOnWorkers(scenes.size(), workers, [&](std::size_t i) {
    try {
      auto& [scene, files] = scenes[i];
      std::sort(files.begin(), files.end());
      std::vector<OmplRun> runs;
      for (const auto& file : files) {
        const auto known = kept.find(file.stem().string());
        runs.push_back(known != kept.end() ? known->second : omplRunOf(loadRunFile(file)));
      }
      written[i] = folder.omplDir() / (scene + ".log");
      writeFileAtomically(written[i],
                          omplBenchmarkLog(scene, std::move(runs), timings, manifest.parameters));
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  // The first scene's error in scene order, as one worker would have met it.
  for (const auto& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  return written;
}

}  // namespace camcov::records
