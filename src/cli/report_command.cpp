// `camcov report RESULTS_DIR [-o report.html]`: (re)build the HTML report of a bench or merge
// results folder, e.g. after `camcov video` added videos or on another machine.
// `camcov report DIR1 DIR2... -o FILE`, or `camcov report SWEEP_DIR` on a folder of results
// folders (scripts/slurm_sweep.sh): one report with the settings side by side.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/command.h"
#include "records/batch_folder.h"
#include "reports/report_builder.h"
#include "reports/settings_report.h"
#include "util/input_error.h"

namespace camcov::cli {
namespace {

namespace fs = std::filesystem;

struct ReportOptions {
  std::vector<std::string> folders;
  std::string out;               // empty: FOLDER/report.html for one folder
  std::string referenceSetting;  // settings report: empty = the first folder
};

int report(const ReportOptions& o) {
  const bool oneBatch = o.folders.size() == 1 && records::BatchFolder::holdsBatch(o.folders[0]);
  if (o.folders.size() > 1 && o.out.empty()) {
    throw InputError("a report over several folders needs --out FILE");
  }
  const fs::path out =
      o.out.empty() ? records::BatchFolder(o.folders[0]).reportFile() : fs::path(o.out);
  if (oneBatch) {
    if (!o.referenceSetting.empty()) {
      throw InputError("--reference-setting compares several results folders; " + o.folders[0] +
                       " is one");
    }
    reports::writeReport(o.folders[0], out);
  } else {
    std::vector<fs::path> folders(o.folders.begin(), o.folders.end());
    if (folders.size() == 1) folders = reports::resultsFoldersIn(folders[0]);
    reports::writeSettingsReport(folders, o.referenceSetting, out);
  }
  std::cout << fmt::format("wrote {}\n", out.string());
  return 0;
}

}  // namespace

Registration addReportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "report",
      "Write the HTML report (figures, statistics, parameters) of a results folder, or of "
      "several folders run with different settings, side by side");
  auto o = std::make_shared<ReportOptions>();
  cmd->add_option("folders", o->folders,
                  "results folder of camcov bench or camcov merge; several of them, or one "
                  "folder holding several (a sweep), for the settings side by side")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out,-o", o->out,
                  "report file (default: FOLDER/report.html; required for several folders)");
  cmd->add_option("--reference-setting", o->referenceSetting,
                  "settings side by side: the folder (name or path as given) every other one is "
                  "compared with (default: the first)");
  return {cmd, [o] { return report(*o); }};
}

}  // namespace camcov::cli
