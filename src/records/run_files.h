#pragma once
// A run's results files: JSON (metadata with every parameter, summary, time series, events)
// and CSV (the time series, one row per step). Same run, same bytes: no clocks, no
// machine-dependent fields; numbers in shortest round-trip form.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "records/atomic_file.h"
#include "records/run_record.h"

namespace camcov::records {

inline constexpr const char* kRunFormat = "camcov-run/2";

// A run's results file, as text (its JSON pretty-printed, one space a level).
std::string runJsonText(const RunRecord& run);
// The same, as a document.
nlohmann::json runToJson(const RunRecord& run);
// A run's summary as its results file writes it (runToJson's "summary").
nlohmann::json summaryJson(const sim::RunSummary& summary);
// The inverse of runToJson (null distances read back as infinity). Throws InputError naming
// `source` if the document is not a camcov run.
RunRecord runFromJson(const nlohmann::json& j, const std::string& source);
RunRecord loadRunFile(const std::filesystem::path& file);
std::string runToCsv(const RunRecord& run);

// "<scene>-<method>-seed<N>": the stem of a run's files (and of its video in a batch).
std::string runStem(const std::string& scene, const std::string& method, std::uint64_t seed);
std::string runStem(const RunMetadata& metadata);
// The scene of stem "<scene>-<method>-seed<N>", made by one of `methods`: method names may hold
// dashes (camcov-dec), so the longest that ends the stem is taken; nullopt if none does.
std::optional<std::string> sceneOfStem(const std::string& stem,
                                       const std::vector<std::string>& methods);

// Writes <folder>/<stem>.json and <folder>/<stem>.csv atomically, flushed to disk or not as
// `durability` says; returns the JSON path.
std::filesystem::path writeRunFiles(const RunRecord& run, const std::filesystem::path& folder,
                                    Durability durability = Durability::Synced);

// Whether the CSV beside a run's JSON file (`run`, read from `jsonFile`) is whole: its header
// and a line for each of the run's steps, the last one ended. Files written with their flush
// deferred may be empty or cut short after a power cut; a JSON file cut short does not read.
bool runCsvIsWhole(const RunRecord& run, const std::filesystem::path& jsonFile);

}  // namespace camcov::records
