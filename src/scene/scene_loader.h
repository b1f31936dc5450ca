#pragma once
// Reads and validates a scene file (SPEC section 2). Every problem is a SceneError naming the
// file, the JSON path and what is wrong; nothing is silently repaired.
#include <filesystem>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace camcov::scene {

Scene loadScene(const std::filesystem::path& file);
// `sourceName` is used in messages and, through its stem, as the scene's name.
Scene parseScene(std::string_view jsonText, const std::string& sourceName);

}  // namespace camcov::scene
