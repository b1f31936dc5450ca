#include "bench/finish_bench.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "bench/explorer_pages.h"
#include "bench/optima.h"
#include "bench/videos.h"
#include "control/methods.h"
#include "records/ompl_benchmark_log.h"
#include "reports/report_builder.h"
#include "util/counted.h"
#include "util/input_error.h"

namespace camcov::bench {

void BenchOutputOptions::check() const {
  videoChoice();
  explorerChoice();
  if (optimumBudget < 0 || optimumBudget > (std::int64_t{1} << 40))
    throw InputError(
        fmt::format("--optimum-budget {}: expected a count in [0, 2^40]", optimumBudget));
}

records::VideoChoice BenchOutputOptions::explorerChoice() const {
  const records::VideoChoice choice = records::parseVideoChoice(explorer, "--explorer");
  if (choice == records::VideoChoice::All) {
    throw InputError("--explorer " + explorer + ": one of none, median, best");
  }
  return choice;
}

std::string BenchOutputOptions::referenceAmong(const std::vector<std::string>& methods) const {
  if (reference.empty()) return control::referenceAmong(methods);
  if (std::find(methods.begin(), methods.end(), reference) == methods.end())
    throw InputError("--reference " + reference + ": not among the batch's methods");
  return reference;
}

namespace {

// "6/2/0" wins, ties, losses (and "+3?" undecided).
std::string tallyText(const records::Tally& t) {
  return fmt::format("{}/{}/{}{}", t.wins, t.ties, t.losses,
                     t.undecided > 0 ? fmt::format("+{}?", t.undecided) : "");
}

// Per group of scenes (family or folder), when there is more than one: each method's mean
// coverage there, and the wins/ties/losses of every comparison the totals count.
void reportGroups(const records::BatchSummary& summary, const std::vector<std::string>& methods,
                  BenchObserver& observer) {
  if (summary.groups.size() < 2) return;
  std::vector<std::string> names;
  for (const auto* tallies : {&summary.tallies, &summary.pairTallies}) {
    for (const auto& t : *tallies)
      names.push_back(t.method + " vs " + (t.against.empty() ? summary.reference : t.against));
  }
  std::string header = fmt::format("{:<20} {:>6}", "by family or folder", "scenes");
  for (const auto& method : methods)
    header += fmt::format(" {:>9}", method);
  for (const auto& name : names)
    header += fmt::format("  {:>16}", name);
  observer.report(header + "  (mean average coverage; wins/ties/losses)");
  for (const auto& g : summary.groups) {
    std::string line = fmt::format("{:<20} {:>6}", g.name, g.scenes.size());
    for (const auto& method : methods) {
      const auto it = std::find_if(g.meanCoverage.begin(), g.meanCoverage.end(),
                                   [&](const auto& m) { return m.first == method; });
      line += it == g.meanCoverage.end() ? fmt::format(" {:>9}", "-")
                                         : fmt::format(" {:>9.3f}", it->second);
    }
    for (const auto* tallies : {&g.tallies, &g.pairTallies}) {
      for (const auto& t : *tallies)
        line += fmt::format("  {:>16}", tallyText(t));
    }
    observer.report(line);
  }
}

// Average coverage per scene and method, then each method against the reference.
void reportSummary(const records::BatchSummary& summary, const std::vector<std::string>& methods,
                   BenchObserver& observer) {
  std::map<std::pair<std::string, std::string>, const records::MethodSummary*> rows;
  for (const auto& m : summary.methods)
    rows[{m.scene, m.method}] = &m;
  std::string header = fmt::format("{:<34}", "scene (average coverage)");
  for (const auto& method : methods)
    header += fmt::format(" {:>15}", method);
  for (const auto& method : methods) {
    if (method != summary.reference)
      header += fmt::format("  {:<26}", method + " vs " + summary.reference);
  }
  observer.report(header);
  for (const auto& scene : summary.scenes) {
    std::string line = fmt::format("{:<34}", scene);
    for (const auto& method : methods) {
      const auto it = rows.find({scene, method});
      line += it == rows.end() || it->second->runs == 0
                  ? fmt::format(" {:>15}", "-")
                  : fmt::format(" {:>15}", fmt::format("{:.3f} ± {:.3f}", it->second->coverage.mean,
                                                       it->second->coverage.sd));
    }
    for (const auto& method : methods) {
      if (method == summary.reference) continue;
      const records::Comparison* c = summary.comparison(scene, method);
      line += fmt::format("  {:<26}", c == nullptr ? std::string("-") : records::verdictText(*c));
    }
    observer.report(line);
  }
  // Against the reference, then the others pairwise.
  int undecided = 0;
  for (const auto* tallies : {&summary.tallies, &summary.pairTallies}) {
    for (const auto& t : *tallies) {
      observer.report(
          fmt::format("{} against {}: wins {}, ties {}, losses {}{}", t.method,
                      t.against.empty() ? summary.reference : t.against, t.wins, t.ties, t.losses,
                      t.undecided > 0 ? fmt::format(", undecided {}", t.undecided) : ""));
      undecided += t.undecided;
    }
  }
  if (undecided > 0) {
    observer.report(fmt::format(
        "note: {} undecided: with so few seeds no difference can reach p < {}; "
        "run at least {} seeds per method (--seeds {})",
        counted(static_cast<std::size_t>(undecided), "comparison is", "comparisons are"),
        records::kSignificance, records::seedsToReachSignificance(),
        records::seedsToReachSignificance()));
  }
  reportGroups(summary, methods, observer);
  observer.report(counted(summary.failures.size(), "failed job", "failed jobs"));
}

}  // namespace

records::BatchSummary finishBench(const records::BatchFolder& folder,
                                  const records::BatchManifest& manifest,
                                  const std::vector<records::JobOutcome>& outcomes,
                                  const std::map<std::string, records::OmplRun>& omplRuns,
                                  const BenchOutputOptions& options, unsigned workers,
                                  BenchObserver& observer) {
  std::map<std::string, std::string> groupOf;
  for (const records::SceneEntry& scene : manifest.scenes)
    groupOf[scene.name] = scene.group;
  // Listed in the one order of methods, whatever order --methods gave them in.
  const std::vector<std::string> methods = control::inMethodOrder(manifest.methods);
  const records::BatchSummary summary =
      records::summarize(outcomes, options.referenceAmong(manifest.methods), methods, groupOf);
  folder.writeSummary(summary);
  const auto logs = records::writeOmplBenchmarkLogs(folder, manifest, workers, omplRuns);
  reportSummary(summary, methods, observer);
  for (const auto& f : summary.failures) {
    observer.report(fmt::format("  failed: {} {} seed {}: {}", f.scene, f.method, f.seed, f.error));
  }
  observer.report(fmt::format(
      "wrote {}, {} and {} OMPL benchmark logs in {}", folder.summaryFile().string(),
      folder.summaryCsvFile().filename().string(), logs.size(), folder.omplDir().string()));
  // Before the report, which embeds what it finds in videos/.
  const auto chosen = records::chooseVideoRuns(summary, outcomes, options.videoChoice());
  if (!chosen.empty()) {
    observer.report(writeBenchVideos(folder, chosen, workers, observer)
                        .describe("video", "videos", folder.videosDir().string()));
  }
  const auto explored = records::chooseVideoRuns(summary, outcomes, options.explorerChoice());
  if (!explored.empty()) {
    observer.report(
        writeBenchExplorers(folder, explored, observer)
            .describe("run explorer page", "run explorer pages", folder.exploreDir().string()));
  }
  const OutputBatch optima =
      writeBenchOptima(folder, manifest, options.optimumBudget, workers, observer);
  if (optima.written + optima.upToDate + optima.failed > 0)
    observer.report(
        optima.describe("offline optimum", "offline optima", folder.optimumDir().string()));
  if (!options.noReport) {
    reports::writeReport(folder.root(), folder.reportFile());
    observer.report(fmt::format("wrote {}", folder.reportFile().string()));
  }
  return summary;
}

}  // namespace camcov::bench
