#pragma once
// The "triple sample" of Algorithm 2 (paper section V-A, lines 3, 6, 7, 8), also the motion
// planner's visibility sampler (section V-C):
//   q1 uniform on target-boundary segments (by length),
//   the omnidirectional visibility polygon of q1,
//   q2 uniform by area inside it among valid states,
//   a yaw uniform among those that keep q1 in the field of view.
#include <optional>
#include <span>
#include <vector>

#include "geometry/ring.h"
#include "planners/state_validity.h"
#include "reward/reward_model.h"
#include "scene/camera.h"
#include "util/random.h"
#include "visibility/segment.h"

namespace camcov::planners {

// A point uniform by length on the segments; nullopt if their total length is zero.
std::optional<geometry::Vec2> samplePointOnSegments(std::span<const visibility::Segment> segments,
                                                    Random& random);
// A point uniform by length on the edges of the rings.
std::optional<geometry::Vec2> samplePointOnRings(std::span<const geometry::Ring> rings,
                                                 Random& random);
// γ uniform in [φ − θ, φ + θ], φ the direction from q2 to q1: q1 stays in view.
double sampleYawSeeing(geometry::Vec2 q2, geometry::Vec2 q1, double halfFov, Random& random);

// Uniform sampling by area inside a visibility polygon, which is star-shaped from its
// viewpoint: the fan of triangles (viewpoint, v_i, v_i+1) tiles it.
class PolygonSampler {
 public:
  void reset(const geometry::Ring& polygon, geometry::Vec2 viewpoint);
  double area() const { return cumulativeArea_.empty() ? 0.0 : cumulativeArea_.back(); }
  // nullopt when no valid point was found in `attempts` tries (or the polygon is empty).
  std::optional<geometry::Vec2> sample(Random& random, const StateValidity& validity,
                                       int attempts) const;

 private:
  std::vector<geometry::Vec2> triangles_;  // 3 per triangle
  std::vector<double> cumulativeArea_;
};

// One whole triple sample: a valid pose that sees q1, or nullopt.
class VisibilitySampler {
 public:
  static constexpr int kAttemptsPerSample = 20;

  // Prepares the polygon of q1 at the model's current instant.
  bool focus(reward::RewardModel& model, geometry::Vec2 q1);
  // Algorithm 2's line 3, then focus: q1 uniform on what the model's last evaluation left
  // unseen (all of ∂T seen: anywhere on it). False if there is no q1 or its polygon is empty.
  bool focusOnUnseen(reward::RewardModel& model, Random& random);
  std::optional<geometry::Pose> sample(Random& random, const StateValidity& validity,
                                       const scene::Lens& lens) const;
  geometry::Vec2 q1() const { return q1_; }

 private:
  geometry::Vec2 q1_;
  std::vector<visibility::Segment> unseen_;  // focusOnUnseen's buffer
  geometry::Ring polygon_;
  PolygonSampler area_;
};

}  // namespace camcov::planners
