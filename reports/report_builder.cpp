#include "reports/report_builder.h"

#include "reports/method_style.h"

#include <fmt/format.h>

#include <algorithm>

#include "records/atomic_file.h"
#include "records/batch_folder.h"
#include "reports/markup.h"
#include "reports/report_assets.h"
#include "reports/sections.h"

namespace camcov::reports {
namespace {

std::string navigation(const ReportData& data) {
  std::string links =
      data.summary.groups.size() > 1 ? "<li><a href=\"#groups\">By family or folder</a></li>" : "";
  links +=
      "<li><a href=\"#summary\">Summary</a></li><li><a href=\"#box-plots\">Per scene (Fig. 4)"
      "</a></li><li><a href=\"#time-series\">Over time (Fig. 5)</a></li><li><a "
      "href=\"#scenes\">Scenes (Fig. 3)</a></li><li><a href=\"#parameters\">Parameters "
      "(Table I)</a></li>";
  if (!data.summary.pairTallies.empty())
    links += "<li><a href=\"#pairs\">Methods against each other</a></li>";
  if (std::any_of(data.scenes.begin(), data.scenes.end(),
                  [](const SceneData& s) { return s.optimum.has_value(); }))
    links += "<li><a href=\"#optimum\">Against the optimum</a></li>";
  if (!data.videos.empty()) links += "<li><a href=\"#videos\">Videos</a></li>";
  if (!data.summary.failures.empty()) {
    links += fmt::format("<li><a href=\"#failures\">Failed jobs ({})</a></li>",
                         data.summary.failures.size());
  }
  return "<nav class=\"toc\" aria-label=\"Sections\"><ul>" + links + "</ul></nav>\n";
}

}  // namespace

std::string buildReportHtml(const ReportData& data, const BuildContext& context) {
  const BroughtMethodLooks looks(data.manifest.methodLooks);
  std::string html = documentHead(fmt::format("camcov report: {} scenes × {} seeds",
                                              data.manifest.scenes.size(), data.manifest.seeds),
                                  data.manifest.toolVersion);
  html += navigation(data);
  html += "<div class=\"page\">\n";
  html += headerSection(data, context);
  html += "<main>\n";
  html += groupsSection(data);
  html += summarySection(data);
  html += pairsSection(data);
  html += optimumSection(data);
  html += boxPlotSection(data);
  html += timeSeriesSection(data);
  html += sceneGallerySection(data);
  html += parametersSection(data);
  html += videosSection(data);
  html += failuresSection(data);
  html += "</main>\n";
  html += fmt::format(
      "<footer>Written by camcov {} from the results folder alone, except the build date and "
      "machine in the header; <code>camcov report RESULTS_DIR</code> writes it again.</footer>\n",
      escapeXml(data.manifest.toolVersion));
  html += fmt::format("</div>\n<script>{}</script>\n</body>\n</html>\n", reportScript());
  return html;
}

void writeReport(const std::filesystem::path& resultsDir, const std::filesystem::path& reportFile) {
  const std::filesystem::path target = std::filesystem::absolute(reportFile);
  records::BatchFolder(resultsDir).refuseToReplaceContent(target);
  const ReportData data = loadReportData(resultsDir, target);
  records::writeFileAtomically(target, buildReportHtml(data, currentBuildContext()));
}

}  // namespace camcov::reports
