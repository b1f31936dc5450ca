#pragma once
// The layout of a batch's --out folder (SPEC section 7), read and written only here:
//   batch.json           what was asked: parameters, methods, seeds, scenes (name, file, hash)
//   runs/<stem>.json     one finished job, as `camcov run` writes it (+ <stem>.csv)
//   runs/<stem>.error.json   one failed job: its error
//   timings.json         wall and CPU seconds per job (machine-dependent, kept apart)
//   summary.json/.csv    the summary; ompl/<scene>.log; report.html
//   optimum/<scene>.json the offline optimum of a scene that holds still (optimum_file.h)
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "params/parameters.h"
#include "records/batch_summary.h"
#include "records/run_record.h"

namespace camcov::records {

struct SceneEntry {
  std::string name;
  std::string file;
  std::uint64_t hash = 0;
  // What the summary groups it under: the family a generated scene was drawn from, else the
  // name of the folder its file is in. Empty in folders written before scenes had groups.
  std::string group;
};

// How a method the build does not know (a Python controller) asked to be shown.
struct MethodLook {
  std::string description;
  std::string color;  // CSS; empty: the reports choose one
};

struct BatchManifest {
  std::string toolVersion;
  params::Parameters parameters;
  std::vector<std::string> methods;
  // Per method, what made its results ("c++ <code identity>", "python <fingerprint>"): a
  // resume with other code is refused like one with other parameters. Empty in folders
  // written before methods had identities.
  std::map<std::string, std::string> methodIdentities;
  // The brought methods' own descriptions and colours, for the reports.
  std::map<std::string, MethodLook> methodLooks;
  std::uint64_t seeds = 0;  // seeds 1..seeds
  std::vector<SceneEntry> scenes;
  std::vector<std::string> command;  // argv, for the report's header
};

struct JobTiming {
  double wallSeconds = 0.0;
  double cpuSeconds = 0.0;
};

// A results folder, and the one owner of every name inside it: batch.json, runs/,
// summary.json and .csv, timings.json, ompl/, optimum/, videos/, explore/ and report.html.
class BatchFolder {
 public:
  explicit BatchFolder(std::filesystem::path root) : root_(std::move(root)) {}
  const std::filesystem::path& root() const { return root_; }
  // Whether `dir` holds a batch (its manifest), without reading it.
  static bool holdsBatch(const std::filesystem::path& dir) {
    return std::filesystem::exists(BatchFolder(dir).manifestFile());
  }
  std::filesystem::path manifestFile() const { return root_ / "batch.json"; }
  std::filesystem::path summaryFile() const { return root_ / "summary.json"; }
  std::filesystem::path summaryCsvFile() const { return root_ / "summary.csv"; }
  std::filesystem::path timingsFile() const { return root_ / "timings.json"; }
  std::filesystem::path omplDir() const { return root_ / "ompl"; }
  std::filesystem::path videosDir() const { return root_ / "videos"; }
  std::filesystem::path videoFile(const std::string& stem) const {
    return videosDir() / (stem + ".mp4");
  }
  std::filesystem::path exploreDir() const { return root_ / "explore"; }
  std::filesystem::path explorerPage(const std::string& scene) const {
    return exploreDir() / (scene + ".html");
  }
  std::filesystem::path reportFile() const { return root_ / "report.html"; }
  std::filesystem::path runsDir() const { return root_ / "runs"; }
  std::filesystem::path runFile(const std::string& stem) const {
    return runsDir() / (stem + ".json");
  }
  std::filesystem::path errorFile(const std::string& stem) const {
    return runsDir() / (stem + ".error.json");
  }

  std::filesystem::path optimumDir() const { return root_ / "optimum"; }
  std::filesystem::path optimumFile(const std::string& scene) const {
    return optimumDir() / (scene + ".json");
  }

  std::optional<BatchManifest> readManifest() const;
  void writeManifest(const BatchManifest& manifest) const;

  // InputError if the folder exists and holds something but no batch (no batch.json): a batch
  // written into it would replace whatever files there share its names (summary.json,
  // report.html, runs/...). A new or empty folder, or one holding a batch, is fine.
  void refuseForeignContent() const;
  // InputError unless `output` may be written by a command that reads this folder (a report):
  // a file the folder holds (its batch, runs, summaries, logs, pages, videos, by identity, so
  // another spelling of the path or a link to it counts) is its content, which the command
  // reads; only the folder's own report file may be written over.
  void refuseToReplaceContent(const std::filesystem::path& output) const;

  // Deletes "*.tmp-*" files a killed batch may have left.
  void removeStaleTemporaries() const;
  // The finished job's summary if runs/<stem>.json reads, its CSV is whole, and it was made
  // with these parameters from a scene with this hash; nullopt means the job must run (again).
  std::optional<JobOutcome> finishedJob(const std::string& stem,
                                        const params::Parameters& parameters,
                                        std::uint64_t sceneHash) const;
  void writeFailure(const std::string& stem, const JobOutcome& outcome) const;
  void removeFailure(const std::string& stem) const;
  // Removes the results and failures of every job of `method` (the files named
  // <scene>-<method>-seed<N>.*), so a method whose code changed is run again whole.
  void removeJobsOf(const std::string& method) const;
  // Every run and failure found in runs/ (for merging).
  std::vector<JobOutcome> allJobs() const;

  std::map<std::string, JobTiming> readTimings() const;
  void writeTimings(const std::map<std::string, JobTiming>& timings) const;

  void writeSummary(const BatchSummary& summary) const;

 private:
  std::filesystem::path root_;
};

nlohmann::json manifestToJson(const BatchManifest& m);
BatchManifest manifestFromJson(const nlohmann::json& j, const std::string& source);

}  // namespace camcov::records
