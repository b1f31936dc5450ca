#pragma once
// Whole-file read for the scene stage's loaders; failures are SceneErrors naming the file.
#include <filesystem>
#include <string>

#include "scene/scene_error.h"
#include "util/input_file.h"

namespace camcov::scene {

inline std::string readText(const std::filesystem::path& file) {
  if (const std::string why = whyNotReadable(file); !why.empty())
    throw SceneError(file.string(), "", "cannot read: " + why);
  return readInputFile(file);
}

}  // namespace camcov::scene
