#pragma once
// The report's sections, one file each; every function returns an HTML fragment (a <section>,
// or nothing when there is nothing to show). report_builder.cpp puts them in order.
#include <string>

#include "reports/build_context.h"
#include "reports/report_data.h"

namespace camcov::reports {

// 1. Tool, date, machine, command, jobs, compute time, and the result in one sentence.
std::string headerSection(const ReportData& data, const BuildContext& context);
// 2. Per scene and method: coverage, utilization, safety; winner and p; grouped, sortable.
std::string summarySection(const ReportData& data);
// 2a. Per group of scenes (family or folder), when there are several: mean coverage and
// wins/ties/losses.
std::string groupsSection(const ReportData& data);
// 2b. The methods other than the reference against each other (e.g. ours against the paper's).
std::string pairsSection(const ReportData& data);
// 2c. Scenes that hold still: each method's final coverage against the offline optimum.
std::string optimumSection(const ReportData& data);
// 3. The paper's Fig. 4: box-and-whisker plots of average coverage (and utilization).
std::string boxPlotSection(const ReportData& data);
// 4. The paper's Fig. 5: coverage and utilization over time, per scene.
std::string timeSeriesSection(const ReportData& data);
// 5. The paper's Fig. 3: each scene at t = 0 with paths and speeds.
std::string sceneGallerySection(const ReportData& data);
// 6. The paper's Table I as used, overrides marked.
std::string parametersSection(const ReportData& data);
// 7. Videos found in videos/ next to the results.
std::string videosSection(const ReportData& data);
// Jobs that failed, with their errors.
std::string failuresSection(const ReportData& data);

}  // namespace camcov::reports
