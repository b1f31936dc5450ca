#pragma once
// Whole-file read for the scene stage's loaders; failures are SceneErrors naming the file.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "scene/scene_error.h"

namespace camcov::scene {

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(file.string(), "", "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(file.string(), "", "read error");
  return text.str();
}

}  // namespace camcov::scene
