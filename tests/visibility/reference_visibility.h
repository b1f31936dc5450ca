#pragma once
// The slow, obviously correct visibility the sweep is tested against. It shares no code with
// the sweep but Vec2's arithmetic: no Occluders, no exact predicates, no ring helpers, no
// sorting of events. Angles come from atan2, insideness from a winding number.
//
// Per camera and target edge E(t) = A + t(B − A), t ∈ [0, 1], it starts from the whole edge
// and subtracts parameter intervals, each the solution of a few linear inequalities in t:
//  - the directions outside the field of view,
//  - the directions blocked at the camera when it stands on an edge or a vertex (the solid
//    side of that ring around it),
//  - the shadow of every other edge F: directions strictly inside F's angular span at points
//    strictly beyond F's line. O(n) per edge, O(n²) per camera.
// It applies the same conventions as the sweep (docs/visibility.md), stated independently.
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"

namespace camcov::visibility::reference {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};
using IntervalSet = std::vector<Interval>;  // disjoint, sorted

// The tolerance ε of the conventions: 1e-12 times the World's bounding-box side.
double tolerance(const kinematics::World& world);

// Visible parameter intervals of every target edge: result[target][edge]. A camera with
// halfFov ≥ π sees all around (used for omnidirectional viewpoints).
std::vector<std::vector<IntervalSet>> visibleIntervals(const kinematics::World& world,
                                                       geometry::Vec2 p, double yaw,
                                                       double halfFov);

// Area of the region seen from p (omnidirectional), by angular decomposition: between two
// consecutive vertex directions the nearest edge along the middle ray is seen throughout.
double visibleArea(const kinematics::World& world, geometry::Vec2 p);

// Can p see q? False if the open segment crosses an edge by more than `tol` (a distance) at
// both of its ends and both of the edge's, or if its midpoint is farther than `tol` inside an
// object or outside the boundary.
bool clearLine(const kinematics::World& world, geometry::Vec2 p, geometry::Vec2 q, double tol);

}  // namespace camcov::visibility::reference
