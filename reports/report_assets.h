#pragma once
// The report's stylesheet and its one script, inlined into every report: a report must work
// offline and from a single file.
#include <string_view>

namespace camcov::reports {

// Screen and print styles (A4 landscape; figures and table rows never split across pages).
std::string_view reportStyle();
// Sorts each table.sortable by the data-* key of the clicked column; logs nothing.
std::string_view reportScript();

}  // namespace camcov::reports
