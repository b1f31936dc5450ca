#include "scene/camera_poses_file.h"

#include <fmt/format.h>
#include <cmath>
#include <nlohmann/json.hpp>

#include "geometry/ring.h"
#include "scene/read_text.h"
#include "scene/scene_error.h"
#include "scene/scene_validation.h"
#include "util/readable_number.h"
#include "util/strict_json.h"

namespace camcov::scene {

std::vector<geometry::Pose> parseCameraPoses(std::string_view jsonText, const std::string& source) {
  nlohmann::json j;
  try {
    j = parseStrictJson(jsonText);
  } catch (const nlohmann::json::exception& e) {
    throw SceneError(source, "", std::string("invalid JSON: ") + e.what());
  } catch (const DuplicateJsonKey& e) {
    throw SceneError(source, "", e.what());
  }
  if (!j.is_array()) throw SceneError(source, "", "expected a list of {x, y, yaw_deg} objects");
  if (j.empty() || j.size() > kMaxCameras) {
    throw SceneError(source, "",
                     fmt::format("expected 1 to {} poses, found {}", kMaxCameras, j.size()));
  }
  std::vector<geometry::Pose> poses;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string path = fmt::format("[{}]", i);
    const auto& item = j[i];
    if (!item.is_object()) throw SceneError(source, path, "expected an object");
    for (const auto& [key, unused] : item.items()) {
      if (key != "x" && key != "y" && key != "yaw_deg") {
        throw SceneError(source, path + "." + key, "unknown key (allowed: x, y, yaw_deg)");
      }
    }
    double values[3];
    const char* keys[3] = {"x", "y", "yaw_deg"};
    for (int k = 0; k < 3; ++k) {
      const std::string keyPath = path + "." + keys[k];
      if (!item.contains(keys[k])) throw SceneError(source, keyPath, "missing required key");
      if (!item[keys[k]].is_number()) throw SceneError(source, keyPath, "expected a number");
      values[k] = item[keys[k]].get<double>();
      if (!std::isfinite(values[k])) throw SceneError(source, keyPath, "number is not finite");
      const double limit = k < 2 ? kMaxCoordinate : kMaxYawDegrees;
      if (std::abs(values[k]) > limit) {
        throw SceneError(source, keyPath,
                         readableNumber(values[k]) + " lies beyond ±" + readableNumber(limit));
      }
    }
    poses.push_back({values[0], values[1], geometry::wrapAngle(geometry::degToRad(values[2]))});
  }
  return poses;
}

std::vector<geometry::Pose> loadCameraPoses(const std::filesystem::path& file) {
  return parseCameraPoses(readText(file), file.string());
}

std::vector<geometry::Pose> loadCameraPosesFor(const std::filesystem::path& file,
                                               const Scene& scene) {
  return parseCameraPosesFor(readText(file), file.string(), scene);
}

std::vector<geometry::Pose> parseCameraPosesFor(std::string_view jsonText,
                                                const std::string& source, const Scene& scene) {
  std::vector<geometry::Pose> poses = parseCameraPoses(jsonText, source);
  if (poses.size() > scene.cameras.size()) {
    throw SceneError(source, "",
                     fmt::format("{} poses, but the scene has {} cameras (pose j is camera j, "
                                 "with its field of view)",
                                 poses.size(), scene.cameras.size()));
  }
  for (std::size_t j = 0; j < poses.size(); ++j) {
    if (geometry::locate(scene.boundary, poses[j].position()) == geometry::Containment::Outside) {
      throw SceneError(
          source, fmt::format("[{}]", j),
          fmt::format("({:g} {:g}) lies outside the scene's boundary", poses[j].x, poses[j].y));
    }
  }
  return poses;
}

std::vector<geometry::Pose> initialPoses(const Scene& scene) {
  std::vector<geometry::Pose> poses;
  for (const CameraSpec& camera : scene.cameras)
    poses.push_back(camera.initial);
  return poses;
}

}  // namespace camcov::scene
