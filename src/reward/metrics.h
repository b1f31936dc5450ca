#pragma once
// The terms of the reward (paper section IV-A) as pure functions of one instant:
// vis(S) eq. (2), coverage eq. (3), utilization eq. (5), repulsion eq. (6)-(7), reward eq. (8).
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "params/parameters.h"
#include "visibility/segment.h"

namespace camcov::reward {

struct RewardTerms {
  double coverage = 0.0;     // eq. (3), in [0, 1]
  double utilization = 0.0;  // eq. (5), in [0, 1]
  double repulsion = 0.0;    // eq. (6), >= 0
  double reward = 0.0;       // eq. (8): λ1·coverage + λ2·utilization − λ3·repulsion
};

// vis(S), eq. (2): total length of segments some camera sees.
double visibleLength(std::span<const visibility::Segment> segments);
// length(∂T): sum of the targets' perimeters.
double targetPerimeter(const kinematics::World& world);
// Coverage, eq. (3). 0 when the targets have no boundary length.
double coverage(std::span<const visibility::Segment> segments, double perimeter);
// Utilization, eq. (5): mean over cameras of the angle ∠ s¹ p_j s² of every segment camera j
// sees, over its field of view 2θ_j (halfFovs[j]).
double utilization(std::span<const visibility::Segment> segments,
                   std::span<const geometry::Pose> cameras, std::span<const double> halfFovs);
// Length of the target boundary camera j sees (what it contributes before overlaps).
double visibleLengthOf(std::span<const visibility::Segment> segments, unsigned camera);

// invdist(a, b), eq. (7): 1/dist² closer than d2, else 0. A zero distance (a camera on or in
// an object) is taken as kMinDistance so the reward stays finite and still strongly negative.
inline constexpr double kMinDistance = 1e-3;
double invdist(double distance, double d2);
// Repulsion, eq. (6): every camera against every target and obstacle, and camera pairs.
double repulsion(const kinematics::World& world, std::span<const geometry::Pose> cameras,
                 double d2);
// Reward, eq. (8).
double combine(const params::RewardParams& p, double coverage, double utilization,
               double repulsion);

}  // namespace camcov::reward
