#pragma once
// The report of settings side by side: several results folders of one study, run
// with different parameters (e.g. the folders of scripts/slurm_sweep.sh), in one offline HTML
// file. What differs between them (parameters from each batch.json, and warnings when methods,
// seeds or scene files differ too); per method the mean over scenes and the wins, ties and
// losses of every setting against the reference setting; the per-scene differences as box
// plots; and the table scenes × methods × settings of mean ± sd average coverage, each cell
// tested against the reference setting's (two-sided Mann-Whitney U over seeds, as the summary
// tests methods).
#include <filesystem>
#include <string>
#include <vector>

#include "reports/build_context.h"
#include "reports/settings_data.h"

namespace camcov::reports {

// The document; a pure function of its inputs.
std::string buildSettingsReportHtml(const SettingsData& data, const BuildContext& context);

// Reads the folders and writes the report to `reportFile` atomically (loadSettingsData says
// what throws).
void writeSettingsReport(const std::vector<std::filesystem::path>& folders,
                         const std::string& reference, const std::filesystem::path& reportFile);

}  // namespace camcov::reports
