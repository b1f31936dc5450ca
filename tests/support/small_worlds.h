#pragma once
// Small worlds and scenes written by hand, shared by the tests of the upper stages.
#include <string>
#include <utility>
#include <vector>

#include "geometry/ring.h"
#include "kinematics/world.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace camcov::testing {

// The rectangle [x0, x1] x [y0, y1], counter-clockwise from (x0, y0).
inline geometry::Ring box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A world of the given rings, as kinematics would place them at some instant.
inline kinematics::World world(geometry::Ring boundary, std::vector<geometry::Ring> targets,
                               std::vector<geometry::Ring> obstacles = {}) {
  kinematics::World w;
  w.boundary = std::move(boundary);
  w.targets = std::move(targets);
  w.obstacles = std::move(obstacles);
  return w;
}

// A 40 m square room with a 1 m square target at the origin and a 2 x 1 obstacle at (6, 0).
inline kinematics::World roomWithTargetAndObstacle() {
  kinematics::World w;
  w.boundary = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};
  w.targets = {{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}};
  w.obstacles = {{{5, -0.5}, {7, -0.5}, {7, 0.5}, {5, 0.5}}};
  return w;
}

// A scene from JSON text (the loader validates it like any file).
// A lens of half-angle θ that sees no farther than `range` metres.
inline scene::Lens rangedLens(double halfFov, double range) {
  scene::Lens lens(halfFov);
  lens.range = range;
  return lens;
}

inline scene::Scene sceneFromJson(const std::string& json, const std::string& name = "test.json") {
  return scene::parseScene(json, name);
}

// One static square target, one camera looking away from it: the method has work to do.
inline const char* kOneTargetScene = R"js({
  "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
  "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))"}],
  "obstacles": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((5 0))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-6 -6)", "angle": 225, "maxVelocity": 2, "maxAngularVelocity": 1},
              {"pos": "POINT(6 6)", "angle": 0, "maxVelocity": 2, "maxAngularVelocity": 1}]})js";

}  // namespace camcov::testing
