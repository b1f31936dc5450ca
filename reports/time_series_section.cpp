// Section 4, the paper's Fig. 5: coverage and utilization over time for every scene, the
// median-seed run of each method as a line over the range of all its seeds, with the
// method's replans and aborted plans marked on the time axis.
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "control/event_kind.h"
#include "control/methods.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/sections.h"
#include "reports/svg_plot.h"

namespace camcov::reports {
namespace {

constexpr double kChartWidth = 540.0;
constexpr double kChartHeight = 250.0;

// Events worth a mark, merged per instant so simultaneous plans of several cameras make one
// mark whose tooltip lists them all.
struct Mark {
  Swatch shape;
  std::string color;
  std::string tooltip;
};

// How the coverage plots draw the marks of the median runs.
Swatch markSwatch(control::EventMark mark) {
  return mark == control::EventMark::Stop ? Swatch::Cross : Swatch::Triangle;
}

std::vector<std::pair<double, Mark>> eventMarks(const std::string& method, const MethodRuns& runs) {
  std::map<std::pair<double, bool>, Mark> marks;  // (time, stop)
  for (const auto& e : runs.events) {
    // The one rule of marks (control/event_kind.h); contacts come from every seed, below.
    const control::EventMark mark = control::markOf(e);
    if (mark != control::EventMark::Move && mark != control::EventMark::Stop) continue;
    const bool stop = mark == control::EventMark::Stop;
    Mark& m = marks[{e.time, stop}];
    if (m.tooltip.empty()) {
      m = {markSwatch(mark), std::string(methodStyle(method).color),
           fmt::format("t = {} s, {}", fixed(e.time, 1), method)};
    }
    m.tooltip += fmt::format("\n{}{}: {}", e.kind,
                             e.camera >= 0 ? fmt::format(" camera {}", e.camera) : "", e.detail);
  }
  std::vector<std::pair<double, Mark>> out;
  for (auto& [key, mark] : marks)
    out.emplace_back(key.first, std::move(mark));
  return out;
}

// Colours of contacts closer than δ: avoidable ones are failures of the method, in red;
// unavoidable ones (no admissible velocity kept δ) in slate.
constexpr std::string_view kAvoidableColour = "#d62728";
constexpr std::string_view kUnavoidableColour = "#5b6472";

// Every seed's contacts, merged per (instant, kind), as diamonds along the top.
std::vector<std::pair<double, Mark>> contactMarks(const std::string& method,
                                                  const MethodRuns& runs) {
  std::map<std::pair<double, bool>, Mark> marks;  // (time, unavoidable)
  for (const auto& [seed, e] : runs.contacts) {
    const bool unavoidable = control::markOf(e) == control::EventMark::UnavoidableContact;
    Mark& m = marks[{e.time, unavoidable}];
    if (m.tooltip.empty()) {
      m = {Swatch::Diamond, std::string(unavoidable ? kUnavoidableColour : kAvoidableColour),
           fmt::format("t = {} s, {}", fixed(e.time, 2), method)};
    }
    m.tooltip += fmt::format("\nseed {}, {} camera {}{}: {}", seed, e.kind, e.camera,
                             e.reason.empty() ? "" : " (" + e.reason + ")", e.detail);
  }
  std::vector<std::pair<double, Mark>> out;
  for (auto& [key, mark] : marks)
    out.emplace_back(key.first, std::move(mark));
  return out;
}

std::string chart(const SceneData& scene, const std::vector<std::string>& methods,
                  SeriesBand MethodRuns::*series, const char* label, double duration) {
  ChartSpec spec;
  spec.width = kChartWidth;
  spec.height = kChartHeight;
  spec.ariaLabel = fmt::format("{} over time, {}", label, scene.name);
  spec.x = {"time, s", 0.0, duration, 7};
  spec.y = {label, 0.0, 1.0, 6};
  std::vector<std::pair<const MethodRuns*, std::string_view>> shown;  // runs, colour
  std::vector<std::pair<double, Mark>> marks;
  for (const auto& method : methods) {
    const auto it = scene.methods.find(method);
    if (it == scene.methods.end()) continue;
    shown.emplace_back(&it->second, methodStyle(method).color);
    spec.legend.push_back({fmt::format("{}, seed {}", method, it->second.medianSeed),
                           std::string(methodStyle(method).color), Swatch::Line});
    for (auto& mark : eventMarks(method, it->second))
      marks.push_back(std::move(mark));
    for (auto& mark : contactMarks(method, it->second))
      marks.push_back(std::move(mark));
  }
  // One legend entry per mark shape, in the colour of the first method that has it.
  for (const control::EventMark mark : {control::EventMark::Move, control::EventMark::Stop}) {
    const Swatch shape = markSwatch(mark);
    const auto it = std::find_if(marks.begin(), marks.end(),
                                 [shape](const auto& m) { return m.second.shape == shape; });
    if (it != marks.end())
      spec.legend.push_back({std::string(control::markInfo(mark).label), it->second.color, shape});
  }
  for (const auto& [color, mark] :
       {std::pair{kAvoidableColour, control::EventMark::AvoidableContact},
        std::pair{kUnavoidableColour, control::EventMark::UnavoidableContact}}) {
    if (std::any_of(marks.begin(), marks.end(),
                    [color = color](const auto& m) { return m.second.color == color; }))
      spec.legend.push_back({std::string(control::markInfo(mark).label) + " < δ",
                             std::string(color), Swatch::Diamond});
  }
  Chart c(spec);
  // Guides under the bands, bands under the lines, the first method's line on top.
  for (const auto& [t, mark] : marks)
    c.addAxisMark(t, mark.shape, mark.color, mark.tooltip);
  for (const auto& [runs, color] : shown) {
    c.addBand(runs->time, (runs->*series).min, (runs->*series).max, color, 0.18);
  }
  for (auto it = shown.rbegin(); it != shown.rend(); ++it) {
    c.addLine(it->first->time, (it->first->*series).median, it->second, 1.6);
  }
  return c.svg();
}

// Recorded tracks: how many people are present over time (the scene's, the same for every
// method), and how many steps had nobody to cover.
std::string presenceChart(const SceneData& scene, double duration) {
  const MethodRuns* runs = nullptr;
  for (const auto& [method, r] : scene.methods) {
    if (!r.targetsPresent.empty()) runs = &r;
  }
  if (runs == nullptr) return {};
  const int most = *std::max_element(runs->targetsPresent.begin(), runs->targetsPresent.end());
  ChartSpec spec;
  spec.width = kChartWidth;
  spec.height = kChartHeight * 0.7;
  spec.ariaLabel = fmt::format("people present over time, {}", scene.name);
  spec.x = {"time, s", 0.0, duration, 7};
  spec.y = {"people present", 0.0, std::max(1.0, static_cast<double>(most)), 5};
  Chart c(spec);
  std::vector<double> count(runs->targetsPresent.begin(), runs->targetsPresent.end());
  c.addLine(runs->time, count, "#5b6472", 1.6);
  return c.svg();
}

std::string presenceNote(const SceneData& scene) {
  for (const auto& [method, r] : scene.methods) {
    if (r.targetsPresent.empty()) continue;
    const auto empty = std::count(r.targetsPresent.begin(), r.targetsPresent.end(), 0);
    return fmt::format(
        " · at most {} people at once; {} of {} steps without anyone, left out of the averages",
        *std::max_element(r.targetsPresent.begin(), r.targetsPresent.end()), empty,
        r.targetsPresent.size());
  }
  return {};
}

std::string sceneFigure(const SceneData& scene, const std::vector<std::string>& methods,
                        double duration) {
  std::vector<std::string> parts;
  for (const auto& method : methods) {
    const auto it = scene.methods.find(method);
    if (it == scene.methods.end()) continue;
    parts.push_back(fmt::format("{}: {} seeds, median seed {}", method,
                                it->second.averageCoverage.size(), it->second.medianSeed));
  }
  const std::string caption = join(parts, "; ") + presenceNote(scene);
  return fmt::format(
      "<figure class=\"series\" id=\"{}\" data-figure=\"series\" data-scene=\"{}\">\n"
      "<figcaption><b>{}</b> <span class=\"muted\">{} · <a href=\"#{}\">scene</a>{}</span>"
      "</figcaption>\n<div class=\"pair\">{}{}</div>\n</figure>\n",
      anchorId("ts", scene.name), escapeXml(scene.name), escapeXml(scene.name), escapeXml(caption),
      anchorId("scene", scene.name),
      scene.explorerUrl.empty()
          ? std::string()
          : fmt::format(" · <a class=\"explore\" href=\"{}\">explore these runs</a>",
                        escapeXml(scene.explorerUrl)),
      chart(scene, methods, &MethodRuns::coverage, "coverage", duration),
      chart(scene, methods, &MethodRuns::utilization, "utilization", duration) +
          presenceChart(scene, duration));
}

}  // namespace

std::string timeSeriesSection(const ReportData& data) {
  const std::vector<std::string> methods = control::inMethodOrder(data.manifest.methods);
  double duration = data.manifest.parameters.sim.duration;
  for (const auto& s : data.scenes) {
    for (const auto& [method, runs] : s.methods) {
      if (!runs.time.empty()) duration = std::max(duration, runs.time.back());
    }
  }
  std::string out =
      "<section id=\"time-series\">\n<h2>Coverage and utilization over time (Fig. 5)</h2>\n"
      "<p>For each scene and method the line is the run of the median seed (the seed whose "
      "average coverage is the median), and the shaded band is the range, at each step, of all "
      "seeds. Triangles on the time axis mark the median run's replans (global optimization "
      "found a pose set better by the factor τ, and paths were planned), crosses mark aborted "
      "plans. Diamonds along the top mark where a camera of any seed came closer than δ to an "
      "object or camera (continuous time): red when the safety layer could have avoided it, "
      "slate when no admissible velocity could. Hover a mark for its details; <i>explore these "
      "runs</i> opens the median runs in the run explorer, to scrub through them step by "
      "step.</p>\n";
  for (const auto& scene : data.scenes) {
    if (!scene.methods.empty()) out += sceneFigure(scene, methods, duration);
  }
  return out + "</section>\n";
}

}  // namespace camcov::reports
