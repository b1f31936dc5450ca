#include "scene/scene.h"

namespace camcov::scene {

geometry::Ring initialPolygon(const MovingObject& object) {
  geometry::Ring out;
  geometry::placeRing(object.shape, 0.0, object.path.front(), out);
  return out;
}

}  // namespace camcov::scene
