#include "reports/report_builder.h"

#include "reports/method_style.h"

#include <fmt/format.h>

#include "records/atomic_file.h"
#include "records/batch_folder.h"
#include "reports/markup.h"
#include "reports/report_assets.h"
#include "reports/sections.h"

namespace camcov::reports {
namespace {

// The links of the sections that show something, in the page's order.
std::string navigation(const ReportData& data) {
  std::string links;
  for (const ReportSection& section : kReportSections) {
    const std::size_t count = section.count == nullptr ? 1 : section.count(data);
    if (count == 0) continue;
    links += fmt::format("<li><a href=\"#{}\">{}</a></li>", section.anchor,
                         fmt::format(fmt::runtime(section.link), count));
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
  for (const ReportSection& section : kReportSections)
    html += section.write(data);
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
