#pragma once
// What `camcov bench` and `camcov merge` write once the runs exist: the summary (JSON, CSV),
// the OMPL benchmark logs, the videos, the explorer pages, the report, and a table on stdout.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "records/batch_folder.h"
#include "records/batch_summary.h"
#include "records/video_choice.h"

namespace camcov::cli {

// The options both commands share.
struct BenchOutputOptions {
  bool noReport = false;
  std::string videos = "median";
  std::string explorer = "median";  // explore/<scene>.html: none, median or best
  std::string reference;            // the method the others are tested against; empty: the baseline
  std::int64_t optimumBudget = 200000;  // reward evaluations per optimum/<scene>.json; 0: none
  void addTo(CLI::App& cmd);
  // InputError for a bad --videos.
  records::VideoChoice videoChoice() const { return records::parseVideoChoice(videos); }
  // InputError for a bad --explorer (all seeds of a scene on one page would not be read).
  records::VideoChoice explorerChoice() const;
  // Both checks, before any job runs.
  void check() const {
    videoChoice();
    explorerChoice();
  }
  // The reference among `methods`; InputError if --reference names another.
  std::string referenceAmong(const std::vector<std::string>& methods) const;
};

// Returns the exit code: 0, or 1 if some job failed. Videos are made on `workers` threads.
int writeBenchOutputs(const records::BatchFolder& folder, const records::BatchManifest& manifest,
                      const std::vector<records::JobOutcome>& outcomes,
                      const BenchOutputOptions& options, unsigned workers);

}  // namespace camcov::cli
