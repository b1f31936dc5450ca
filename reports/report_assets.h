#pragma once
// The report's stylesheet and its one script, inlined into every report: a report must work
// offline and from a single file.
#include <string>
#include <string_view>

namespace camcov::reports {

// Screen and print styles (A4 landscape; figures and table rows never split across pages).
std::string_view reportStyle();

// Everything a report may load is inline, or a local video next to it ('self' when served,
// file: when opened from disk); anything else is blocked and reported by the browser.
inline constexpr std::string_view kReportPolicy =
    "default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'; "
    "img-src data:; media-src 'self' file:";

// The document up to and including <body>: charset, viewport, the Content-Security-Policy,
// generator, title (escaped here) and the stylesheet. Shared by every page camcov writes: the
// report of a batch, of settings side by side, and the run explorer (its own style, and a
// policy without media).
std::string documentHead(std::string_view title, std::string_view toolVersion,
                         std::string_view style = reportStyle(),
                         std::string_view contentSecurityPolicy = kReportPolicy);

// Sorts each table.sortable by the data-* key of the clicked column; logs nothing.
std::string_view reportScript();

}  // namespace camcov::reports
