#pragma once
// Reads summary.json back into a BatchSummary: the inverse of records::summaryToJson, so the
// report shows exactly the numbers `camcov bench` printed and wrote.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "records/batch_summary.h"

namespace camcov::reports {

// Throws InputError naming `source` if the document is not a camcov summary.
records::BatchSummary summaryFromJson(const nlohmann::json& j, const std::string& source);
records::BatchSummary loadSummaryFile(const std::filesystem::path& file);

}  // namespace camcov::reports
