#pragma once
// A list of camera poses given by a user, e.g. for `camcov inspect --cameras FILE`:
//   [{"x": 1.0, "y": -2.0, "yaw_deg": 90}, ...]
#include <filesystem>
#include <string_view>
#include <vector>

#include "geometry/vec2.h"

namespace camcov::scene {

// Throws SceneError (file, JSON path, problem) for anything but a list of 1 to 64 poses with
// finite x, y (m) and yaw_deg (degrees).
std::vector<geometry::Pose> loadCameraPoses(const std::filesystem::path& file);
std::vector<geometry::Pose> parseCameraPoses(std::string_view jsonText, const std::string& source);

}  // namespace camcov::scene
