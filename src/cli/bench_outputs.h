#pragma once
// What `camcov bench` and `camcov merge` write once the runs exist: the summary (JSON, CSV),
// the OMPL benchmark logs, the videos, the report, and a table on stdout.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "results/batch_folder.h"
#include "results/batch_summary.h"
#include "results/video_choice.h"

namespace camcov::cli {

// The options both commands share.
struct BenchOutputOptions {
  bool noReport = false;
  std::string videos = "median";
  void addTo(CLI::App& cmd);
  // InputError for a bad --videos: called before any job runs.
  results::VideoChoice videoChoice() const { return results::parseVideoChoice(videos); }
};

// Returns the exit code: 0, or 1 if some job failed. Videos are made on `workers` threads.
int writeBenchOutputs(const results::BatchFolder& folder, const results::BatchManifest& manifest,
                      const std::vector<results::JobOutcome>& outcomes,
                      const BenchOutputOptions& options, unsigned workers);

}  // namespace camcov::cli
