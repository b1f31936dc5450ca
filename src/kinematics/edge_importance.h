#pragma once
// How much each edge of a target counts in coverage at one instant (our extension, the paper's
// future work in section VII: "regions of varying importance assigned to the target
// boundaries, for example, to prioritize the front of a football player"). A target's edge
// weighs its scene weight (scene::MovingObject::edgeWeights, 1 without), times frontWeight
// while the edge is in front: its outward normal within the front's half-angle of the target's
// direction of motion. That direction is told from where the target is and where it was —
// never where it will be — so a controller could know it.
#include <optional>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::kinematics {

// The direction of motion at t: reference(t) − reference(t − δ) for the first look-back δ of
// 0.5 s, 1 s, 2 s and 4 s (cut at `since`, when the target appeared) over which the target
// moved at least kMinFrontMove; none when it stood that long, or has only just appeared.
inline constexpr double kFrontWindow = 0.5;    // s, the first look-back
inline constexpr double kFrontLookBack = 4.0;  // s, the last
inline constexpr double kMinFrontMove = 0.05;  // m: less is a person shifting on the spot
template <class ReferenceAt>
std::optional<geometry::Vec2> recentMotion(ReferenceAt referenceAt, double t, double since) {
  const geometry::Vec2 now = referenceAt(t);
  for (double delta = kFrontWindow; delta <= kFrontLookBack; delta *= 2.0) {
    const double from = std::max(t - delta, since);
    if (from >= t) return std::nullopt;
    const geometry::Vec2 moved = now - referenceAt(from);
    if (geometry::norm(moved) >= kMinFrontMove) return moved;
    if (from == since) return std::nullopt;
  }
  return std::nullopt;
}

// Edge i of `placed` (the target's ring at t, counter-clockwise) is in front: its outward
// normal lies within halfAngle of `motion`. A zero-length edge has no normal: never.
bool inFront(const geometry::Ring& placed, std::size_t i, geometry::Vec2 motion, double halfAngle);

// The weights of the edges of `placed` (target `object` at t, moving along `motion` if known)
// into `out`, as the scene gives them.
void edgeWeightsAt(const scene::MovingObject& object, const geometry::Ring& placed,
                   const std::optional<geometry::Vec2>& motion, std::vector<double>& out);

// Divides every weight by the largest (if any is above 0): each is then at most 1, the largest
// exactly 1, so a weighted length is at most the length and the weighted perimeter at least
// the heaviest edge's — coverage, a ratio of weighted lengths, is the same, its sums stay in
// the range of plain ones, and their rounding (reward/fixed_point_sum.h) stays far below
// anything coverage can tell apart, however small the weights.
void normalizeWeights(std::vector<std::vector<double>>& weights);

}  // namespace camcov::kinematics
