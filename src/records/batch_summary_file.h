#pragma once
// The batch summary as files: summary.json (format camcov-summary/2) and summary.csv, written
// with sorted keys and shortest round-trip numbers so one process and N shards plus a merge
// give the same bytes, and summary.json read back so a report shows exactly the numbers the
// batch wrote. Apart from the summary itself (records/batch_summary.h), which the bench and the
// reports build and read without caring how it is stored.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "records/batch_summary.h"

namespace camcov::records {

nlohmann::json summaryToJson(const BatchSummary& summary);
// The inverse of summaryToJson. Throws InputError naming `source` if the document is not a
// camcov summary, or holds a key summaryToJson does not write (a misspelled one would
// otherwise be left unread).
BatchSummary summaryFromJson(const nlohmann::json& j, const std::string& source);
BatchSummary loadSummaryFile(const std::filesystem::path& file);
std::string summaryToCsv(const BatchSummary& summary);

}  // namespace camcov::records
