#pragma once
// How a comparison of two methods reads in the tables: its p-value and its winner's badge,
// the same in the summary (against the reference) and between the other methods.
#include <string>

#include "records/verdicts.h"

namespace camcov::reports {

// "< 0.001", else three decimals.
std::string pValueText(double p);
// The winner ("tie" and "undecided" grey, a method in its colour), or a dash when there was no
// comparison.
std::string winnerBadge(const std::string& winner);

// A comparison's three table cells: Δ of the mean average coverage (its 95 % interval and the
// effect size A₁₂ on hover), p (the test on hover) and the winner's badge (for an undecided one,
// the seeds it needs on hover); dashes when nothing was compared.
std::string comparisonCells(const records::Comparison* c);

}  // namespace camcov::reports
