#pragma once
// Reads and validates a scene file (SPEC section 2). Every problem is a SceneError naming the
// file, the JSON path and what is wrong; nothing is silently repaired.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace camcov::scene {

Scene loadScene(const std::filesystem::path& file);

// A scene with the fingerprint (FNV-1a) of its file's bytes: a changed file makes new jobs
// in a batch, and a replay or a report can tell it is no longer the file a run was made from.
struct SceneFile {
  Scene scene;
  std::uint64_t hash = 0;
};
SceneFile loadSceneFile(const std::filesystem::path& file);
// The hash loadSceneFile gives `file`, from its bytes alone (nothing parsed): whether a file
// read earlier still holds the same bytes, for a fraction of a reading's cost.
std::uint64_t sceneFileHash(const std::filesystem::path& file);
// `sourceName` is used in messages and, through its stem, as the scene's name.
Scene parseScene(std::string_view jsonText, const std::string& sourceName);

}  // namespace camcov::scene
