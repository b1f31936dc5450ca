// Section 3, the paper's Fig. 4: per scene both methods' boxes side by side, one panel per
// scene group and metric (the paper shows coverage only; utilization is our addition).
#include <fmt/format.h>

#include <algorithm>

#include "control/methods.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/sections.h"
#include "reports/svg_plot.h"

namespace camcov::reports {
namespace {

constexpr std::size_t kScenesPerPanel = 16;  // the paper's 16 static and 16 dynamic scenes
constexpr double kMinPanelWidth = 600.0;     // room for the legend
constexpr double kMaxPanelWidth = 1100.0;
constexpr double kPanelHeight = 330.0;
// The boxes' own height, whatever the scene names below them take: a few tenths of coverage
// between two methods must show as a gap a reader sees.
constexpr double kMinBoxesHeight = 240.0;

struct Metric {
  const char* key;      // data-metric attribute
  const char* label;    // y axis
  const char* caption;  // figure caption
  std::vector<double> MethodRuns::*values;
};

std::string panel(const std::vector<const SceneData*>& scenes,
                  const std::vector<std::string>& methods, const Metric& metric, double lo,
                  double hi, const std::string& title) {
  ChartSpec spec;
  // About 68 px per scene, so a few scenes do not spread over the page.
  spec.width =
      std::clamp(140.0 + 68.0 * static_cast<double>(scenes.size()), kMinPanelWidth, kMaxPanelWidth);
  spec.height = kPanelHeight;
  spec.minPlotHeight = kMinBoxesHeight;
  spec.ariaLabel = title;
  spec.y = {metric.label, lo, hi, 7};
  spec.x.label = "scene";
  for (const auto* s : scenes)
    spec.categories.push_back(s->name);
  for (const auto& method : methods) {
    spec.legend.push_back({std::string(methodStyle(method).label),
                           std::string(methodStyle(method).color), Swatch::Box});
  }
  spec.legend.push_back({"outlier (beyond 1.5 IQR)", "#555", Swatch::Plus});
  Chart chart(spec);
  // Slots share their width among the methods, with a gap between scenes.
  const double width = 0.8 / static_cast<double>(methods.size());
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const auto it = scenes[i]->methods.find(methods[k]);
      if (it == scenes[i]->methods.end() || (it->second.*metric.values).empty()) continue;
      const BoxStats b = boxStats(it->second.*metric.values);
      const std::string tooltip = fmt::format(
          "{} · {}: median {}, quartiles {}–{}, whiskers {}–{}, {} outliers, n = {}",
          scenes[i]->name, methods[k], fixed(b.median, 3), fixed(b.q1, 3), fixed(b.q3, 3),
          fixed(b.whiskerLow, 3), fixed(b.whiskerHigh, 3), b.outliers.size(), b.count);
      chart.addBox(i, -0.4 + width * (static_cast<double>(k) + 0.5), width * 0.85, b,
                   methodStyle(methods[k]).color, tooltip,
                   fmt::format("data-metric=\"{}\" data-scene=\"{}\" data-method=\"{}\"",
                               metric.key, escapeXml(scenes[i]->name), escapeXml(methods[k])));
    }
  }
  return chart.svg();
}

}  // namespace

std::string boxPlotSection(const ReportData& data) {
  const std::vector<std::string> methods = control::inMethodOrder(data.manifest.methods);
  const Metric metrics[] = {
      {"coverage", "average coverage", "Average coverage (eq. 4)", &MethodRuns::averageCoverage},
      {"utilization", "average utilization", "Average utilization",
       &MethodRuns::averageUtilization}};
  std::string out = fmt::format(
      "<section id=\"box-plots\">\n<h2>Coverage and utilization per scene (Fig. 4)</h2>\n"
      "<p>Each box is one method on one scene over {} seeds: the box spans the quartiles with "
      "the median as a bar, the whiskers reach the most extreme run within 1.5 IQR of the box, "
      "and + marks runs beyond. As in the paper, the paper's method is orange and local "
      "optimization blue. Hover a box for its numbers.</p>\n",
      data.manifest.seeds);
  for (const SceneGroup group : kSceneGroups) {
    std::vector<const SceneData*> scenes;
    for (const auto& s : data.scenes) {
      if (s.group == group && !s.methods.empty()) scenes.push_back(&s);
    }
    if (scenes.empty()) continue;
    out += fmt::format("<h3>{}</h3>\n", groupTitle(group));
    for (const Metric& metric : metrics) {
      double lo = 1.0, hi = 0.0;
      for (const auto* s : scenes) {
        for (const auto& [method, runs] : s->methods) {
          for (const double v : runs.*metric.values) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
          }
        }
      }
      for (std::size_t start = 0; start < scenes.size(); start += kScenesPerPanel) {
        const std::vector<const SceneData*> chunk(
            scenes.begin() + static_cast<std::ptrdiff_t>(start),
            scenes.begin() +
                static_cast<std::ptrdiff_t>(std::min(scenes.size(), start + kScenesPerPanel)));
        const std::string title = fmt::format("{} per run, {}", metric.label, groupTitle(group));
        out += fmt::format(
            "<figure class=\"panel\" data-figure=\"box\" data-metric=\"{}\">\n{}<figcaption>{} "
            "per run of each method over {} seeds; {}{}.</figcaption>\n</figure>\n",
            metric.key, panel(chunk, methods, metric, lo, hi, title), metric.caption,
            data.manifest.seeds, groupName(group),
            scenes.size() > kScenesPerPanel
                ? fmt::format(" scenes {}–{} of {}", start + 1, start + chunk.size(), scenes.size())
                : std::string(" scenes"));
      }
    }
  }
  return out + "</section>\n";
}

}  // namespace camcov::reports
