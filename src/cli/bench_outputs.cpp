#include "cli/bench_outputs.h"

#include <fmt/format.h>

#include <iostream>
#include <map>

#include "cli/bench_videos.h"
#include "records/ompl_benchmark_log.h"
#include "reports/report_builder.h"

namespace camcov::cli {

void BenchOutputOptions::addTo(CLI::App& cmd) {
  cmd.add_flag("--no-report", noReport, "do not write report.html");
  cmd.add_option("--videos", videos,
                 "videos/ for the report: none; median (per scene and method, the seed with the "
                 "median average coverage); best (the highest); all")
      ->capture_default_str();
}

int writeBenchOutputs(const records::BatchFolder& folder, const records::BatchManifest& manifest,
                      const std::vector<records::JobOutcome>& outcomes,
                      const BenchOutputOptions& options, unsigned workers) {
  const records::BatchSummary summary = records::summarize(outcomes);
  folder.writeSummary(summary);
  const auto logs = records::writeOmplBenchmarkLogs(folder, manifest.parameters);

  std::map<std::pair<std::string, std::string>, const records::MethodSummary*> rows;
  for (const auto& m : summary.methods)
    rows[{m.scene, m.method}] = &m;
  auto cell = [&](const std::string& scene, const std::string& method) {
    const auto it = rows.find({scene, method});
    if (it == rows.end() || it->second->runs == 0) return std::string("-");
    const auto& c = it->second->coverage;
    return fmt::format("{:.3f} ± {:.3f}", c.mean, c.sd);
  };
  std::cout << fmt::format("{:<34} {:>15} {:>15}  {:<6} {}\n", "scene (average coverage)", "paper",
                           "local", "winner", "p");
  for (const auto& c : summary.scenes) {
    std::cout << fmt::format("{:<34} {:>15} {:>15}  {:<6} {}\n", c.scene, cell(c.scene, "paper"),
                             cell(c.scene, "local"), c.winner.empty() ? "-" : c.winner,
                             c.winner.empty() ? std::string("-") : fmt::format("{:.3g}", c.pValue));
  }
  std::cout << fmt::format("paper wins {}, ties {}, local wins {}; {} failed jobs\n",
                           summary.paperWins, summary.ties, summary.localWins,
                           summary.failures.size());
  for (const auto& f : summary.failures) {
    std::cout << fmt::format("  failed: {} {} seed {}: {}\n", f.scene, f.method, f.seed, f.error);
  }
  std::cout << fmt::format(
      "wrote {}/summary.json, summary.csv and {} OMPL benchmark logs in {}/ompl\n",
      folder.root().string(), logs.size(), folder.root().string());
  // Before the report, which embeds what it finds in videos/.
  const auto chosen = records::chooseVideoRuns(summary, outcomes, options.videoChoice());
  if (!chosen.empty()) {
    const VideoBatch videos = writeBenchVideos(folder, chosen, workers);
    std::cout << fmt::format("wrote {} videos in {}/videos ({} up to date{})\n", videos.written,
                             folder.root().string(), videos.upToDate,
                             videos.failed ? fmt::format(", {} not written", videos.failed) : "");
  }
  if (!options.noReport) {
    reports::writeReport(folder.root(), folder.root() / "report.html");
    std::cout << fmt::format("wrote {}\n", (folder.root() / "report.html").string());
  }
  return summary.failures.empty() ? 0 : 1;
}

}  // namespace camcov::cli
