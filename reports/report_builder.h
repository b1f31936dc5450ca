#pragma once
// The report (SPEC section 6): one HTML file that works offline — inline CSS and SVG,
// one small inline script, videos by relative URL, and a Content-Security-Policy that lets
// the browser fetch nothing else. Sections: header, summary, Fig. 4, Fig. 5, Fig. 3,
// Table I, videos, failed jobs.
#include <filesystem>
#include <string>

#include "reports/build_context.h"
#include "reports/report_data.h"

namespace camcov::reports {

// The document; a pure function of its inputs.
std::string buildReportHtml(const ReportData& data, const BuildContext& context);

// Reads `resultsDir` and writes the report to `reportFile` atomically. Throws InputError if the
// folder is not a finished batch (no batch.json or summary.json).
void writeReport(const std::filesystem::path& resultsDir, const std::filesystem::path& reportFile);

}  // namespace camcov::reports
