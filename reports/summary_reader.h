#pragma once
// Reads summary.json back into a BatchSummary: the inverse of results::summaryToJson, so the
// report shows exactly the numbers `camcov bench` printed and wrote.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "results/batch_summary.h"

namespace camcov::reports {

// Throws InputError naming `source` if the document is not a camcov summary.
results::BatchSummary summaryFromJson(const nlohmann::json& j, const std::string& source);
results::BatchSummary loadSummaryFile(const std::filesystem::path& file);

}  // namespace camcov::reports
