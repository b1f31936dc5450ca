#include "cli/bench_output_options.h"

#include "cli/number_options.h"

namespace camcov::cli {

void addBenchOutputOptions(CLI::App& cmd, bench::BenchOutputOptions& options) {
  cmd.add_flag("--no-report", options.noReport, "do not write report.html");
  cmd.add_option("--videos", options.videos,
                 "videos/ for the report: none; median (per scene and method, the seed with the "
                 "median average coverage); best (the highest); all")
      ->capture_default_str();
  cmd.add_option("--explorer", options.explorer,
                 "explore/<scene>.html, the run explorer for the report: none; median (each "
                 "method's median-seed run, side by side); best")
      ->capture_default_str();
  cmd.add_option("--reference", options.reference,
                 "the method every other is tested against (default: the baseline, local, if "
                 "run; else the first method)");
  cmd.add_option("--optimum-budget", options.optimumBudget,
                 "reward evaluations of the offline optimum (camcov optimum) searched for each "
                 "scene that holds still, for the report to set final coverage against; 0: none")
      ->check(within(0, 0x1p40))
      ->capture_default_str();
}

}  // namespace camcov::cli
