// Section 2a: the scenes by group (the family a generated scene was drawn from, else the
// folder it was read from), when there is more than one: each method's mean coverage there and
// its wins, ties and losses, so a reader sees where a method is strong and where it is weak.
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "control/methods.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/sections.h"

namespace camcov::reports {
namespace {

std::string tallyCell(const records::Tally& t) {
  return fmt::format("<td class=\"num\" title=\"wins, ties, losses{}\">{} / {} / {}{}</td>",
                     t.undecided > 0 ? ", undecided" : "", t.wins, t.ties, t.losses,
                     t.undecided > 0 ? fmt::format(" / {}?", t.undecided) : "");
}

}  // namespace

std::string groupsSection(const ReportData& data) {
  const records::BatchSummary& s = data.summary;
  if (s.groups.size() < 2) return {};
  const std::vector<std::string> methods = control::inMethodOrder(data.manifest.methods);
  std::string head = "<th scope=\"col\">Family or folder</th><th scope=\"col\">Scenes</th>";
  for (const auto& method : methods) {
    head += fmt::format("<th scope=\"col\">{}</th>",
                        methodMark(methodStyle(method).color, escapeXml(method)));
  }
  for (const auto* tallies : {&s.tallies, &s.pairTallies}) {
    for (const auto& t : *tallies) {
      head += fmt::format("<th scope=\"col\">{} vs {}</th>", escapeXml(t.method),
                          escapeXml(t.against.empty() ? s.reference : t.against));
    }
  }
  std::string rows;
  for (const auto& g : s.groups) {
    std::string row = fmt::format("<tr><th scope=\"row\">{}</th><td class=\"num\">{}</td>",
                                  escapeXml(g.name), g.scenes.size());
    // Bold marks the one best mean of the group.
    double best = -1.0;
    int atBest = 0;
    for (const auto& [method, mean] : g.meanCoverage) {
      if (mean > best) {
        best = mean;
        atBest = 1;
      } else if (mean == best) {
        ++atBest;
      }
    }
    for (const auto& method : methods) {
      const auto it = std::find_if(g.meanCoverage.begin(), g.meanCoverage.end(),
                                   [&](const auto& m) { return m.first == method; });
      if (it == g.meanCoverage.end()) {
        row += "<td class=\"num\">—</td>";
        continue;
      }
      const std::string text = fixed(it->second, 3);
      row += fmt::format("<td class=\"num\">{}</td>",
                         atBest == 1 && it->second == best ? "<b>" + text + "</b>" : text);
    }
    for (const auto* tallies : {&g.tallies, &g.pairTallies}) {
      for (const auto& t : *tallies)
        row += tallyCell(t);
    }
    rows += row + "</tr>\n";
  }
  return fmt::format(
      "<section id=\"groups\">\n<h2>By family or folder</h2>\n<p>The scenes grouped by the "
      "family a generated scene was drawn from (<code>camcov generate --family</code>), else by "
      "the folder it was read from. Per group: each method's mean over the scenes of its mean "
      "average coverage, and the scenes it won, tied and lost in each comparison of the summary "
      "(the same verdicts, counted per group; ? marks scenes with too few seeds to tell).</p>\n"
      "<div class=\"table-wrap\"><table class=\"groups\">\n<thead><tr>{}</tr></thead>\n<tbody>\n"
      "{}</tbody></table></div>\n</section>\n",
      head, rows);
}

}  // namespace camcov::reports
