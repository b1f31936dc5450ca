#pragma once
// The scene file as camcov writes it (the generators, the importers): the one place that spells
// its keys and WKT forms, so every file written reads back as meant (scene_loader.h). Rings
// are written open, as the published files write them; numbers as the shortest text that reads
// back to the same double. Values are in the file's units: metres, seconds, m/s and rad/s,
// but degrees for a camera's yaw and field of view (the published format's).
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::scene {

// A camera as a file gives it.
struct CameraEntry {
  geometry::Vec2 position;
  double yawDegrees = 0.0;
  double maxVelocity = 0.0;            // m/s
  double maxAngularVelocity = 0.0;     // rad/s
  std::optional<double> sensingRange;  // m; none: sees without limit
  std::optional<double> imageWidth;    // pixels across the field of view; none: no image model
};

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
