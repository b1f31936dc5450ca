#pragma once
// Objects that pass through each other: a target through an obstacle, two targets, two
// obstacles. Allowed — recorded people walk through each other, and the importers say so —
// but worth a warning, since a target inside another object is covered or hidden by accident
// of the data, not of the cameras. `camcov validate` prints them and the report shows them
// under each scene.
//
// Sampled, not exact: every `step` seconds over [0, duration] (at most kMaxInstants instants),
// the first instant per pair. Two objects overlap when their interiors meet in more than a
// sliver (an area above 1e-9 of the larger one's); touching is not overlapping.
#include <string>
#include <vector>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::kinematics {

inline constexpr int kMaxInstants = 1000;

struct ObjectOverlap {
  std::string first, second;  // JSON paths: "targets[0]", "obstacles[2]"
  double time = 0.0;          // s, the first instant sampled at which they overlap
  geometry::Vec2 near;        // the centroid of the largest piece of their intersection
};

// Every pair of objects that overlaps at some sampled instant, by the first such instant.
std::vector<ObjectOverlap> findObjectOverlaps(const scene::Scene& scene, double duration,
                                              double step);

// "targets[0] and obstacles[1] pass through each other at t = 3.2 s near (1.00, 2.00)".
std::string describeOverlap(const ObjectOverlap& overlap);

}  // namespace camcov::kinematics
