#pragma once
// The run explorer: one offline HTML file that replays recorded runs of one scene
// side by side in the browser — a timeline with play/pause, step, slider, the coverage and
// utilization curves and the events; the world at each step as the frames draw it; details of
// any edge (length, visibleBy, why each other camera does not see it) or camera (pose, limits,
// what it sees, nearest object and camera). Data: explorer_data.h; script: explorer.js.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "records/run_record.h"
#include "scene/scene.h"

namespace camcov::reports::explorer {

// The page; a pure function of the runs and the scene. `playgroundUrl`, if not empty: a
// playground page of the scene (camcov playground), which each step links to at its instant
// and poses.
std::string buildExplorerHtml(std::span<const records::RunRecord> runs, const scene::Scene& scene,
                              const std::string& playgroundUrl = {});

// Reads the run files, loads the scene the first names (or `sceneFile` if given: the file has
// moved), and writes the page to `out` atomically. InputError for runs of different scenes or
// a missing scene file.
// `playgroundPage`, if given, is linked by a URL relative to the page.
void writeExplorer(const std::vector<std::filesystem::path>& runFiles,
                   const std::filesystem::path& out, const std::filesystem::path& sceneFile = {},
                   const std::filesystem::path& playgroundPage = {});

}  // namespace camcov::reports::explorer
