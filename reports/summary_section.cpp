// Section 2: the summary table, one table per scene group, one <tbody> per scene so the
// inline script can sort scenes without tearing their method rows apart.
#include <fmt/format.h>

#include <map>
#include <string>
#include <vector>

#include "control/methods.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/sections.h"
#include "reports/verdict_markup.h"

namespace camcov::reports {
namespace {

// The scene's name with a line break allowed after each '_': the longest own scene name
// ("dynamic_fast_target_slow_cameras") would otherwise take a fifth of the table's width.
std::string breakableName(const std::string& name) {
  std::string out;
  for (const char c : escapeXml(name)) {
    out += c;
    if (c == '_') out += "<wbr>";
  }
  return out;
}

std::string meanSd(const records::Description& d, bool best) {
  if (d.count == 0) return "—";
  const std::string text = fixed(d.mean, 3) + " ± " + fixed(d.sd, 3);
  return best ? "<b>" + text + "</b>" : text;
}

// The coverages some scenes record beside the plain one, which the verdicts compare: a weighted
// scene's importance-weighted coverage, a scene with a resolution's resolution coverage; each a
// line under the plain mean, which wraps after its word rather than widen the table past the
// page: the winner is its last column.
std::string extraCoverageLines(const records::MethodSummary& m) {
  std::string lines;
  const auto line = [&](const records::Description& d, const char* title, const char* label) {
    if (d.count == 0) return;
    lines += fmt::format(
        "<br><span class=\"muted extra\" title=\"{}\">{} <span class=\"value\">{}</span></span>",
        title, label, meanSd(d, false));
  };
  line(m.weightedCoverage, "average importance-weighted coverage (edgeWeights, frontWeight)",
       "weighted");
  line(m.resolutionCoverage,
       "average resolution coverage: boundary seen with the pixel density the scene asks for",
       "resolved");
  return lines;
}

std::string methodRow(const records::MethodSummary& m, bool bestCoverage, bool bestUtilization) {
  const MethodStyle style = methodStyle(m.method);
  // A method whose every run failed has no numbers, not zeros.
  const auto number = [&](double v, int decimals) {
    return m.runs == 0 ? std::string("—") : fixed(v, decimals);
  };
  return fmt::format(
      "<td>{}</td><td class=\"num\">{}</td>"
      "<td class=\"num\">{}{}</td><td class=\"num\">{}</td>"
      "<td class=\"num\">{}</td><td class=\"num\">{}</td>"
      "<td class=\"num\" title=\"of which {} s near objects, {} s between cameras\">{} / {}</td>"
      "<td class=\"num\" title=\"{} runs had an unavoidable contact\">{} / {}</td>"
      "<td class=\"num\">{} / {}</td>",
      methodMark(style.color, escapeXml(m.method)),
      m.failed == 0 ? std::to_string(m.runs) : fmt::format("{} ({} failed)", m.runs, m.failed),
      meanSd(m.coverage, bestCoverage), extraCoverageLines(m), number(m.coverage.median, 3),
      meanSd(m.utilization, bestUtilization), number(m.utilization.median, 3),
      number(m.meanObjectCollisionTime, 2), number(m.meanCameraCollisionTime, 2),
      number(m.meanAvoidableContactTime, 2), number(m.meanUnavoidableContactTime, 2),
      m.runsWithUnavoidableContact, m.runsWithAvoidableContact, m.runs,
      number(m.minObjectDistance, 2), number(m.minCameraDistance, 2));
}

// A method's row ends with its comparison against the reference: Δ, p, the winner; the
// reference's own row says what it is.
std::string comparisonOf(const records::MethodSummary& m, const records::BatchSummary& s) {
  if (m.method == s.reference) {
    return "<td class=\"num muted\" colspan=\"3\">reference</td>";
  }
  return comparisonCells(s.comparison(m.scene, m.method));
}

std::string sceneBody(const SceneData& scene, const records::BatchSummary& summary,
                      const std::vector<const records::MethodSummary*>& rows, std::size_t order) {
  // Bold marks the one best mean; equal means (a deterministic tie) stay plain.
  const auto uniqueBest = [&](records::Description records::MethodSummary::*metric) {
    const records::MethodSummary* best = nullptr;
    int atBest = 0;
    for (const auto* m : rows) {
      if (m->runs == 0) continue;
      if (best == nullptr || (m->*metric).mean > (best->*metric).mean) {
        best = m;
        atBest = 1;
      } else if ((m->*metric).mean == (best->*metric).mean) {
        ++atBest;
      }
    }
    return atBest == 1 ? best : nullptr;
  };
  const auto* bestCoverage = uniqueBest(&records::MethodSummary::coverage);
  const auto* bestUtilization = uniqueBest(&records::MethodSummary::utilization);
  // Sort keys live on the <tbody> (the script reorders whole scenes): those of the first
  // method compared with the reference.
  const records::Comparison* first = nullptr;
  for (const auto* m : rows) {
    if (!first) first = summary.comparison(m->scene, m->method);
  }
  std::string out =
      fmt::format("<tbody data-scene=\"{}\" data-delta=\"{}\" data-p=\"{}\" data-winner=\"{}\">\n",
                  order, first ? first->meanDifference : 0.0, first ? first->pValue : 1.0,
                  escapeXml(first ? first->winner : ""));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& m = *rows[i];
    out += "<tr>";
    if (i == 0) {
      out += fmt::format("<th scope=\"rowgroup\" rowspan=\"{}\"><a href=\"#{}\">{}</a></th>",
                         rows.size(), anchorId("ts", scene.name), breakableName(scene.name));
    }
    out += methodRow(m, rows.size() > 1 && &m == bestCoverage,
                     rows.size() > 1 && &m == bestUtilization);
    out += comparisonOf(m, summary) + "</tr>\n";
  }
  return out + "</tbody>\n";
}

std::string groupTable(SceneGroup group, const ReportData& data) {
  std::map<std::string, std::vector<const records::MethodSummary*>> byScene;
  for (const auto& m : data.summary.methods)
    byScene[m.scene].push_back(&m);
  std::string bodies;
  int scenes = 0;
  std::map<std::string, records::Tally> tallies;  // of this group's scenes, by method
  for (std::size_t i = 0; i < data.scenes.size(); ++i) {
    const SceneData& scene = data.scenes[i];
    if (scene.group != group) continue;
    std::vector<const records::MethodSummary*> rows;
    for (const auto& method : control::inMethodOrder(data.manifest.methods)) {
      for (const auto* m : byScene[scene.name]) {
        if (m->method == method) rows.push_back(m);
      }
    }
    if (rows.empty()) continue;
    ++scenes;
    for (const auto* m : rows) {
      const records::Comparison* c = data.summary.comparison(m->scene, m->method);
      if (c == nullptr || c->winner.empty()) continue;
      records::count(tallies[m->method], *c, data.summary.reference);
    }
    bodies += sceneBody(scene, data.summary, rows, i);
  }
  std::vector<std::string> verdicts;
  for (const auto& method : control::inMethodOrder(data.manifest.methods)) {
    const auto it = tallies.find(method);
    if (it == tallies.end()) continue;
    verdicts.push_back(fmt::format(
        "{} against {}: wins {}, ties {}, losses {}{}", escapeXml(method),
        escapeXml(data.summary.reference), it->second.wins, it->second.ties, it->second.losses,
        it->second.undecided > 0 ? fmt::format(", undecided {}", it->second.undecided) : ""));
  }
  if (scenes == 0) return {};
  const auto sortable = [](std::string_view key, std::string_view label) {
    return fmt::format(
        "<th scope=\"col\" data-key=\"{}\" rowspan=\"2\"><button type=\"button\">{}</button></th>",
        key, label);
  };
  std::string out = fmt::format(
      "<h3>{} <span class=\"muted\">({}{}{})</span>"
      "</h3>\n<div class=\"table-wrap\"><table class=\"summary sortable\" data-group=\"{}\">\n"
      "<thead><tr>{}<th scope=\"col\" rowspan=\"2\">Method</th><th scope=\"col\" "
      "rowspan=\"2\">Runs</th><th scope=\"colgroup\" colspan=\"2\">Average coverage</th>"
      "<th scope=\"colgroup\" colspan=\"2\">Average utilization</th><th scope=\"colgroup\" "
      "colspan=\"3\">Safety</th>{}{}{}</tr>\n"
      "<tr><th scope=\"col\">mean ± sd</th><th scope=\"col\">median</th><th scope=\"col\">mean ± "
      "sd</th><th scope=\"col\">median</th><th scope=\"col\" title=\"mean seconds per run closer "
      "than δ, measured in continuous time\">time &lt; δ, s<br>avoidable / unavoidable</th>"
      "<th scope=\"col\" title=\"runs with time below δ that the safety layer judged "
      "avoidable\">runs with avoidable contact</th><th scope=\"col\" title=\"minimum over all "
      "runs, continuous time\">min distance, m<br>object / camera</th></tr></thead>\n",
      groupTitle(group), scenes, verdicts.empty() ? "" : ": ", join(verdicts, "; "),
      groupName(group), sortable("scene", "Scene"),
      sortable("delta", "Δ coverage vs " + escapeXml(data.summary.reference)), sortable("p", "p"),
      sortable("winner", "Winner"));
  return out + bodies + "</table></div>\n";
}

}  // namespace

std::string summarySection(const ReportData& data) {
  std::string out = fmt::format(
      "<section id=\"summary\">\n<h2>Summary</h2>\n<p>Per scene and method over {} seeds: "
      "average coverage (eq. 4) and average utilization, mean ± sample standard deviation and "
      "median; safety as the mean time per run a camera spent closer than δ = {} m to an object "
      "or to another camera, measured in continuous time and split by the safety layer's "
      "verdict when the contact began (unavoidable: no admissible velocity kept δ), the runs "
      "with an avoidable contact, and the smallest distances in any run. Every method is "
      "compared with the reference, {}: Δ is its mean coverage minus the reference's; p is the "
      "two-sided Mann-Whitney U test of the two samples.</p>\n<p class=\"rule\" "
      "id=\"verdict-rule\"><b>The rule for every verdict of this report</b> (docs/statistics.md): "
      "{}.</p>\n<p>Click a column title to sort (by the first method compared).</p>\n",
      data.manifest.seeds, data.manifest.parameters.sim.delta, escapeXml(data.summary.reference),
      escapeXml(records::verdictRuleText()));
  for (const SceneGroup group : kSceneGroups) {
    out += groupTable(group, data);
  }
  return out + "</section>\n";
}

}  // namespace camcov::reports
