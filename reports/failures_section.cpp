// The jobs that failed, so a reader sees why a scene has fewer runs than seeds.
#include <fmt/format.h>

#include "reports/markup.h"
#include "reports/sections.h"

namespace camcov::reports {

std::string failuresSection(const ReportData& data) {
  const auto& failures = data.summary.failures;
  if (failures.empty()) return {};
  std::string rows;
  for (const auto& f : failures) {
    rows += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"num\">{}</td><td>{}</td></tr>\n",
                        escapeXml(f.scene), escapeXml(f.method), f.seed, escapeXml(f.error));
  }
  return fmt::format(
      "<section id=\"failures\">\n<h2>Failed jobs ({})</h2>\n<p>These runs stopped with an "
      "error and are left out of every statistic above; their errors are in "
      "<code>runs/*.error.json</code>. Running the same <code>camcov bench</code> again retries "
      "them.</p>\n<div class=\"table-wrap\"><table class=\"failures\"><thead><tr><th "
      "scope=\"col\">Scene</th><th scope=\"col\">Method</th><th scope=\"col\">Seed</th><th "
      "scope=\"col\">Error</th></tr></thead>\n<tbody>\n{}</tbody></table></div>\n</section>\n",
      failures.size(), rows);
}

}  // namespace camcov::reports
