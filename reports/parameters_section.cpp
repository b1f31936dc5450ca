// Section 6, the paper's Table I as this batch used it: every row of the parameter table
// (src/params/parameter_table.h), with the values that differ from the defaults marked.
#include <fmt/format.h>

#include "params/parameter_table.h"
#include "reports/markup.h"
#include "reports/sections.h"

namespace camcov::reports {
namespace {

// The column headings of the paper's Table I, plus the simulation settings of SPEC section 3.
const char* groupOf(std::string_view key) {
  const std::string_view group = key.substr(0, key.find('.'));
  if (group == "reward") return "Reward";
  if (group == "global") return "Global optimization";
  if (group == "local") return "Local optimization";
  if (group == "planner") return "Motion planning";
  if (group == "potential") return "Artificial potentials";
  if (group == "sim") return "Simulation";
  if (group == "safety") return "Safety layer";
  return "Other";
}

}  // namespace

std::string parametersSection(const ReportData& data) {
  const params::Parameters defaults;
  std::string rows;
  std::vector<std::string> overrides;
  std::string_view previousGroup;
  for (const params::ParamField& f : params::parameterTable()) {
    const double used = f.get(data.manifest.parameters), standard = f.get(defaults);
    const bool changed = used != standard;
    const std::string_view group = groupOf(f.key);
    if (group != previousGroup) {
      rows += fmt::format("<tr class=\"group\"><th colspan=\"6\" scope=\"rowgroup\">{}</th></tr>\n",
                          group);
      previousGroup = group;
    }
    rows += fmt::format(
        "<tr{}><td class=\"symbol\">{}</td><td><code>{}</code></td><td class=\"num\">{}{}</td>"
        "<td class=\"num\">{}</td><td>{}</td><td>{}</td></tr>\n",
        changed ? " class=\"override\"" : "", escapeXml(f.symbol), escapeXml(f.key),
        params::formatValue(f, used),
        changed ? " <span class=\"badge\" style=\"--c:#b45309\">set</span>" : "",
        params::formatValue(f, standard), escapeXml(f.unit), escapeXml(f.description));
    if (changed) {
      overrides.push_back(fmt::format("<code>{}</code> = {} (default {})", escapeXml(f.key),
                                      params::formatValue(f, used),
                                      params::formatValue(f, standard)));
    }
  }
  return fmt::format(
      "<section id=\"parameters\">\n<h2>Parameters (Table I)</h2>\n<p>{}</p>\n"
      "<div class=\"table-wrap\"><table class=\"parameters\">\n<thead><tr><th scope=\"col\">"
      "Symbol</th><th scope=\"col\">Key</th><th scope=\"col\">Value</th><th scope=\"col\">"
      "Default</th><th scope=\"col\">Unit</th><th scope=\"col\">Meaning</th></tr></thead>\n"
      "<tbody>\n{}</tbody></table></div>\n</section>\n",
      overrides.empty()
          ? "Every parameter at its default: the paper's Table I, plus our "
            "simulation settings."
          : "Overrides of the defaults (the paper's Table I): " + join(overrides, ", ") + ".",
      rows);
}

}  // namespace camcov::reports
