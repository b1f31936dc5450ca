// Section 2b: the methods other than the reference against each other, with the same test
// as the summary's: for three methods (paper, local, camcov) with local the reference, ours
// against the paper's. A tally per pair and scene group, then every scene.
#include <fmt/format.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/sections.h"
#include "reports/verdict_markup.h"

namespace camcov::reports {
namespace {

struct Pair {
  std::string method, against;  // the later one in the batch's order against the earlier
};

// The pairs the summary compared, in its order (the batch's methods).
std::vector<Pair> comparedPairs(const ReportData& data) {
  std::vector<Pair> pairs;
  for (const auto& t : data.summary.pairTallies)
    pairs.push_back({t.method, t.against});
  return pairs;
}

std::string tallyText(const records::Tally& t) {
  return fmt::format("{} / {} / {}{}", t.wins, t.ties, t.losses,
                     t.undecided > 0 ? fmt::format(" ({} undecided)", t.undecided) : "");
}

}  // namespace

std::string pairsSection(const ReportData& data) {
  const std::vector<Pair> pairs = comparedPairs(data);
  if (pairs.empty()) return {};
  using Key = std::tuple<std::string, std::string, std::string>;  // scene, method, against
  std::map<Key, const records::Comparison*> byKey;
  for (const auto& p : data.summary.pairs)
    byKey[{p.comparison.scene, p.comparison.method, p.against}] = &p.comparison;

  // Tallies per group, from the same comparisons as the summary's pairTotals.
  std::map<std::pair<SceneGroup, std::size_t>, records::Tally> tallies;
  std::map<std::size_t, records::Tally> totals;
  std::vector<SceneGroup> groups;
  std::string bodies;
  for (const SceneGroup group : kSceneGroups) {
    std::string rows;
    for (const SceneData& scene : data.scenes) {
      if (scene.group != group) continue;
      std::string cells;
      bool any = false;
      for (std::size_t i = 0; i < pairs.size(); ++i) {
        const auto it = byKey.find({scene.name, pairs[i].method, pairs[i].against});
        const records::Comparison* c = it == byKey.end() ? nullptr : it->second;
        cells += comparisonCells(c);
        if (c == nullptr || c->winner.empty()) continue;
        any = true;
        for (records::Tally* t : {&tallies[{group, i}], &totals[i]})
          records::count(*t, *c, pairs[i].against);
      }
      if (any)
        rows += fmt::format("<tr><th scope=\"row\">{}</th>{}</tr>\n", escapeXml(scene.name), cells);
    }
    if (rows.empty()) continue;
    groups.push_back(group);
    bodies += fmt::format(
        "<tbody data-group=\"{}\"><tr><th scope=\"rowgroup\" colspan=\"{}\">{}</th></tr>\n{}"
        "</tbody>\n",
        groupName(group), 1 + 3 * pairs.size(), groupTitle(group), rows);
  }
  if (bodies.empty()) return {};

  std::string head, subhead, tallyHead, tallyRows;
  for (const SceneGroup group : groups)
    tallyHead += fmt::format("<th scope=\"col\">{}</th>", groupTitle(group));
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::string name =
        fmt::format("{} vs {}", escapeXml(pairs[i].method), escapeXml(pairs[i].against));
    head += fmt::format("<th scope=\"colgroup\" colspan=\"3\">{}</th>", name);
    subhead += fmt::format(
        "<th scope=\"col\">Δ coverage</th><th scope=\"col\">p</th><th scope=\"col\">Winner</th>");
    std::string cells;
    for (const SceneGroup group : groups)
      cells += "<td class=\"num\">" + tallyText(tallies[{group, i}]) + "</td>";
    tallyRows += fmt::format(
        "<tr data-pair=\"{}|{}\"><th scope=\"row\">{}</th>{}<td "
        "class=\"num\"><b>{}</b></td></tr>\n",
        escapeXml(pairs[i].method), escapeXml(pairs[i].against),
        methodMark(methodStyle(pairs[i].method).color, name), cells, tallyText(totals[i]));
  }
  return fmt::format(
      "<section id=\"pairs\">\n<h2>Methods against each other</h2>\n<p>Every pair of methods "
      "other than the reference ({}), tested as in the summary: Δ is the first method's mean "
      "average coverage minus the second's, p the two-sided Mann-Whitney U test of their runs "
      "(winners by <a href=\"#verdict-rule\">the rule</a> of the summary). Tallies are wins / ties "
      "/ "
      "losses of the first method.</p>\n<div class=\"table-wrap\"><table class=\"pair-totals\">"
      "<thead><tr><th scope=\"col\">Pair</th>{}<th scope=\"col\">All scenes</th></tr></thead>\n"
      "<tbody>\n{}</tbody></table></div>\n<div class=\"table-wrap\"><table class=\"pairs\">"
      "<thead><tr><th scope=\"col\" rowspan=\"2\">Scene</th>{}</tr>\n<tr>{}</tr></thead>\n{}"
      "</table></div>\n</section>\n",
      escapeXml(data.summary.reference), tallyHead, tallyRows, head, subhead, bodies);
}

}  // namespace camcov::reports
