#include "scene/scene.h"

namespace camcov::scene {

geometry::Ring initialPolygon(const MovingObject& object) {
  geometry::Ring out;
  geometry::placeRing(object.shape, 0.0, object.path.front(), out);
  return out;
}

std::vector<double> halfFovs(const Scene& scene) {
  std::vector<double> out;
  for (const CameraSpec& camera : scene.cameras)
    out.push_back(camera.halfFov);
  return out;
}

}  // namespace camcov::scene
