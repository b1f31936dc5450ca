#pragma once
// A list of camera poses given by a user, e.g. for `camcov inspect --cameras FILE`:
//   [{"x": 1.0, "y": -2.0, "yaw_deg": 90}, ...]
#include <filesystem>
#include <string_view>
#include <vector>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::scene {

// Throws SceneError (file, JSON path, problem) for anything but a list of 1 to kMaxCameras poses
// with x, y within the scene format's ±1e9 m and yaw_deg within ±1e6 degrees, each key once.
std::vector<geometry::Pose> loadCameraPoses(const std::filesystem::path& file);
std::vector<geometry::Pose> parseCameraPoses(std::string_view jsonText, const std::string& source);

// The poses of `file` for the cameras of `scene` (pose j is camera j, with its field of view):
// at most one per camera, each inside the scene's boundary (on it is allowed), as the scene
// file's own cameras must be.
std::vector<geometry::Pose> loadCameraPosesFor(const std::filesystem::path& file,
                                               const Scene& scene);
std::vector<geometry::Pose> parseCameraPosesFor(std::string_view jsonText,
                                                const std::string& source, const Scene& scene);

// Where the scene's cameras start, camera j first: the team when no poses are given.
std::vector<geometry::Pose> initialPoses(const Scene& scene);

}  // namespace camcov::scene
