#include "reports/explorer/explorer_page.h"

#include <fmt/format.h>

#include "camcov/version.h"
#include "records/atomic_file.h"
#include "records/run_files.h"
#include "reports/explorer/explorer_assets.h"
#include "reports/explorer/explorer_data.h"
#include "reports/markup.h"
#include "reports/report_assets.h"
#include "util/input_error.h"
#include "viz/run_replay.h"

namespace camcov::reports::explorer {
namespace {

// Nothing to fetch: the data, the script and the style are in the page.
constexpr std::string_view kExplorerPolicy =
    "default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'";

}  // namespace

std::string buildExplorerHtml(std::span<const records::RunRecord> runs, const scene::Scene& scene,
                              const std::string& playgroundUrl) {
  if (runs.empty()) throw InputError("no run to explore");
  nlohmann::json data = explorerData(runs, scene);
  if (!playgroundUrl.empty()) data["playground"] = playgroundUrl;
  std::vector<std::string> labels;
  for (const auto& run : runs)
    labels.push_back(fmt::format("{} seed {}", run.metadata.method, run.metadata.seed));
  return documentHead(scene.name + " — camcov run explorer", kVersion, explorerStyle(),
                      kExplorerPolicy) +
         fmt::format(
             "<header><h1>{}</h1><p class=\"lede\">camcov run explorer: {} over {:.1f} s. Space "
             "plays and pauses, ← → step, Home and End jump to the ends, a click on the curves "
             "jumps there; the wheel zooms the scene, a drag pans it.</p></header>\n"
             "<div class=\"controls\"><button id=\"play\" type=\"button\" "
             "aria-pressed=\"false\">Play</button><button id=\"step-back\" type=\"button\" "
             "aria-label=\"step back\">◀ step</button><button id=\"step-forward\" "
             "type=\"button\" aria-label=\"step forward\">step ▶</button><input id=\"slider\" "
             "type=\"range\" min=\"0\" max=\"0\" step=\"1\" value=\"0\" "
             "aria-label=\"step\"><span id=\"time\"></span><button id=\"zoom-reset\" "
             "type=\"button\" title=\"show the whole scene again\">whole scene</button></div>\n"
             "<svg id=\"timeline\" class=\"timeline\" role=\"img\" aria-label=\"coverage (solid) "
             "and utilization (dashed) over time, with events\"></svg>\n"
             "<div id=\"curve-legend\"></div>\n"
             "<div id=\"runs\"></div>\n<div id=\"legend\"></div>\n"
             "<footer>Written by camcov {} from the results files; geometry as the frames compute "
             "it, to the millimetre.</footer>\n"
             "<script type=\"application/json\" id=\"camcov-data\">{}</script>\n"
             "<script>{}</script>\n<script>{}</script>\n</body>\n</html>\n",
             escapeXml(scene.name), escapeXml(join(labels, ", ")), runs.front().steps.back().time,
             escapeXml(kVersion), scriptSafe(data.dump()), worldViewScript(), explorerScript());
}

void writeExplorer(const std::vector<std::filesystem::path>& runFiles,
                   const std::filesystem::path& out, const std::filesystem::path& sceneFile,
                   const std::filesystem::path& playgroundPage) {
  std::vector<records::RunRecord> runs;
  for (const auto& file : runFiles)
    runs.push_back(records::loadRunFile(file));
  if (runs.empty()) throw InputError("no run to explore");
  const viz::RunScene scene = viz::loadRunScene(runs.front().metadata, sceneFile);
  const std::string playgroundUrl = playgroundPage.empty()
                                        ? std::string()
                                        : relativeUrl(std::filesystem::absolute(playgroundPage),
                                                      std::filesystem::absolute(out).parent_path());
  records::writeFileAtomically(out, buildExplorerHtml(runs, scene.scene, playgroundUrl));
}

}  // namespace camcov::reports::explorer
