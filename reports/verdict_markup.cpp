#include "reports/verdict_markup.h"

#include <fmt/format.h>

#include "reports/markup.h"
#include "reports/method_style.h"

namespace camcov::reports {

std::string pValueText(double p) {
  return p < 0.001 ? "&lt;&nbsp;0.001" : fixed(p, 3);
}

std::string winnerBadge(const std::string& winner) {
  if (winner.empty()) return "<span class=\"badge\">—</span>";
  const std::string_view color = winner == "tie" ? "#8a8f98" : methodStyle(winner).color;
  return fmt::format("<span class=\"badge\" style=\"--c:{}\">{}</span>", color, escapeXml(winner));
}

}  // namespace camcov::reports
