// Section 1: what was run, where, how long it took, and the outcome in one sentence.
#include <fmt/format.h>

#include <filesystem>

#include "control/methods.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/sections.h"
#include "util/readable_number.h"

namespace camcov::reports {
namespace {

// argv as a POSIX shell would need it typed, so the command can be pasted to rerun; the binary
// by its name, as a reader types it (its absolute path says where the author built it, and
// pushes the command past the page's width).
std::string shellCommand(std::vector<std::string> argv) {
  if (!argv.empty()) argv.front() = std::filesystem::path(argv.front()).filename().string();
  std::string line;
  for (const auto& arg : argv) {
    if (!line.empty()) line += ' ';
    const bool plain = !arg.empty() && arg.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyz"
                                           "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789-_./=:,+@%") == std::string::npos;
    if (plain) {
      line += arg;
      continue;
    }
    line += '\'';
    for (const char c : arg)
      line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

std::string duration(double seconds) {
  if (seconds < 120.0) return fmt::format("{:.1f} s", seconds);
  if (seconds < 7200.0) return fmt::format("{:.1f} min", seconds / 60.0);
  return fmt::format("{:.2f} h", seconds / 3600.0);
}

// Mean over scenes of each method's mean coverage: one number per method for the lede.
std::string meanCoverageByMethod(const ReportData& data) {
  std::vector<std::string> parts;
  for (const auto& method : control::inMethodOrder(data.manifest.methods)) {
    double sum = 0.0;
    int n = 0;
    for (const auto& m : data.summary.methods) {
      if (m.method != method || m.runs == 0) continue;
      sum += m.coverage.mean;
      ++n;
    }
    if (n == 0) continue;
    parts.push_back(methodMark(methodStyle(method).color,
                               escapeXml(methodStyle(method).label) + " " + fixed(sum / n, 3)));
  }
  return join(parts, ", ");
}

}  // namespace

std::string headerSection(const ReportData& data, const BuildContext& context) {
  const auto& m = data.manifest;
  const auto& s = data.summary;
  const std::size_t jobs = m.scenes.size() * m.methods.size() * m.seeds;
  double wall = 0.0, cpu = 0.0;
  for (const auto& [stem, t] : data.timings) {
    wall += t.wallSeconds;
    cpu += t.cpuSeconds;
  }

  std::string out = "<header class=\"report-header\">\n<h1>camcov benchmark report</h1>\n";
  // What ran, said from the batch itself: its methods by their own descriptions.
  std::string ran;
  const std::vector<std::string> methods = control::inMethodOrder(m.methods);
  for (std::size_t i = 0; i < methods.size(); ++i) {
    // "paper (global + local)" names itself; "local optimization" gets its name in front.
    const std::string label(methodStyle(methods[i]).label);
    ran += fmt::format(
        "{}{}",
        i == 0                    ? ""
        : i + 1 == methods.size() ? " and "
                                  : ", ",
        label.rfind(methods[i], 0) == 0
            ? "<b>" + escapeXml(methods[i]) + "</b>" + escapeXml(label.substr(methods[i].size()))
            : fmt::format("<b>{}</b> ({})", escapeXml(methods[i]), escapeXml(label)));
  }
  out += fmt::format(
      "<p class=\"lede\">{} on {} scenes with {} seeds each{}.</p>\n", ran, m.scenes.size(),
      m.seeds,
      methods.size() > 1 ? fmt::format(", each compared with {}", escapeXml(s.reference)) : "");
  // Against the reference, then the others pairwise (section "Methods against each other").
  for (const auto* tallies : {&s.tallies, &s.pairTallies}) {
    for (const records::Tally& t : *tallies) {
      out += fmt::format(
          "<p class=\"verdict\">On average coverage over {} scenes, {} against {}: <b>wins "
          "{}</b>, ties {}, <b>loses {}</b>{} (by <a href=\"#verdict-rule\">the rule</a> the "
          "summary states).</p>\n",
          t.wins + t.ties + t.losses + t.undecided, escapeXml(methodStyle(t.method).label),
          escapeXml(methodStyle(t.against.empty() ? s.reference : t.against).label), t.wins, t.ties,
          t.losses,
          t.undecided > 0 ? fmt::format(", <b>undecided {}</b> (too few seeds to tell: {} per "
                                        "method at least)",
                                        t.undecided, records::seedsToReachSignificance())
                          : std::string());
    }
  }
  if (!s.tallies.empty()) {
    out +=
        fmt::format("<p class=\"verdict\">Mean over scenes of the mean average coverage: {}.</p>\n",
                    meanCoverageByMethod(data));
  }
  out += "<dl class=\"facts\">\n";
  const auto fact = [&](std::string_view term, const std::string& html) {
    out += fmt::format("<dt>{}</dt><dd>{}</dd>\n", term, html);
  };
  fact("Tool", "camcov " + escapeXml(m.toolVersion));
  // What made each method's results (a resume with other code is refused): the build's
  // sources for C++ methods, the factory's file for Python ones.
  std::string identities;
  for (const std::string& method : control::inMethodOrder(m.methods)) {
    const auto it = m.methodIdentities.find(method);
    identities += fmt::format(
        "{}<b>{}</b> <code>{}</code>", identities.empty() ? "" : "; ", escapeXml(method),
        it == m.methodIdentities.end() ? "not recorded" : escapeXml(it->second));
  }
  fact("Code", identities);
  fact("Command", "<code>" + escapeXml(shellCommand(m.command)) + "</code>");
  fact("Jobs", fmt::format("{} = {} scenes × {} methods × {} seeds; {} failed", jobs,
                           m.scenes.size(), m.methods.size(), m.seeds, s.failures.size()));
  fact("Simulated",
       fmt::format("{} s per run, dt = {} s", readableNumber(m.parameters.sim.duration),
                   readableNumber(m.parameters.sim.dt)));
  fact("Compute time", fmt::format("{} wall, {} CPU, summed over {} jobs", duration(wall),
                                   duration(cpu), data.timings.size()));
  fact("Report built", escapeXml(context.date));
  fact("Machine", escapeXml(machineDescription(context)));
  return out + "</dl>\n</header>\n";
}

}  // namespace camcov::reports
