#include "reports/verdict_markup.h"

#include <fmt/format.h>

#include <cmath>

#include "reports/markup.h"
#include "reports/method_style.h"

namespace camcov::reports {

std::string pValueText(double p) {
  return p < 0.001 ? "&lt;&nbsp;0.001" : fixed(p, 3);
}

std::string winnerBadge(const std::string& winner) {
  if (winner.empty()) return "<span class=\"badge\">—</span>";
  const std::string_view color =
      winner == "tie" || winner == "undecided" ? "#8a8f98" : methodStyle(winner).color;
  return fmt::format("<span class=\"badge\" style=\"--c:{}\">{}</span>", color, escapeXml(winner));
}

std::string comparisonCells(const records::Comparison* c) {
  if (c == nullptr || c->winner.empty())
    return "<td class=\"num\">—</td><td class=\"num\">—</td><td>" + winnerBadge("") + "</td>";
  const auto& ci = c->meanDifferenceCI;
  const std::string interval =
      std::isfinite(ci.low) ? fmt::format("95 % interval [{:+.4f}, {:+.4f}]; ", ci.low, ci.high)
                            : std::string();
  return fmt::format(
      "<td class=\"num\" title=\"{}A₁₂ = {:.2f}\">{:+.3f}</td><td class=\"num\" "
      "title=\"{}\">{}</td><td title=\"{}\">{}</td>",
      interval, c->a12, c->meanDifference,
      c->exact ? "exact permutation test" : "normal approximation", pValueText(c->pValue),
      c->seedsNeeded > 0 ? fmt::format("too few seeds: {} per method needed", c->seedsNeeded)
                         : std::string(),
      winnerBadge(c->winner));
}

}  // namespace camcov::reports
