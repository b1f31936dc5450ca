#pragma once
// The velocity problem of one camera for one step: of the velocities u with ‖u‖ ≤ v_max that
// satisfy a set of half-planes a·u ≥ b, the one closest to the commanded velocity.
//
// Solved exactly by the incremental two-dimensional algorithm that ORCA uses (van den Berg,
// Guy, Lin, Manocha, "Reciprocal n-Body Collision Avoidance", ISRR 2009, section V-B, and
// its RVO2 library): add the half-planes one by one; while the current optimum satisfies the
// next one it stays, otherwise the new optimum lies on that half-plane's line, a problem in
// one variable. Correct because the objective ‖u − desired‖² is strictly convex. Deterministic:
// the constraints are taken in the order given (no random shuffle), O(m²) for m half-planes.
#include <optional>
#include <span>

#include "geometry/vec2.h"

namespace camcov::safety {

// {u : normal·u ≥ offset}; normal has unit length.
struct HalfPlane {
  geometry::Vec2 normal;
  double offset = 0.0;
};

// The point of {‖u‖ ≤ maxSpeed} ∩ every half-plane closest to `desired`, or nothing when that
// set is empty (up to 1e-12 m/s).
std::optional<geometry::Vec2> closestAdmissibleVelocity(std::span<const HalfPlane> constraints,
                                                        double maxSpeed, geometry::Vec2 desired);

struct LeastViolation {
  geometry::Vec2 velocity;
  double violation = 0.0;  // max over the soft half-planes of offset − normal·u, ≥ 0
};

// When no velocity satisfies everything: the first `hardCount` half-planes are kept exactly
// (they must admit u = 0), the others are relaxed by the smallest common amount s that makes
// the set non-empty, and of what remains the velocity closest to `desired` is returned. This
// is ORCA's fallback (minimise the largest violation), found here by bisection on s, which
// reuses closestAdmissibleVelocity and is only run in the rare infeasible steps.
LeastViolation leastViolatingVelocity(std::span<const HalfPlane> constraints, std::size_t hardCount,
                                      double maxSpeed, geometry::Vec2 desired);

}  // namespace camcov::safety
