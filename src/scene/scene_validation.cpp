#include "scene/scene_validation.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "scene/deformation.h"
#include "util/readable_number.h"

namespace camcov::scene {

std::string describeRingDefect(const geometry::Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (ring[i] == ring[(i + 1) % n]) {
      return "zero-length edge: vertices " + std::to_string(i) + " and " +
             std::to_string((i + 1) % n) + " coincide";
    }
  }
  const bool collinear = std::all_of(ring.begin(), ring.end(), [&](geometry::Vec2 v) {
    return geometry::orient(ring[0], ring[1], v) == 0.0;
  });
  if (collinear) return "all vertices are collinear (zero area)";
  if (const auto pair = geometry::findSelfIntersection(ring); pair.found()) {
    return "polygon intersects itself (edges " + std::to_string(pair.first) + " and " +
           std::to_string(pair.second) + ")";
  }
  return {};
}

std::string describeDeformationDefect(const MovingObject& object) {
  constexpr int kSamplesPerInterval = 16;
  const Deformation& d = *object.deformation;
  geometry::Ring shape;
  double t0 = 0.0;
  for (std::size_t k = 0; k <= d.keyframes.size(); ++k) {
    const double t1 = k < d.keyframes.size() ? d.keyframes[k].time : d.period;
    for (int s = 1; s < kSamplesPerInterval; ++s) {
      const double t = t0 + (t1 - t0) * s / kSamplesPerInterval;
      localShapeAt(object, t, shape);
      if (std::string problem = describeRingDefect(shape); !problem.empty()) {
        return fmt::format("interpolated shape at t = {} s is not simple: {}", roundedNumber(t),
                           problem);
      }
    }
    t0 = t1;
  }
  return {};
}

namespace {

std::string objectPath(const char* kind, std::size_t i) {
  return std::string(kind) + "[" + std::to_string(i) + "]";
}

}  // namespace

std::vector<PlacementDefect> findPlacementDefects(const Scene& scene) {
  std::vector<PlacementDefect> defects;
  struct Placed {
    std::string path;
    geometry::Ring polygon;
    bool presentAtZero = true;  // a recorded object may enter later
  };
  std::vector<Placed> placed;
  for (std::size_t i = 0; i < scene.targets.size(); ++i) {
    placed.push_back({objectPath("targets", i), initialPolygon(scene.targets[i]),
                      scene.targets[i].presentAt(0.0)});
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    placed.push_back({objectPath("obstacles", i), initialPolygon(scene.obstacles[i]),
                      scene.obstacles[i].presentAt(0.0)});
  }
  // A recorded track: every sample inside the boundary (the importers choose the boundary
  // around them). Recorded people are not checked against walls or one another: they are
  // where they were, and walls occlude but do not stop them.
  // (Per object, its first sample outside.)
  for (const auto& [kind, objects] :
       {std::pair{"targets", &scene.targets}, std::pair{"obstacles", &scene.obstacles}}) {
    for (std::size_t i = 0; i < objects->size(); ++i) {
      if (!(*objects)[i].track) continue;
      const Track& track = *(*objects)[i].track;
      for (std::size_t k = 0; k < track.times.size(); ++k) {
        if (geometry::locate(scene.boundary, track.positions[k]) ==
            geometry::Containment::Outside) {
          defects.push_back(
              {objectPath(kind, i) + ".track.samples[" + std::to_string(k) + "]",
               fmt::format("at t = {} s the position lies outside the boundary", track.times[k])});
          break;
        }
      }
    }
  }
  for (const auto& object : placed) {
    if (!object.presentAtZero) continue;
    for (std::size_t v = 0; v < object.polygon.size(); ++v) {
      if (geometry::locate(scene.boundary, object.polygon[v]) == geometry::Containment::Outside) {
        defects.push_back({object.path + ".shape",
                           "at t = 0 vertex " + std::to_string(v) + " lies outside the boundary"});
        break;
      }
    }
  }
  for (std::size_t c = 0; c < scene.cameras.size(); ++c) {
    const geometry::Vec2 p = scene.cameras[c].initial.position();
    const std::string path = objectPath("cameras", c) + ".pos";
    if (geometry::locate(scene.boundary, p) == geometry::Containment::Outside) {
      defects.push_back({path, "camera lies outside the boundary"});
      continue;
    }
    for (const auto& object : placed) {
      if (object.presentAtZero &&
          geometry::locate(object.polygon, p) == geometry::Containment::Inside) {
        defects.push_back({path, "camera lies inside " + object.path + " at t = 0"});
        break;
      }
    }
  }
  return defects;
}

}  // namespace camcov::scene
