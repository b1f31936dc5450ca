#pragma once
// How a comparison of two methods reads in the tables: its p-value and its winner's badge,
// the same in the summary (against the reference) and between the other methods.
#include <string>

namespace camcov::reports {

// "< 0.001", else three decimals.
std::string pValueText(double p);
// The winner ("tie" grey, a method in its colour), or a dash when there was no comparison.
std::string winnerBadge(const std::string& winner);

}  // namespace camcov::reports
