#include "records/batch_folder.h"

#include <fmt/format.h>

#include <fstream>

#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "records/batch_summary_file.h"
#include "records/known_keys.h"
#include "records/run_files.h"
#include "util/input_error.h"

namespace camcov::records {

namespace fs = std::filesystem;

namespace {

std::optional<nlohmann::json> readJson(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": invalid JSON: " + e.what());
  }
}

void writeJson(const fs::path& file, const nlohmann::json& j) {
  writeFileAtomically(file, j.dump(1) + "\n");
}

nlohmann::json looksToJson(const std::map<std::string, MethodLook>& looks) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [method, look] : looks)
    j[method] = {{"description", look.description}, {"color", look.color}};
  return j;
}

}  // namespace

nlohmann::json manifestToJson(const BatchManifest& m) {
  nlohmann::json scenes = nlohmann::json::array();
  for (const auto& s : m.scenes) {
    scenes.push_back(
        {{"name", s.name}, {"file", s.file}, {"hash", hashText(s.hash)}, {"group", s.group}});
  }
  return {{"format", "camcov-batch/1"},
          {"toolVersion", m.toolVersion},
          {"parameters", params::toJson(m.parameters)},
          {"methods", m.methods},
          {"methodIdentities", m.methodIdentities},
          {"methodLooks", looksToJson(m.methodLooks)},
          {"seeds", m.seeds},
          {"scenes", scenes},
          {"command", m.command}};
}

BatchManifest manifestFromJson(const nlohmann::json& j, const std::string& source) {
  try {
    if (j.at("format") != "camcov-batch/1")
      throw InputError(source + ": not a camcov batch manifest");
    requireKnownKeys(j,
                     {"format", "toolVersion", "parameters", "methods", "methodIdentities",
                      "methodLooks", "seeds", "scenes", "command"},
                     "the batch manifest", source);
    BatchManifest m;
    m.toolVersion = j.at("toolVersion").get<std::string>();
    m.parameters = params::fromJson(j.at("parameters"), source);
    m.methods = j.at("methods").get<std::vector<std::string>>();
    m.methodIdentities = j.value("methodIdentities", std::map<std::string, std::string>{});
    const nlohmann::json looks = j.value("methodLooks", nlohmann::json::object());
    for (const auto& [method, look] : looks.items()) {
      requireKnownKeys(look, {"description", "color"}, "methodLooks." + method, source);
      m.methodLooks[method] = {look.at("description"), look.at("color")};
    }
    m.seeds = wholeNumberFrom<std::uint64_t>(j.at("seeds"), "seeds", source);
    for (const auto& s : j.at("scenes")) {
      requireKnownKeys(s, {"name", "file", "hash", "group"}, "scenes[]", source);
      m.scenes.push_back({s.at("name").get<std::string>(), s.at("file").get<std::string>(),
                          hashFrom(s.at("hash"), "scenes[].hash", source),
                          s.value("group", std::string())});
    }
    m.command = j.at("command").get<std::vector<std::string>>();
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": malformed batch manifest: " + e.what());
  }
}

std::optional<BatchManifest> BatchFolder::readManifest() const {
  const fs::path file = manifestFile();
  const auto j = readJson(file);
  if (!j) return std::nullopt;
  return manifestFromJson(*j, file.string());
}

void BatchFolder::writeManifest(const BatchManifest& manifest) const {
  writeJson(manifestFile(), manifestToJson(manifest));
}

void BatchFolder::refuseForeignContent() const {
  std::error_code ec;
  if (!fs::exists(root_, ec) || holdsBatch(root_)) return;
  if (!fs::is_directory(root_, ec)) throw InputError(root_.string() + ": is not a folder");
  if (!fs::is_empty(root_, ec)) {
    throw InputError(root_.string() +
                     ": holds files but no camcov batch (no batch.json); write the results into "
                     "a new or empty folder, or into one a batch made");
  }
}

void BatchFolder::refuseToReplaceContent(const fs::path& output) const {
  std::error_code ec;
  if (!fs::exists(output, ec) || fs::equivalent(output, reportFile(), ec)) return;
  for (const auto& entry : fs::recursive_directory_iterator(root_, ec)) {
    if (entry.is_regular_file(ec) && fs::equivalent(entry.path(), output, ec)) {
      throw InputError(output.string() + ": is part of the results folder " + root_.string() +
                       " that this report reads; write the report elsewhere");
    }
  }
}

void BatchFolder::removeStaleTemporaries() const {
  for (const fs::path& dir : {root_, runsDir(), omplDir(), optimumDir()}) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      if (isTemporaryFile(entry.path())) fs::remove(entry.path(), ec);
    }
  }
}

std::optional<JobOutcome> BatchFolder::finishedJob(const std::string& stem,
                                                   const params::Parameters& parameters,
                                                   std::uint64_t sceneHash) const {
  const fs::path file = runFile(stem);
  if (!fs::exists(file)) return std::nullopt;
  RunRecord run;
  try {
    run = loadRunFile(file);
  } catch (const InputError&) {
    return std::nullopt;  // unreadable: run it again, the new file replaces it atomically
  }
  // A batch defers the flush of its run files (Durability::Deferred): after a power cut, one
  // that reads but whose CSV was cut short runs again too.
  if (!runCsvIsWhole(run, file)) return std::nullopt;
  if (run.metadata.sceneHash != sceneHash ||
      params::toJson(run.metadata.parameters) != params::toJson(parameters)) {
    return std::nullopt;
  }
  return JobOutcome{run.metadata.scene, run.metadata.method, run.metadata.seed, false, "",
                    run.summary};
}

void BatchFolder::writeFailure(const std::string& stem, const JobOutcome& o) const {
  writeJson(errorFile(stem), {{"format", "camcov-failure/1"},
                              {"scene", o.scene},
                              {"method", o.method},
                              {"seed", o.seed},
                              {"error", o.error}});
}

void BatchFolder::removeFailure(const std::string& stem) const {
  std::error_code ec;
  fs::remove(errorFile(stem), ec);
}

void BatchFolder::removeJobsOf(const std::string& method) const {
  // By what each file says it holds: a file name cannot tell "a-b" of method "b" from
  // scene "a" of method "b-…".
  std::error_code ec;
  std::vector<fs::path> doomed;
  for (const auto& entry : fs::directory_iterator(runsDir(), ec)) {
    if (entry.path().extension() != ".json") continue;
    std::optional<nlohmann::json> j;
    try {
      j = readJson(entry.path());
    } catch (const InputError&) {
      continue;  // not ours to judge: a damaged file is run again by its own job
    }
    if (j && j->is_object() && j->value("method", "") == method) {
      doomed.push_back(entry.path());
      if (entry.path().stem().extension() != ".error")
        doomed.push_back(fs::path(entry.path()).replace_extension(".csv"));
    }
  }
  for (const auto& file : doomed)
    fs::remove(file, ec);
}

std::vector<JobOutcome> BatchFolder::allJobs() const {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(runsDir(), ec)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<JobOutcome> jobs;
  for (const auto& file : files) {
    if (file.stem().extension() == ".error") {
      const nlohmann::json j = *readJson(file);
      jobs.push_back({j.at("scene"), j.at("method"), j.at("seed"), true, j.at("error"), {}});
      continue;
    }
    const RunRecord run = loadRunFile(file);
    jobs.push_back(
        {run.metadata.scene, run.metadata.method, run.metadata.seed, false, "", run.summary});
  }
  return jobs;
}

std::map<std::string, JobTiming> BatchFolder::readTimings() const {
  std::map<std::string, JobTiming> timings;
  const auto j = readJson(timingsFile());
  if (!j) return timings;
  for (const auto& [stem, t] : j->items()) {
    timings[stem] = {t.at("wallSeconds").get<double>(), t.at("cpuSeconds").get<double>()};
  }
  return timings;
}

void BatchFolder::writeTimings(const std::map<std::string, JobTiming>& timings) const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [stem, t] : timings) {
    j[stem] = {{"wallSeconds", t.wallSeconds}, {"cpuSeconds", t.cpuSeconds}};
  }
  writeJson(timingsFile(), j);
}

void BatchFolder::writeSummary(const BatchSummary& summary) const {
  writeJson(summaryFile(), summaryToJson(summary));
  writeFileAtomically(summaryCsvFile(), summaryToCsv(summary));
}

}  // namespace camcov::records
