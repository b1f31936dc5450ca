#pragma once
// The report's sections, one file each; every function returns an HTML fragment (a <section>,
// or nothing when there is nothing to show). The table at the end is the page: a new section
// is its own file, its declaration and one row there.
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

#include "reports/build_context.h"
#include "reports/report_data.h"

namespace camcov::reports {

// Above the sections: tool, date, machine, command, jobs, compute time, and the result in one
// sentence.
std::string headerSection(const ReportData& data, const BuildContext& context);

std::string summarySection(const ReportData& data);
std::string groupsSection(const ReportData& data);
std::string pairsSection(const ReportData& data);
std::string optimumSection(const ReportData& data);
std::string boxPlotSection(const ReportData& data);
std::string timeSeriesSection(const ReportData& data);
std::string sceneGallerySection(const ReportData& data);
std::string parametersSection(const ReportData& data);
std::string videosSection(const ReportData& data);
std::string failuresSection(const ReportData& data);

// A section of the page's <main> and its link in the navigation.
struct ReportSection {
  std::string (*write)(const ReportData& data);
  std::string_view anchor;  // the <section>'s id, which the link points at
  std::string_view link;    // the link's words; "{}" stands for the count
  // How many things the section shows: 0 leaves the link out; nullptr, always linked.
  std::size_t (*count)(const ReportData& data) = nullptr;
};

// The sections in the page's order, which the navigation follows.
inline constexpr ReportSection kReportSections[] = {
    // 2a. Per group of scenes (family or folder), when there are several: mean coverage and
    // wins/ties/losses.
    {groupsSection, "groups", "By family or folder",
     [](const ReportData& d) { return d.summary.groups.size() > 1 ? d.summary.groups.size() : 0; }},
    // 2. Per scene and method: coverage, utilization, safety; winner and p; grouped, sortable.
    {summarySection, "summary", "Summary"},
    // 2b. The methods other than the reference against each other (e.g. ours against the
    // paper's).
    {pairsSection, "pairs", "Methods against each other",
     [](const ReportData& d) { return d.summary.pairTallies.size(); }},
    // 2c. Scenes that hold still: each method's final coverage against the offline optimum.
    {optimumSection, "optimum", "Against the optimum",
     [](const ReportData& d) {
       return static_cast<std::size_t>(
           std::count_if(d.scenes.begin(), d.scenes.end(),
                         [](const SceneData& s) { return s.optimum.has_value(); }));
     }},
    // 3. The paper's Fig. 4: box-and-whisker plots of average coverage (and utilization).
    {boxPlotSection, "box-plots", "Per scene (Fig. 4)"},
    // 4. The paper's Fig. 5: coverage and utilization over time, per scene.
    {timeSeriesSection, "time-series", "Over time (Fig. 5)"},
    // 5. The paper's Fig. 3: each scene at t = 0 with paths and speeds.
    {sceneGallerySection, "scenes", "Scenes (Fig. 3)"},
    // 6. The paper's Table I as used, overrides marked.
    {parametersSection, "parameters", "Parameters (Table I)"},
    // 7. Videos found in videos/ next to the results.
    {videosSection, "videos", "Videos", [](const ReportData& d) { return d.videos.size(); }},
    // Jobs that failed, with their errors.
    {failuresSection, "failures", "Failed jobs ({})",
     [](const ReportData& d) { return d.summary.failures.size(); }},
};

}  // namespace camcov::reports
