#pragma once
// What the report of settings side by side shows, read from several results folders
// of the same study run with different parameters: e.g. the folders OUT/<key=value_...> of
// scripts/slurm_sweep.sh. Per folder its manifest and every run's average coverage and
// utilization (from runs/, so the comparisons see the seeds, not only the means); across the
// folders what differs: the parameters (from each batch.json), and anything else that makes
// two columns not comparable (methods, seeds, scene files, tool version).
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "records/batch_folder.h"
#include "reports/report_data.h"

namespace camcov::reports {

// One method on one scene in one setting: a value per finished run (seed order is irrelevant
// to the statistics), and the number of failed runs.
struct SettingRuns {
  std::vector<double> averageCoverage;  // eq. (4)
  std::vector<double> averageUtilization;
  int failed = 0;
};

struct Setting {
  std::string name;   // the folder's name; its path as given when two folders share a name
  std::string label;  // its differing parameters by symbol, "K=50 τ=1.2"; else the name
  std::filesystem::path folder;
  records::BatchManifest manifest;
  std::map<std::string, std::map<std::string, SettingRuns>> runs;  // scene → method → runs
  std::string reportUrl;  // its own report.html relative to the settings report; empty if none
};

// A parameter whose value is not the same in every setting.
struct DifferingParameter {
  std::string key;                  // "global.K"
  std::string symbol;               // "K"; the key for our extensions, which have no symbol
  std::vector<std::string> values;  // one per setting, formatted as --set takes them
};

struct SettingsData {
  std::vector<Setting> settings;  // in the order given (a sweep's folders in natural order)
  std::size_t reference = 0;      // the setting every other one is compared with
  std::vector<DifferingParameter> parameters;
  std::vector<std::string> notes;            // other differences, as sentences (plain text)
  std::vector<std::string> scenes;           // every scene of any setting, natural order
  std::map<std::string, SceneGroup> groups;  // of each scene
  std::vector<std::string> methods;          // every method of any setting, the table's order
};

// The results folders directly inside `root` (those with a batch.json), in natural order of
// their names. Throws InputError if there is none.
std::vector<std::filesystem::path> resultsFoldersIn(const std::filesystem::path& root);

// Reads every folder; `reference` names the reference setting (a folder's name or its path as
// given; empty: the first). `reportFile` is where the report will be written, for the links.
// Throws InputError for a folder that is not a results folder, fewer than one folder, or an
// unknown reference.
SettingsData loadSettingsData(const std::vector<std::filesystem::path>& folders,
                              const std::string& reference,
                              const std::filesystem::path& reportFile);

}  // namespace camcov::reports
