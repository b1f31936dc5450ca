#include "scene/scene_writer.h"

#include <fmt/format.h>

#include "geometry/vec2.h"

namespace camcov::scene {

std::string wktPolygon(std::span<const geometry::Vec2> points) {
  std::string out = "POLYGON((";
  for (std::size_t i = 0; i < points.size(); ++i)
    out += fmt::format("{}{} {}", i == 0 ? "" : ",", points[i].x, points[i].y);
  return out + "))";
}

std::string wktPoint(geometry::Vec2 p) {
  return fmt::format("POINT({} {})", p.x, p.y);
}

nlohmann::json objectJson(const MovingObject& object) {
  nlohmann::json j{{"shape", wktPolygon(object.shape)}};
  if (!object.color.empty()) j["color"] = object.color;
  // In the order of the ring written above (normalised, counter-clockwise), as the loader keeps
  // them.
  if (!object.edgeWeights.empty()) j["edgeWeights"] = object.edgeWeights;
  if (object.front) {
    j["frontWeight"] = object.front->weight;
    j["frontAngle"] = writtenDegrees(object.front->halfAngle);
  }
  if (object.track) {
    const Track& track = *object.track;
    nlohmann::json samples = nlohmann::json::array();
    for (std::size_t k = 0; k < track.times.size(); ++k) {
      nlohmann::json sample{track.times[k], track.positions[k].x, track.positions[k].y};
      if (!track.headings.empty()) sample.push_back(geometry::radToDeg(track.headings[k]));
      samples.push_back(std::move(sample));
    }
    j["track"] = {{"samples", std::move(samples)}};
    return j;
  }
  j["path"] = wktPolygon(object.path);
  if (object.path.size() > 1) j["velocity"] = object.velocity;
  if (object.angularVelocity != 0.0) j["angularVelocity"] = object.angularVelocity;
  if (object.deformation) {
    nlohmann::json keyframes = nlohmann::json::array();
    for (const DeformationKeyframe& k : object.deformation->keyframes)
      keyframes.push_back({{"time", k.time}, {"shape", wktPolygon(k.shape)}});
    j["deformation"] = {{"period", object.deformation->period},
                        {"keyframes", std::move(keyframes)}};
  }
  return j;
}

CameraEntry cameraEntry(geometry::Vec2 position, double yawDegrees, double maxVelocity,
                        double maxAngularVelocity) {
  CameraEntry entry{position, {}};
  entry[CameraKeyId::angle] = yawDegrees;
  entry[CameraKeyId::maxVelocity] = maxVelocity;
  entry[CameraKeyId::maxAngularVelocity] = maxAngularVelocity;
  return entry;
}

nlohmann::json cameraJson(const CameraEntry& camera) {
  nlohmann::json j{{kCameraPositionKey, wktPoint(camera.position)}};
  for (const CameraKey& row : kCameraKeys)
    if (camera[row.id]) j[row.name] = *camera[row.id];
  return j;
}

nlohmann::json sceneJson(const WrittenScene& file) {
  nlohmann::json scene;
  if (!file.description.empty()) scene["description"] = file.description;
  if (!file.family.empty()) scene["family"] = file.family;
  scene["boundary"] = wktPolygon(file.boundary);
  if (file.pitch) scene["pitch"] = {{"length", file.pitch->length}, {"width", file.pitch->width}};
  if (file.duration) scene["duration"] = *file.duration;
  scene["cameraFoV"] = file.halfFovDegrees;
  if (file.resolution) {
    scene["resolution"] = {{"minDensity", file.resolution->minDensity}};
    if (file.resolution->proportional) scene["resolution"]["proportional"] = true;
  }
  for (const char* key : {"targets", "obstacles", "cameras"})
    scene[key] = nlohmann::json::array();
  for (const MovingObject& o : file.targets)
    scene["targets"].push_back(objectJson(o));
  for (const MovingObject& o : file.obstacles)
    scene["obstacles"].push_back(objectJson(o));
  for (const CameraEntry& c : file.cameras)
    scene["cameras"].push_back(cameraJson(c));
  return scene;
}

}  // namespace camcov::scene
