#pragma once
// The report's stylesheet and its one script, inlined into every report: a report must work
// offline and from a single file.
#include <string>
#include <string_view>

namespace camcov::reports {

// The document up to and including <body>: charset, viewport, a Content-Security-Policy that
// lets the page load nothing but itself and local videos, generator, title (escaped here) and
// the stylesheet. Shared by the report of a batch and the report of settings side by side.
std::string documentHead(std::string_view title, std::string_view toolVersion);
// Screen and print styles (A4 landscape; figures and table rows never split across pages).
std::string_view reportStyle();
// Sorts each table.sortable by the data-* key of the clicked column; logs nothing.
std::string_view reportScript();

}  // namespace camcov::reports
