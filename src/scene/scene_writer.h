#pragma once
// The scene file as camcov writes it (the generators, the importers): the one place that spells
// its keys and WKT forms, so every file written reads back as meant (scene_loader.h). Rings
// are written open, as the published files write them; numbers as the shortest text that reads
// back to the same double. Values are in the file's units: metres, seconds, m/s and rad/s,
// but degrees for a camera's yaw and field of view (the published format's).
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/vec2.h"
#include "scene/camera_keys.h"
#include "scene/scene.h"

namespace camcov::scene {

// A camera as a file gives it: its position and, for each row of the camera table
// (camera_keys.h), the value in the file's units (degrees for angles), written when given.
// Without one a camera takes the scene's value or none (its fallback).
struct CameraEntry {
  geometry::Vec2 position;
  std::array<std::optional<double>, kCameraKeys.size()> values;

  std::optional<double>& operator[](CameraKeyId id) { return values[index(id)]; }
  const std::optional<double>& operator[](CameraKeyId id) const { return values[index(id)]; }
};

// A camera with the keys every camera gives: where it starts, facing `yawDegrees`, and its
// limits v_max (m/s) and γ̇_max (rad/s).
CameraEntry cameraEntry(geometry::Vec2 position, double yawDegrees, double maxVelocity,
                        double maxAngularVelocity);

// What a written scene holds. Objects keep the in-memory form (MovingObject), whose units are
// the file's; a track's headings, if any, are written in degrees.
struct WrittenScene {
  std::string description;  // written when not empty
  std::string family;       // the family it was drawn from; written when not empty
  std::vector<geometry::Vec2> boundary;
  std::optional<Pitch> pitch;
  std::optional<double> duration;  // s: how long a run of it lasts (an imported window)
  double halfFovDegrees = 0.0;     // the scene's cameraFoV: θ, half the field of view
  std::optional<ResolutionRequirement> resolution;  // with every camera's imageWidth
  std::vector<MovingObject> targets;
  std::vector<MovingObject> obstacles;
  std::vector<CameraEntry> cameras;
};

// `v` rounded to 1/perUnit, so that a file prints short and exact and nothing drawn from it
// depends on the last bit of a maths library; `+ 0.0` turns −0 into 0, which prints as "0".
inline double roundTo(double v, double perUnit) {
  return std::round(v * perUnit) / perUnit + 0.0;
}
// An angle in radians as a file's degrees: they come back a bit off (a file's 30 reads back
// 29.999999999999996), so rounded to 1e-9°, far below anything a pose or lens can tell apart.
inline double writtenDegrees(double radians) {
  return roundTo(geometry::radToDeg(radians), 1e9);
}
// To the millimetre, as the generators and importers write coordinates.
inline double mm(double v) {
  return roundTo(v, 1e3);
}
inline geometry::Vec2 mm(geometry::Vec2 p) {
  return {mm(p.x), mm(p.y)};
}

// POLYGON((x1 y1,x2 y2,...)): a ring or a looping path, open; one point: a still path.
std::string wktPolygon(std::span<const geometry::Vec2> points);
// POINT(x y).
std::string wktPoint(geometry::Vec2 p);

nlohmann::json objectJson(const MovingObject& object);
nlohmann::json cameraJson(const CameraEntry& camera);
nlohmann::json sceneJson(const WrittenScene& file);

}  // namespace camcov::scene
