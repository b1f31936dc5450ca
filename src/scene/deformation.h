#pragma once
// The deformation extension's meaning: the local shape of an object at time t.
#include "geometry/ring.h"
#include "scene/scene.h"

namespace camcov::scene {

// Local (unrotated, untranslated) shape at time t, into `out`: the shape itself for objects
// without deformation, else the per-vertex linear interpolation through the keyframe cycle.
void localShapeAt(const MovingObject& object, double t, geometry::Ring& out);

}  // namespace camcov::scene
