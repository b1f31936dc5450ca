#include "scene/scene.h"

#include <algorithm>

namespace camcov::scene {

geometry::Ring initialPolygon(const MovingObject& object) {
  geometry::Ring out;
  geometry::placeRing(object.shape, 0.0, object.path.front(), out);
  return out;
}

bool Scene::hasPresenceWindows() const {
  const auto tracked = [](const MovingObject& o) { return o.track.has_value(); };
  return std::any_of(targets.begin(), targets.end(), tracked) ||
         std::any_of(obstacles.begin(), obstacles.end(), tracked);
}

bool Scene::isWeighted() const {
  return std::any_of(targets.begin(), targets.end(),
                     [](const MovingObject& o) { return o.isWeighted(); });
}

bool Scene::holdsStill() const {
  const auto isStatic = [](const MovingObject& o) { return o.isStatic(); };
  return std::all_of(targets.begin(), targets.end(), isStatic) &&
         std::all_of(obstacles.begin(), obstacles.end(), isStatic);
}

std::vector<Lens> lenses(const Scene& scene) {
  std::vector<Lens> out;
  for (const CameraSpec& camera : scene.cameras)
    out.push_back(camera.lens);
  return out;
}

}  // namespace camcov::scene
