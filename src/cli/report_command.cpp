// `camcov report RESULTS_DIR [-o report.html]`: (re)build the HTML report of a bench or merge
// results folder, e.g. after `camcov video` added videos or on another machine.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/command.h"
#include "reports/report_builder.h"

namespace camcov::cli {
namespace {

struct ReportOptions {
  std::string results;
  std::string out;  // empty: RESULTS_DIR/report.html
};

int report(const ReportOptions& o) {
  const std::filesystem::path out = o.out.empty() ? std::filesystem::path(o.results) / "report.html"
                                                  : std::filesystem::path(o.out);
  reports::writeReport(o.results, out);
  std::cout << fmt::format("wrote {}\n", out.string());
  return 0;
}

}  // namespace

Registration addReportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "report", "Write the HTML report (figures, statistics, parameters) of a results folder");
  auto o = std::make_shared<ReportOptions>();
  cmd->add_option("results", o->results, "results folder of camcov bench or camcov merge")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out,-o", o->out, "report file (default: RESULTS_DIR/report.html)");
  return {cmd, [o] { return report(*o); }};
}

}  // namespace camcov::cli
