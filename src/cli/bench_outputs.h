#pragma once
// What `camcov bench` and `camcov merge` write once the runs exist: the summary (JSON, CSV),
// the OMPL benchmark logs, and a table on stdout.
#include <vector>

#include "results/batch_folder.h"
#include "results/batch_summary.h"

namespace camcov::cli {

// Returns the exit code: 0, or 1 if some job failed. With `report`, also writes report.html.
int writeBenchOutputs(const results::BatchFolder& folder, const results::BatchManifest& manifest,
                      const std::vector<results::JobOutcome>& outcomes, bool report);

}  // namespace camcov::cli
