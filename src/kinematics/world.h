#pragma once
// The world at one instant t: every polygon in world coordinates, as the controller sees it.
// This is the paper's X(t) = (T(t), O(t)) plus the time-invariant boundary B (section II).
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/ring.h"
#include "scene/camera.h"

namespace camcov::kinematics {

// A field added here is also copied by simplifyObjects() (world_simplification.cpp), which
// copies a World field by field.
struct World {
  double time = 0.0;                      // t, seconds
  geometry::Ring boundary;                // B: simple, CCW, occludes
  std::vector<geometry::Ring> targets;    // T(t): CCW rings; their boundaries are covered
  std::vector<geometry::Ring> obstacles;  // O(t): CCW rings; occlude, are not covered
  // Which object of the scene each ring is: scene targets and obstacles in order, leaving out
  // those absent at t (recorded tracks). Without tracks, 0, 1, 2, ...
  std::vector<std::uint32_t> targetIds;
  std::vector<std::uint32_t> obstacleIds;
  // Importance weights (kinematics/edge_importance.h): targetEdgeWeights[i][e] of edge e of
  // targets[i], each in [0, 1], divided by the largest at t. Empty in a scene without weights:
  // every edge weighs 1.
  std::vector<std::vector<double>> targetEdgeWeights;
  // What a covered point asks of a camera's image (the scene's "resolution", ρ_min): the
  // reward counts only resolved boundary where its parameters say so (RewardParams::resolution).
  // None: any sight counts.
  std::optional<scene::ResolutionRequirement> resolution;
};

// The scene's index of world target i (world obstacle i): a World made by hand has no ids.
inline std::uint32_t targetId(const World& w, std::size_t i) {
  return w.targetIds.empty() ? static_cast<std::uint32_t>(i) : w.targetIds[i];
}
inline std::uint32_t obstacleId(const World& w, std::size_t i) {
  return w.obstacleIds.empty() ? static_cast<std::uint32_t>(i) : w.obstacleIds[i];
}

}  // namespace camcov::kinematics
