#pragma once
// The visibility playground (`camcov playground SCENE -o page.html`): one offline HTML page
// holding the scene as its file says it, the cameras' poses, the engine compiled to
// WebAssembly (src/wasm, camcov_engine.js) and the page's script, which asks the engine for
// every picture. Works from file://, fetches nothing.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::reports::playground {

// The page for `scene` (loaded from `sceneText`, whose file is `fileName`) at `time`, with
// camera j at poses[j], running `engineScript`.
std::string buildPlaygroundHtml(std::string_view sceneText, const std::string& fileName,
                                const scene::Scene& scene, double time,
                                std::span<const geometry::Pose> poses,
                                std::string_view engineScript);

// Reads the scene (and the poses file, if given: one pose per camera) and the engine, writes
// the page atomically. InputError for a bad scene or poses, or an engine that is not there or
// not the one the page calls (its first line, the stamp of its interface).
void writePlayground(const std::filesystem::path& sceneFile, double time,
                     const std::optional<std::filesystem::path>& posesFile,
                     const std::filesystem::path& engine, const std::filesystem::path& out);

}  // namespace camcov::reports::playground
