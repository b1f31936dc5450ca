// Section 2c: scenes that hold still against their offline optimum: the coverage
// of the best team pose `camcov optimum` found, and each method's final coverage, median
// over seeds, as a fraction of it. The optimum is a reference a long search found, not a
// proof: a method may end above it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "control/methods.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/sections.h"

namespace camcov::reports {
namespace {

// A final coverage this close to the optimum's counts as reaching it (2 %).
constexpr double kNearOptimum = 0.98;

}  // namespace

std::string optimumSection(const ReportData& data) {
  const std::vector<std::string> methods = control::inMethodOrder(data.manifest.methods);
  std::map<std::pair<std::string, std::string>, const records::MethodSummary*> rows;
  for (const auto& m : data.summary.methods)
    rows[{m.scene, m.method}] = &m;
  std::map<std::string, int> near, compared;
  const double duration = data.manifest.parameters.sim.duration;
  int outOfReachScenes = 0;
  std::string body;
  int scenes = 0;
  for (const SceneData& scene : data.scenes) {
    if (!scene.optimum) continue;
    const records::OptimumFile& o = *scene.optimum;
    const double best = o.result.terms.coverage;
    // A pose the team cannot reach before the run ends is no target for its final coverage:
    // shown, not counted (unknown travel, in older files, counts as reachable).
    const bool outOfReach = o.travelTime > duration;
    ++scenes;
    std::string cells;
    for (const std::string& method : methods) {
      const auto it = rows.find({scene.name, method});
      if (it == rows.end() || it->second->finalCoverage.count == 0) {
        cells += "<td class=\"num\">—</td><td class=\"num\">—</td>";
        continue;
      }
      const double final = it->second->finalCoverage.median;
      if (best <= 0.0) {
        cells += fmt::format("<td class=\"num\">{}</td><td class=\"num\">—</td>", fixed(final, 3));
        continue;
      }
      const double fraction = final / best;
      const bool reached = fraction >= kNearOptimum;
      if (!outOfReach) {
        ++compared[method];
        near[method] += reached;
      }
      cells += fmt::format("<td class=\"num\">{}</td><td class=\"num{}\">{}{}&nbsp;%</td>",
                           fixed(final, 3),
                           outOfReach ? " muted"
                           : reached  ? " near-optimum"
                                      : "",
                           reached && !outOfReach ? "✓ " : "", fixed(100.0 * fraction, 1));
    }
    outOfReachScenes += outOfReach;
    const std::string reach =
        std::isnan(o.travelTime)
            ? std::string("—")
            : fmt::format("{}{}", fixed(o.travelTime, 1),
                          outOfReach ? " <span class=\"out-of-reach\">out of reach</span>" : "");
    body += fmt::format(
        "<tr><th scope=\"row\">{}</th><td class=\"num\" title=\"found in round {} of {} by {} "
        "after {} of {} reward evaluations\">{}</td><td class=\"num\">{}</td>{}</tr>\n",
        escapeXml(scene.name), o.result.foundInRound, o.result.rounds, escapeXml(o.result.foundBy),
        o.result.foundAt, o.budget, fixed(best, 3), reach, cells);
  }
  if (scenes == 0) return {};
  std::string head, subhead, foot;
  std::vector<std::string> verdicts;
  for (const std::string& method : methods) {
    head += fmt::format("<th scope=\"colgroup\" colspan=\"2\">{}</th>",
                        methodMark(methodStyle(method).color, escapeXml(method)));
    subhead += "<th scope=\"col\">final, median</th><th scope=\"col\">of optimum</th>";
    foot += fmt::format("<td class=\"num\" colspan=\"2\">{} of {}</td>", near[method],
                        compared[method]);
    verdicts.push_back(
        fmt::format("{} {} of {}", escapeXml(method), near[method], compared[method]));
  }
  const records::OptimumFile& any =
      *std::find_if(data.scenes.begin(), data.scenes.end(), [](const SceneData& s) {
         return s.optimum.has_value();
       })->optimum;
  return fmt::format(
      "<section id=\"optimum\">\n<h2>Against the offline optimum</h2>\n<p>For each scene that "
      "holds still, the coverage of the best team pose <code>camcov optimum</code> found at "
      "t = 0 ({} reward evaluations: rounds of Algorithm 2, each improved camera by camera), "
      "and each method's coverage at the end of the run (t = {} s), median over seeds, as a "
      "fraction of it; ✓ marks {} % or more. Reach is how long the team needs from its start "
      "to the optimum's poses (section V-B's estimate: straight at full speed, obstacles "
      "ignored, so at least that); a pose out of reach within the run is shown, greyed, and "
      "not counted{}. The optimum is a reference, not a proof: a method can end above it. "
      "Within {} %: {}.</p>\n<div class=\"table-wrap\"><table "
      "class=\"optimum\"><thead><tr><th scope=\"col\" rowspan=\"2\">Scene</th><th scope=\"col\" "
      "rowspan=\"2\">Optimum coverage</th><th scope=\"col\" rowspan=\"2\">Reach, s</th>{}</tr>\n"
      "<tr>{}</tr></thead>\n<tbody>\n{}</tbody>\n"
      "<tfoot><tr><th scope=\"row\" colspan=\"3\">Within {} %</th>{}</tr></tfoot></table></div>\n"
      "</section>\n",
      any.budget, fmt::format("{:g}", duration), fixed(100 * kNearOptimum, 0),
      outOfReachScenes > 0 ? fmt::format(" ({} of {} scenes here)", outOfReachScenes, scenes) : "",
      fixed(100 * (1 - kNearOptimum), 0), join(verdicts, ", "), head, subhead, body,
      fixed(100 * (1 - kNearOptimum), 0), foot);
}

}  // namespace camcov::reports
