#include "reports/settings_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>

#include "records/atomic_file.h"
#include "records/batch_folder.h"
#include "records/verdicts.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/report_assets.h"
#include "reports/svg_plot.h"

namespace camcov::reports {
namespace {

constexpr const char* kBetterColor = "#2e7d32";
constexpr const char* kWorseColor = "#c62828";
constexpr std::size_t kMaxCategoryLabel = 32;  // chars of a setting's label under a box plot

// The runs of `method` on `scene` in setting `s`; nullptr when it has no finished run.
const SettingRuns* runsOf(const Setting& s, const std::string& scene, const std::string& method) {
  const auto byMethod = s.runs.find(scene);
  if (byMethod == s.runs.end()) return nullptr;
  const auto runs = byMethod->second.find(method);
  if (runs == byMethod->second.end() || runs->second.averageCoverage.empty()) return nullptr;
  return &runs->second;
}

double mean(const std::vector<double>& values) {
  return records::describe(values).mean;
}

// Every setting against the reference on each scene and method it ran, tested once: the
// sections read the verdicts several times. By setting, then (scene, method); the reference
// and what either did not run have none.
using Verdicts =
    std::vector<std::map<std::pair<std::string, std::string>, records::RunsComparison>>;

Verdicts testAgainstReference(const SettingsData& data) {
  Verdicts verdicts(data.settings.size());
  const Setting& reference = data.settings[data.reference];
  for (std::size_t i = 0; i < data.settings.size(); ++i) {
    if (i == data.reference) continue;
    for (const auto& scene : data.scenes) {
      for (const auto& method : data.methods) {
        const SettingRuns* here = runsOf(data.settings[i], scene, method);
        const SettingRuns* base = runsOf(reference, scene, method);
        if (here != nullptr && base != nullptr) {
          verdicts[i][{scene, method}] =
              records::compareRuns(here->averageCoverage, base->averageCoverage);
        }
      }
    }
  }
  return verdicts;
}

const records::RunsComparison* versusReference(const Verdicts& verdicts, std::size_t i,
                                               const std::string& scene,
                                               const std::string& method) {
  const auto it = verdicts[i].find({scene, method});
  return it == verdicts[i].end() ? nullptr : &it->second;
}

// One setting and method over every scene it ran: the mean of the per-scene means, and the
// verdicts against the reference.
struct Overall {
  int scenes = 0;
  double meanCoverage = 0.0;
  int wins = 0, ties = 0, losses = 0, undecided = 0;
};

Overall overall(const SettingsData& data, const Verdicts& verdicts, std::size_t i,
                const std::string& method) {
  Overall o;
  double sum = 0.0;
  for (const auto& scene : data.scenes) {
    const SettingRuns* runs = runsOf(data.settings[i], scene, method);
    if (runs == nullptr) continue;
    sum += mean(runs->averageCoverage);
    ++o.scenes;
    if (const auto c = versusReference(verdicts, i, scene, method)) {
      (c->verdict == records::Verdict::Better      ? o.wins
       : c->verdict == records::Verdict::Worse     ? o.losses
       : c->verdict == records::Verdict::Undecided ? o.undecided
                                                   : o.ties)++;
    }
  }
  if (o.scenes > 0) o.meanCoverage = sum / o.scenes;
  return o;
}

std::string methodName(const std::string& method) {
  const MethodStyle style = methodStyle(method);
  return methodMark(style.color, escapeXml(style.label));
}

std::string settingHeading(const Setting& s, bool reference) {
  const std::string name = s.reportUrl.empty()
                               ? escapeXml(s.label)
                               : fmt::format("<a href=\"{}\" title=\"its own report\">{}</a>",
                                             escapeXml(s.reportUrl), escapeXml(s.label));
  return reference ? name + "<br><span class=\"muted\">reference</span>" : name;
}

std::string header(const SettingsData& data, const Verdicts& verdicts,
                   const BuildContext& context) {
  const Setting& reference = data.settings[data.reference];
  std::string out = "<header class=\"report-header\">\n<h1>camcov settings side by side</h1>\n";
  out += fmt::format(
      "<p class=\"lede\">{} settings of one study, {} scenes, each setting compared with the "
      "reference setting <b>{}</b> on the same scene and method (two-sided Mann-Whitney U test "
      "of the runs' average coverage, α&nbsp;=&nbsp;{}).</p>\n",
      data.settings.size(), data.scenes.size(), escapeXml(reference.label), records::kSignificance);
  for (const auto& method : data.methods) {
    std::size_t best = data.reference;
    Overall bestOverall = overall(data, verdicts, best, method);
    for (std::size_t i = 0; i < data.settings.size(); ++i) {
      const Overall o = overall(data, verdicts, i, method);
      if (o.scenes > 0 && (bestOverall.scenes == 0 || o.meanCoverage > bestOverall.meanCoverage)) {
        best = i;
        bestOverall = o;
      }
    }
    if (bestOverall.scenes == 0) continue;
    out += best == data.reference
               ? fmt::format(
                     "<p class=\"verdict\">{}: no setting has a higher mean coverage over "
                     "scenes than the reference, {}.</p>\n",
                     methodName(method), fixed(bestOverall.meanCoverage, 3))
               : fmt::format(
                     "<p class=\"verdict\">{}: <b>{}</b> has the highest mean coverage over "
                     "scenes, {} (reference {}); against the reference it wins {}, ties {} and "
                     "loses {} of {} scenes.</p>\n",
                     methodName(method), escapeXml(data.settings[best].label),
                     fixed(bestOverall.meanCoverage, 3),
                     fixed(overall(data, verdicts, data.reference, method).meanCoverage, 3),
                     bestOverall.wins, bestOverall.ties, bestOverall.losses,
                     bestOverall.wins + bestOverall.ties + bestOverall.losses);
  }
  out += "<dl class=\"facts\">\n";
  const auto fact = [&](std::string_view term, const std::string& html) {
    out += fmt::format("<dt>{}</dt><dd>{}</dd>\n", term, html);
  };
  fact("Tool", "camcov " + escapeXml(reference.manifest.toolVersion));
  std::vector<std::string> folders;
  for (const auto& s : data.settings)
    folders.push_back("<code>" + escapeXml(s.folder.string()) + "</code>");
  fact("Folders", join(folders, " "));
  fact("Report built", escapeXml(context.date));
  fact("Machine", escapeXml(machineDescription(context)));
  return out + "</dl>\n</header>\n";
}

std::string settingsSection(const SettingsData& data) {
  std::string head = "<th scope=\"col\">Setting</th>";
  for (const auto& d : data.parameters) {
    head += fmt::format("<th scope=\"col\" title=\"{}\"><span class=\"symbol\">{}</span>{}</th>",
                        escapeXml(d.key), escapeXml(d.symbol),
                        d.symbol == d.key ? "" : " <code>" + escapeXml(d.key) + "</code>");
  }
  head +=
      "<th scope=\"col\">Folder</th><th scope=\"col\">Methods</th><th scope=\"col\">Seeds</th>"
      "<th scope=\"col\">Runs</th><th scope=\"col\">Failed</th>";
  std::string rows;
  for (std::size_t i = 0; i < data.settings.size(); ++i) {
    const Setting& s = data.settings[i];
    int runs = 0, failed = 0;
    for (const auto& [scene, byMethod] : s.runs) {
      for (const auto& [method, r] : byMethod) {
        runs += static_cast<int>(r.averageCoverage.size());
        failed += r.failed;
      }
    }
    rows += fmt::format("<tr data-setting=\"{}\"><th scope=\"row\">{}</th>", escapeXml(s.name),
                        settingHeading(s, i == data.reference));
    for (const auto& d : data.parameters)
      rows += fmt::format("<td class=\"num\">{}</td>", escapeXml(d.values[i]));
    rows += fmt::format(
        "<td><code>{}</code></td><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
        "<td class=\"num\">{}</td></tr>\n",
        escapeXml(s.name), escapeXml(join(s.manifest.methods, ", ")), s.manifest.seeds, runs,
        failed);
  }
  std::string notes;
  for (const auto& note : data.notes)
    notes += "<p class=\"note\">" + escapeXml(note) + "</p>\n";
  return fmt::format(
      "<section id=\"settings\">\n<h2>Settings</h2>\n<p>{}</p>\n{}<div class=\"table-wrap\">"
      "<table class=\"settings\">\n<thead><tr>{}</tr></thead>\n<tbody>\n{}</tbody></table>"
      "</div>\n</section>\n",
      data.parameters.empty()
          ? "Every parameter is the same in all settings."
          : "The parameters that differ between the settings, as each folder's batch.json "
            "records them; every other parameter is the same in all. A setting's name links to "
            "its own report.",
      notes, head, rows);
}

// Per method, a box per setting over the scenes: how much its mean coverage differs from the
// reference setting's on each scene.
std::string differencePlot(const SettingsData& data, const Verdicts& verdicts) {
  if (data.settings.size() < 2) return {};
  ChartSpec spec;
  spec.width =
      std::clamp(220.0 + 110.0 * static_cast<double>(data.settings.size() - 1), 600.0, 1100.0);
  spec.height = 340.0;
  spec.ariaLabel = "difference in mean coverage from the reference setting, per scene";
  spec.x.label = "setting";
  std::vector<std::size_t> shown;
  for (std::size_t i = 0; i < data.settings.size(); ++i) {
    if (i == data.reference) continue;
    shown.push_back(i);
    const std::string& label = data.settings[i].label;
    spec.categories.push_back(
        label.size() <= kMaxCategoryLabel ? label : label.substr(0, kMaxCategoryLabel - 3) + "...");
  }
  std::vector<std::vector<std::vector<double>>> deltas(shown.size());  // setting, method, scene
  double lo = 0.0, hi = 0.0;
  for (std::size_t k = 0; k < shown.size(); ++k) {
    deltas[k].resize(data.methods.size());
    for (std::size_t m = 0; m < data.methods.size(); ++m) {
      for (const auto& scene : data.scenes) {
        if (const auto c = versusReference(verdicts, shown[k], scene, data.methods[m])) {
          deltas[k][m].push_back(c->meanDifference);
          lo = std::min(lo, c->meanDifference);
          hi = std::max(hi, c->meanDifference);
        }
      }
    }
  }
  spec.y = {"Δ mean coverage per scene", lo, hi, 7};
  for (const auto& method : data.methods) {
    spec.legend.push_back({std::string(methodStyle(method).label),
                           std::string(methodStyle(method).color), Swatch::Box});
  }
  spec.legend.push_back({"outlier (beyond 1.5 IQR)", "#555", Swatch::Plus});
  Chart chart(spec);
  const double zero[] = {0.0, 0.0};
  const double ends[] = {-0.5, static_cast<double>(shown.size()) - 0.5};
  chart.addLine(ends, zero, "#8a8f98", 1.0, true);
  const double width = 0.8 / static_cast<double>(data.methods.size());
  for (std::size_t k = 0; k < shown.size(); ++k) {
    for (std::size_t m = 0; m < data.methods.size(); ++m) {
      if (deltas[k][m].empty()) continue;
      const BoxStats b = boxStats(deltas[k][m]);
      chart.addBox(
          k, -0.4 + width * (static_cast<double>(m) + 0.5), width * 0.85, b,
          methodStyle(data.methods[m]).color,
          fmt::format("{} · {}: median Δ {}, quartiles {} – {}, n = {} scenes",
                      data.settings[shown[k]].label, data.methods[m],
                      fmt::format("{:+.3f}", b.median), fmt::format("{:+.3f}", b.q1),
                      fmt::format("{:+.3f}", b.q3), b.count),
          fmt::format("data-setting=\"{}\" data-method=\"{}\"",
                      escapeXml(data.settings[shown[k]].name), escapeXml(data.methods[m])));
    }
  }
  return fmt::format(
      "<figure class=\"panel\" data-figure=\"settings-difference\">\n{}<figcaption>Each box is "
      "one method in one setting over the scenes both it and the reference setting ran: the "
      "difference of their mean average coverage, one value per scene (above the dashed line: "
      "better than the reference).</figcaption>\n</figure>\n",
      chart.svg());
}

// The settings in the order of the one parameter they differ in: by its value where every
// value is a number ("inf" last, as a communication range without limit), else as given.
std::vector<std::size_t> byParameterValue(const SettingsData& data) {
  std::vector<std::size_t> order(data.settings.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  const std::vector<std::string>& values = data.parameters.front().values;
  std::vector<double> numbers;
  for (const std::string& v : values) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || end != v.c_str() + v.size() || std::isnan(x)) return order;
    numbers.push_back(x);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return numbers[a] < numbers[b]; });
  return order;
}

// A study of one parameter (a communication range, a sample count): each method's mean
// coverage over the scenes against its value, one line per method, so that a method that
// needs the parameter and one that does not (a centralized reference) read side by side.
std::string trendPlot(const SettingsData& data, const Verdicts& verdicts) {
  if (data.parameters.size() != 1 || data.settings.size() < 2) return {};
  const DifferingParameter& parameter = data.parameters.front();
  const std::vector<std::size_t> order = byParameterValue(data);
  ChartSpec spec;
  spec.width = std::clamp(260.0 + 90.0 * static_cast<double>(order.size()), 520.0, 1000.0);
  spec.height = 320.0;
  spec.ariaLabel = "mean coverage over the scenes against " + parameter.key + ", per method";
  spec.x.label = parameter.key;
  for (const std::size_t i : order)
    spec.categories.push_back(parameter.values[i]);
  double lo = 1.0, hi = 0.0;
  std::vector<std::vector<double>> xs(data.methods.size()), ys(data.methods.size());
  for (std::size_t m = 0; m < data.methods.size(); ++m) {
    for (std::size_t k = 0; k < order.size(); ++k) {
      const Overall o = overall(data, verdicts, order[k], data.methods[m]);
      if (o.scenes == 0) continue;
      xs[m].push_back(static_cast<double>(k));
      ys[m].push_back(o.meanCoverage);
      lo = std::min(lo, o.meanCoverage);
      hi = std::max(hi, o.meanCoverage);
    }
  }
  if (hi < lo) return {};
  spec.y = {"mean average coverage", lo, hi, 6};
  for (const auto& method : data.methods) {
    spec.legend.push_back({std::string(methodStyle(method).label),
                           std::string(methodStyle(method).color), Swatch::Line});
  }
  Chart chart(spec);
  for (std::size_t m = 0; m < data.methods.size(); ++m)
    chart.addLine(xs[m], ys[m], methodStyle(data.methods[m]).color, 2.0);
  std::string orderText;
  for (const std::size_t i : order)
    orderText += (orderText.empty() ? "" : ",") + parameter.values[i];
  return fmt::format(
      "<figure class=\"panel\" data-figure=\"settings-trend\" data-order=\"{}\">\n{}"
      "<figcaption>Each line is one method: its mean over the scenes of the mean average "
      "coverage (eq. 4) in each setting, by the value of {}.</figcaption>\n</figure>\n",
      escapeXml(orderText), chart.svg(), escapeXml(parameter.key));
}

std::string overallSection(const SettingsData& data, const Verdicts& verdicts) {
  std::string head = "<th scope=\"col\">Method</th>";
  for (std::size_t i = 0; i < data.settings.size(); ++i)
    head += "<th scope=\"col\">" + settingHeading(data.settings[i], i == data.reference) + "</th>";
  std::string rows;
  for (const auto& method : data.methods) {
    rows += fmt::format("<tr data-method=\"{}\"><th scope=\"row\">{}</th>", escapeXml(method),
                        methodName(method));
    for (std::size_t i = 0; i < data.settings.size(); ++i) {
      const Overall o = overall(data, verdicts, i, method);
      if (o.scenes == 0) {
        rows += "<td class=\"num\">—</td>";
        continue;
      }
      rows += fmt::format(
          "<td class=\"num\" data-setting=\"{}\" data-mean=\"{}\" data-wins=\"{}\" "
          "data-ties=\"{}\" data-losses=\"{}\" data-undecided=\"{}\">{}<br><span "
          "class=\"muted\">{}</span></td>",
          escapeXml(data.settings[i].name), o.meanCoverage, o.wins, o.ties, o.losses, o.undecided,
          fixed(o.meanCoverage, 3),
          i == data.reference
              ? fmt::format("{} scenes", o.scenes)
              : fmt::format("{} / {} / {}{}", o.wins, o.ties, o.losses,
                            o.undecided > 0 ? fmt::format(" ({} undecided)", o.undecided) : ""));
    }
    rows += "</tr>\n";
  }
  return fmt::format(
      "<section id=\"overall\">\n<h2>Over all scenes</h2>\n<p>Per method and setting: the mean "
      "over scenes of the mean average coverage (eq. 4), and below it the scenes where the "
      "setting wins / ties / loses against the reference setting.</p>\n<div "
      "class=\"table-wrap\"><table class=\"overall\">\n<thead><tr>{}</tr></thead>\n<tbody>\n{}"
      "</tbody></table></div>\n{}</section>\n",
      head, rows, trendPlot(data, verdicts) + differencePlot(data, verdicts));
}

std::string sceneCell(const SettingsData& data, const Verdicts& verdicts, std::size_t i,
                      const std::string& scene, const std::string& method, bool best) {
  const SettingRuns* runs = runsOf(data.settings[i], scene, method);
  if (runs == nullptr) return "<td class=\"num\">—</td>";
  const records::Description d = records::describe(runs->averageCoverage);
  std::string text = fixed(d.mean, 3) + " ± " + fixed(d.sd, 3);
  if (best) text = "<b>" + text + "</b>";
  std::string verdict = "reference";
  std::string mark,
      title = fmt::format("n = {}, median {}, mean utilization {}", d.count, fixed(d.median, 3),
                          fixed(mean(runs->averageUtilization), 3));
  if (runs->failed > 0) title += fmt::format(", {} failed", runs->failed);
  if (const auto c = versusReference(verdicts, i, scene, method)) {
    verdict = c->verdict == records::Verdict::Better      ? "better"
              : c->verdict == records::Verdict::Worse     ? "worse"
              : c->verdict == records::Verdict::Undecided ? "undecided"
                                                          : "tie";
    title += fmt::format("; Δ {:+.3f} against the reference, p = {:.3g} ({})", c->meanDifference,
                         c->pValue, c->exact ? "exact" : "normal approximation");
    if (c->verdict == records::Verdict::Better) {
      mark = fmt::format(" <span style=\"color:{}\" aria-label=\"better\">▲</span>", kBetterColor);
    } else if (c->verdict == records::Verdict::Worse) {
      mark = fmt::format(" <span style=\"color:{}\" aria-label=\"worse\">▼</span>", kWorseColor);
    }
  } else if (i != data.reference) {
    verdict = "";  // the reference did not run it
  }
  return fmt::format(
      "<td class=\"num\" data-setting=\"{}\" data-mean=\"{}\" data-verdict=\"{}\" "
      "title=\"{}\">{}{}</td>",
      escapeXml(data.settings[i].name), d.mean, verdict, escapeXml(title), text, mark);
}

std::string perSceneSection(const SettingsData& data, const Verdicts& verdicts) {
  std::string head = "<th scope=\"col\">Scene</th><th scope=\"col\">Method</th>";
  for (std::size_t i = 0; i < data.settings.size(); ++i)
    head += "<th scope=\"col\">" + settingHeading(data.settings[i], i == data.reference) + "</th>";
  const std::size_t columns = data.settings.size() + 2;
  std::string bodies;
  for (const SceneGroup group : kSceneGroups) {
    std::string body;
    for (const auto& scene : data.scenes) {
      if (data.groups.at(scene) != group) continue;
      std::vector<std::string> methods;
      for (const auto& method : data.methods) {
        for (const auto& s : data.settings) {
          if (runsOf(s, scene, method) != nullptr) {
            methods.push_back(method);
            break;
          }
        }
      }
      for (std::size_t k = 0; k < methods.size(); ++k) {
        // Bold marks the one best mean of the row; equal means stay plain.
        std::optional<std::size_t> best;
        int atBest = 0;
        double bestMean = 0.0;
        for (std::size_t i = 0; i < data.settings.size(); ++i) {
          const SettingRuns* runs = runsOf(data.settings[i], scene, methods[k]);
          if (runs == nullptr) continue;
          const double m = mean(runs->averageCoverage);
          if (!best || m > bestMean) {
            best = i;
            bestMean = m;
            atBest = 1;
          } else if (m == bestMean) {
            ++atBest;
          }
        }
        body += fmt::format("<tr data-scene=\"{}\" data-method=\"{}\">", escapeXml(scene),
                            escapeXml(methods[k]));
        if (k == 0) {
          body += fmt::format("<th scope=\"rowgroup\" rowspan=\"{}\">{}</th>", methods.size(),
                              escapeXml(scene));
        }
        body += "<td>" + methodName(methods[k]) + "</td>";
        for (std::size_t i = 0; i < data.settings.size(); ++i) {
          body += sceneCell(data, verdicts, i, scene, methods[k],
                            data.settings.size() > 1 && atBest == 1 && best == i);
        }
        body += "</tr>\n";
      }
    }
    if (body.empty()) continue;
    bodies += fmt::format(
        "<tbody data-group=\"{}\"><tr class=\"group\"><th colspan=\"{}\" scope=\"rowgroup\">{}"
        "</th></tr>\n{}</tbody>\n",
        groupName(group), columns, groupTitle(group), body);
  }
  return fmt::format(
      "<section id=\"per-scene\">\n<h2>Per scene</h2>\n<p>Mean ± sd over seeds of the runs' "
      "average coverage; <span style=\"color:{}\">▲</span> significantly better and <span "
      "style=\"color:{}\">▼</span> significantly worse than the reference setting's runs of the "
      "same method, unmarked a tie; bold the best setting of the row. Hover a cell for n, the "
      "median, utilization, Δ and p.</p>\n<div class=\"table-wrap\"><table "
      "class=\"summary settings-scenes\">\n<thead><tr>{}</tr></thead>\n{}</table></div>\n"
      "</section>\n",
      kBetterColor, kWorseColor, head, bodies);
}

}  // namespace

std::string buildSettingsReportHtml(const SettingsData& data, const BuildContext& context) {
  const Setting& reference = data.settings[data.reference];
  const BroughtMethodLooks looks(reference.manifest.methodLooks);
  std::string html = documentHead(fmt::format("camcov settings: {} settings × {} scenes",
                                              data.settings.size(), data.scenes.size()),
                                  reference.manifest.toolVersion);
  html +=
      "<nav class=\"toc\" aria-label=\"Sections\"><ul><li><a href=\"#settings\">Settings</a>"
      "</li><li><a href=\"#overall\">Over all scenes</a></li><li><a href=\"#per-scene\">Per "
      "scene</a></li></ul></nav>\n<div class=\"page\">\n";
  const Verdicts verdicts = testAgainstReference(data);
  html += header(data, verdicts, context);
  html += "<main>\n" + settingsSection(data) + overallSection(data, verdicts) +
          perSceneSection(data, verdicts) + "</main>\n";
  html += fmt::format(
      "<footer>Written by camcov {} from the results folders alone, except the build date and "
      "machine in the header; <code>camcov report FOLDER...</code> writes it again.</footer>\n"
      "</div>\n</body>\n</html>\n",
      escapeXml(reference.manifest.toolVersion));
  return html;
}

void writeSettingsReport(const std::vector<std::filesystem::path>& folders,
                         const std::string& reference, const std::filesystem::path& reportFile) {
  const std::filesystem::path target = std::filesystem::absolute(reportFile);
  for (const std::filesystem::path& folder : folders)
    records::BatchFolder(folder).refuseToReplaceContent(target);
  const SettingsData data = loadSettingsData(folders, reference, target);
  records::writeFileAtomically(target, buildSettingsReportHtml(data, currentBuildContext()));
}

}  // namespace camcov::reports
