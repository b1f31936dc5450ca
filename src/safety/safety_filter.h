#pragma once
// The safety layer between every controller and the simulator (our extension; the paper's
// constraints 1 and 2 of Problems 2.2/2.3 made hard instead of discouraged by eq. (9)).
//
// Each step it takes the commanded velocities (already saturated to v_max) and returns, per
// camera, the velocity closest to the command under which the camera keeps δ from every
// target, obstacle and camera over the coming step — a discrete-time control barrier
// function (Ames et al., "Control Barrier Functions: Theory and Applications", ECC 2019)
// whose barrier is each distance minus δ, posed as ORCA's small LP per camera (velocity_lp.h).
//
// Why this technique: the distance from a point to a segment is convex in the point, so its
// linearisation at the present position bounds it from below everywhere; an object vertex
// moving at most s m/s moves the segment's points at most s·τ (they are convex combinations
// of the vertices, or images under one rigid motion). Hence for a velocity u held over the
// step, d(τ) ≥ d + (n·u − s)·τ for all τ, a function linear in τ: a half-plane on u that
// makes d ≥ δ hold at both ends of the step holds it at every instant between — safety in
// continuous time, not only at the samples. ORCA's velocity obstacles or a time-to-collision
// filter would need the objects' future velocities; this needs only speed bounds, which the
// controller can estimate from the past (observed_speeds.h).
//
// Per camera, in order of preference:
//   1. keep δ + margin for the horizon (H ≥ dt) against objects at their observed speeds;
//   2. keep δ over the coming step — the weakest promise that still avoids contact — by the
//      contact accounting's precision where it can (step_contacts.h: a distance that only
//      touches δ is counted as a contact by a measurement that never undercounts), else
//      exactly;
//   3. none exists: the contact is unavoidable; take the velocity that violates the
//      constraints least (ORCA's fallback) and say why: "within-delta" (already closer than
//      δ), "outpaced" (one object alone closes faster than the camera can move away) or
//      "cornered" (each threat alone could be escaped, not all at once: the boundary,
//      other objects or cameras are in the way).
// Cameras are solved in index order; camera j honours the velocities already chosen for
// cameras i < j exactly and takes half of the closing allowed with cameras i > j, which then
// see j's velocity exactly (the reciprocal split of Wang, Ames, Egerstedt, "Safety Barrier
// Certificates for Collisions-Free Multirobot Systems", IEEE T-RO 2017). The boundary is a
// hard constraint (cameras stay inside B, 1 mm clear), never relaxed.
#include <span>
#include <string>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "params/parameters.h"
#include "safety/observed_speeds.h"
#include "safety/velocity_lp.h"
#include "scene/scene.h"

namespace camcov::safety {

enum class ContactReason { None, WithinDelta, Outpaced, Cornered };
// "within-delta", "outpaced", "cornered" ("" for None): the reason field of the records.
const char* reasonName(ContactReason reason);

struct Verdict {
  bool keepsDelta = true;  // some admissible velocity keeps δ over the coming step
  ContactReason reason = ContactReason::None;
  std::string detail;  // what the camera faced, in words and numbers, when !keepsDelta
};

class SafetyFilter {
 public:
  SafetyFilter(const scene::Scene& scene, const params::Parameters& params);

  // Observes the present (`world` at its time, the cameras' poses) and, when the layer is
  // enabled, replaces each velocity by the closest admissible one; disabled, it leaves them
  // as they are and only judges. Either way verdicts() then tells, per camera, whether δ
  // could be kept over the coming step.
  void apply(const kinematics::World& world, std::span<const geometry::Pose> cameras,
             std::span<geometry::Vec2> velocities);
  const std::vector<Verdict>& verdicts() const { return verdicts_; }

 private:
  // One half-plane on the camera's velocity and where it comes from: normal·u ≥ base +
  // share·(clearance − distance)/T, the clearance and T of the level being solved.
  struct Threat {
    enum class Source { Boundary, Target, Obstacle, Camera } source;
    std::size_t index = 0;  // which target, obstacle or camera
    geometry::Vec2 normal;  // unit, from the threat towards the camera
    double distance = 0.0;  // m now; negative: the camera is inside the object
    double base = 0.0;      // m/s: the object's speed bound, or n·u of an earlier camera
    double share = 1.0;     // of the closing allowed: ½ against a camera solved later
  };
  void collect(const kinematics::World& world, std::span<const geometry::Pose> cameras,
               std::span<const geometry::Vec2> velocities, std::size_t camera);
  void addObject(const geometry::Ring& ring, bool isTarget, std::size_t index,
                 geometry::Vec2 position, double reach);
  // Per threat, the half-plane of velocities that keep `clearance` over `T` seconds.
  std::vector<HalfPlane> planes(double clearance, double T) const;
  // Why no velocity keeps δ, from the half-planes of level 2 (`hard`, one per threat).
  Verdict explain(const kinematics::World& world, std::size_t camera, double maxSpeed,
                  std::span<const HalfPlane> hard) const;

  std::vector<double> maxSpeeds_;
  bool enabled_;
  double dt_, delta_, margin_, horizon_;
  ObservedSpeeds speeds_;
  std::vector<Threat> threats_;  // of the camera being solved; hard ones first
  std::size_t hardCount_ = 0;
  std::vector<Verdict> verdicts_;
};

}  // namespace camcov::safety
