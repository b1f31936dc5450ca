#include "reports/playground/playground_page.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "camcov/version.h"
#include "params/parameters.h"
#include "records/atomic_file.h"
#include "reports/explorer/explorer_assets.h"
#include "reports/explorer/explorer_data.h"
#include "reports/markup.h"
#include "reports/playground/playground_assets.h"
#include "reports/report_assets.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"
#include "scene/scene_writer.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace camcov::reports::playground {
namespace {

// Nothing from the network: the engine compiles its WebAssembly from the page's own bytes
// (which a policy must allow: 'wasm-unsafe-eval'), read through a data: URL (connect-src
// data:); exported files are blob: downloads.
constexpr std::string_view kPlaygroundPolicy =
    "default-src 'none'; style-src 'unsafe-inline'; "
    "script-src 'unsafe-inline' 'wasm-unsafe-eval'; connect-src data:";

}  // namespace

std::string buildPlaygroundHtml(std::string_view sceneText, const std::string& fileName,
                                const scene::Scene& scene, double time,
                                std::span<const geometry::Pose> poses,
                                std::string_view engineScript) {
  nlohmann::json posesJson = nlohmann::json::array();
  for (const geometry::Pose& p : poses)
    posesJson.push_back({{"x", p.x}, {"y", p.y}, {"yaw_deg", scene::writtenDegrees(p.yaw)}});
  nlohmann::json colours = nlohmann::json::array();
  for (const scene::MovingObject& t : scene.targets)
    colours.push_back(t.color.empty() ? nlohmann::json() : nlohmann::json(t.color));
  const nlohmann::json data{{"scene", nlohmann::json::parse(sceneText)},
                            {"file", fileName},
                            {"time", time},
                            {"duration", scene.duration.value_or(params::SimParams{}.duration)},
                            {"poses", posesJson},
                            {"colors", colours},
                            {"palette", explorer::paletteJson()}};
  return documentHead(scene.name + " — camcov visibility playground", kVersion, playgroundStyle(),
                      kPlaygroundPolicy) +
         fmt::format(
             "<header><h1>{}</h1><p class=\"lede\">camcov visibility playground: the engine of "
             "camcov {}, compiled to WebAssembly, recomputes everything at every change. Drag a "
             "camera, turn it with the wheel (Shift: finely); drag any vertex (click a large "
             "object for its vertices), double-click an edge to add one, select one and press "
             "Delete to remove it; click an edge for who sees it. The wheel on the floor zooms, a "
             "drag on it pans.</p></header>\n"
             "<div class=\"toolbar\"><label>time <input id=\"time\" type=\"range\" min=\"0\" "
             "step=\"0.1\"></label><span id=\"time-value\">t = {:.2f} s</span>"
             "<button id=\"add-target\" type=\"button\">+ target</button>"
             "<button id=\"add-obstacle\" type=\"button\">+ obstacle</button>"
             "<button id=\"remove-object\" type=\"button\">remove the selected object"
             "</button><button id=\"delete-vertex\" type=\"button\">delete vertex</button>"
             "<button id=\"add-camera\" type=\"button\">+ camera</button>"
             "<button id=\"remove-camera\" type=\"button\">remove camera</button>"
             "<button id=\"zoom-reset\" type=\"button\" title=\"show the whole scene "
             "again\">whole scene</button></div>\n"
             "<main><svg id=\"world\" role=\"img\" aria-label=\"the scene\"></svg>\n<aside>"
             "<div id=\"message\" role=\"alert\" hidden></div>"
             "<section><h2>The team</h2><table id=\"terms\"><tbody>"
             "<tr><th>coverage, eq. (3)</th><td data-term=\"coverage\"></td></tr>"
             "<tr><th>weighted coverage</th><td data-term=\"weightedCoverage\"></td></tr>"
             "<tr><th>utilization, eq. (5)</th><td data-term=\"utilization\"></td></tr>"
             "<tr><th>repulsion, eq. (6)</th><td data-term=\"repulsion\"></td></tr>"
             "<tr><th>reward, eq. (8)</th><td data-term=\"reward\"></td></tr></tbody></table>"
             "</section>"
             "<section><h2>Cameras</h2><table id=\"cameras\"><thead><tr><th>#</th><th>x, y</th>"
             "<th>yaw</th><th>θ</th><th>cov.</th><th>util.</th><th>reward</th></tr></thead>"
             "<tbody></tbody></table><p><label>θ of the selected camera <input id=\"fov\" "
             "type=\"range\" min=\"1\" max=\"179\" step=\"0.5\" disabled></label> "
             "<span id=\"fov-value\"></span></p></section>"
             "<section><h2>Edge</h2><div id=\"edge\"></div></section>"
             "<section id=\"sweep\"><h2>The selected camera's sweep</h2><p>"
             "<button id=\"sweep-back\" type=\"button\">◀ event</button> "
             "<button id=\"sweep-forward\" type=\"button\">event ▶</button></p>"
             "<p id=\"sweep-step\"></p></section>"
             "<section><h2>From a picture to a test</h2><p><button id=\"export\" "
             "type=\"button\">export</button></p><div id=\"exported\" hidden><p>"
             "<a id=\"export-scene\"></a> · <a id=\"export-poses\"></a></p><p>reproduces these "
             "numbers:</p><code id=\"export-command\"></code><p class=\"hint\">As a "
             "regression test: save <a id=\"export-case\"></a> into "
             "tests/data/visibility_cases/ (docs/visibility.md).</p></div></section>"
             "</aside></main>\n"
             "<footer>camcov {}: the numbers are camcov inspect's, from the same C++.</footer>\n"
             "<script type=\"application/json\" id=\"camcov-data\">{}</script>\n"
             "<script>{}</script>\n<script>{}</script>\n<script>{}</script>\n</body>\n</html>\n",
             escapeXml(scene.name), escapeXml(kVersion), time, escapeXml(kVersion),
             scriptSafe(data.dump()), scriptSafe(std::string(engineScript)),
             explorer::worldViewScript(), playgroundScript());
}

void writePlayground(const std::filesystem::path& sceneFile, double time,
                     const std::optional<std::filesystem::path>& posesFile,
                     const std::filesystem::path& engine, const std::filesystem::path& out) {
  const scene::Scene scene = scene::loadScene(sceneFile);
  std::vector<geometry::Pose> poses = scene::initialPoses(scene);
  if (posesFile) {
    poses = scene::loadCameraPosesFor(*posesFile, scene);
    if (poses.size() != scene.cameras.size()) {
      throw InputError(fmt::format("{}: {} poses for the scene's {} cameras", posesFile->string(),
                                   poses.size(), scene.cameras.size()));
    }
  }
  if (!std::filesystem::is_regular_file(engine)) {
    throw InputError(engine.string() +
                     ": the WebAssembly engine is not there: install Debian's emscripten "
                     "(scripts/install_deps.sh does) and build again, or give --engine FILE");
  }
  const std::string engineScript = readWholeFile(engine);
  // Any other file (another script, an engine of other bindings) would make a page that
  // draws nothing: the engine this page calls begins with its interface's stamp.
  constexpr std::string_view kStamp = CAMCOV_ENGINE_STAMP;
  if (!engineScript.starts_with(std::string(kStamp) + "\n")) {
    throw InputError(fmt::format(
        "--engine {}: not the engine this page calls (its first line is not \"{}\"): give "
        "camcov_engine.js as this build writes it (build/wasm), or leave --engine out",
        engine.string(), kStamp));
  }
  const std::string page = buildPlaygroundHtml(
      readWholeFile(sceneFile), sceneFile.filename().string(), scene, time, poses, engineScript);
  records::writeFileAtomically(out, page);
}

}  // namespace camcov::reports::playground
