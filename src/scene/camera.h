#pragma once
// What a camera is, in one place: where it starts, what it sees (its lens) and how it may move
// (paper section II: dynamics ṗ_j = u_j; Problem 2.2, constraint 3: ‖[ẋ ẏ]‖ ≤ v_j^max and
// |γ̇_j| ≤ γ̇_j^max). Visibility, reward, planners, controllers, the safety layer and the
// simulator read a camera only through these types, so a property added here (a lens's reach,
// say) needs no parallel array threaded through the stages.
#include <cstddef>
#include <limits>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "geometry/same_bits.h"
#include "geometry/vec2.h"
#include "scene/camera_set.h"

namespace camcov::scene {

inline constexpr double kUnlimitedRange = std::numeric_limits<double>::infinity();

// What a camera sees from its pose: the closed wedge within θ_j either side of its yaw, up to
// its sensing range r_j (our extension: the paper's cameras see without limit, so do ours
// unless a scene gives a range). Everything that decides what a camera sees — the sweep, the
// explanation of what it does not see, the planners' sampler — asks the lens.
struct Lens {
  // Implicit on purpose: a half-angle alone is the paper's camera.
  constexpr Lens(double halfFov = 0.0) : halfFov(halfFov) {}

  double halfFov;                  // θ_j, radians, in (0, π)
  double range = kUnlimitedRange;  // r_j, metres, > 0: nothing farther is seen
  // W_j, pixels across the field of view 2θ_j (our extension, for resolution-aware coverage);
  // 0: the camera has no image model. It changes what counts as covered, never what is seen.
  double imageWidth = 0.0;

  bool limited() const { return range < kUnlimitedRange; }
  bool hasImage() const { return imageWidth > 0.0; }
  // k_j = W_j / 2θ_j: an equidistant (f-θ) image spreads its pixels evenly over the angles of
  // the field of view (resolution_coverage.h says why this model and not the pinhole's).
  double pixelsPerRadian() const { return imageWidth / (2.0 * halfFov); }
  bool withinRange(double distance) const { return distance <= range; }
  // Whether a point at `offset` from a camera facing `yaw` is in view: in the wedge, in range.
  bool sees(geometry::Vec2 offset, double yaw) const;
  // The parameters [t0, t1] ⊆ [0, 1] of the points a + t (b − a) within range of `camera`
  // (a disc meets a segment in one piece); false if none. Unlimited: [0, 1].
  bool rangeOnSegment(geometry::Vec2 camera, geometry::Vec2 a, geometry::Vec2 b, double& t0,
                      double& t1) const;

  constexpr bool operator==(const Lens&) const = default;
};

// Bit-for-bit equality, for the caches keyed by a camera's lens (geometry/same_bits.h).
inline bool sameBits(const Lens& a, const Lens& b) {
  return geometry::sameBits(a.halfFov, b.halfFov) && geometry::sameBits(a.range, b.range) &&
         geometry::sameBits(a.imageWidth, b.imageWidth);
}

// What a scene asks of the images for a piece of target boundary to count as covered (our
// extension, the paper's future work on resolution): a pixel density ρ_min, pixels per metre of
// boundary, reached by some camera that sees it. `proportional`: a point seen at density ρ
// counts min(1, ρ/ρ_min) instead of all or nothing.
struct ResolutionRequirement {
  double minDensity = 0.0;  // ρ_min, pixels per metre, > 0
  bool proportional = false;
};

// What moves a camera: its velocity u_j = ṗ_j. Controllers produce it, the plan executor
// computes it, the safety layer and the simulator consume it.
struct CameraCommand {
  geometry::Vec2 velocity;       // [ẋ, ẏ], m/s (saturated to v_max)
  double angularVelocity = 0.0;  // γ̇, rad/s (saturated to γ̇_max)

  bool isFinite() const;
};

// How far a camera may move and turn in one time step dt.
struct StepLimits {
  double maxTranslation = 0.0;  // m per step: v_max · dt
  double maxRotation = 0.0;     // rad per step: γ̇_max · dt
};

struct CameraSpec {
  geometry::Pose initial;           // p_j(0); yaw γ in radians, wrapped to [-π, π]
  double maxVelocity = 0.0;         // v_j^max, m/s, > 0; also the speed the safety layer bounds
  double maxAngularVelocity = 0.0;  // γ̇_j^max, rad/s, > 0
  Lens lens;                        // the scene's θ unless the camera has its own

  // Constraint 3: the command scaled into ‖v‖ ≤ v_max and clamped to |γ̇| ≤ γ̇_max. A non-finite
  // component stops that part of the motion (the simulator records it as an event).
  CameraCommand saturate(CameraCommand u) const;
  StepLimits stepLimits(double dt) const { return {maxVelocity * dt, maxAngularVelocity * dt}; }
  // How long running `length` m and turning `turn` rad at once takes at full speed: the longer
  // of the two (section V-B's estimate for the assignment; obstacles ignored).
  double travelTime(double length, double turn) const;
  double travelTime(const geometry::Pose& from, const geometry::Pose& to) const;
};

// A camera as every output shows it (`camcov state`, the explorer's camera panel, Python's
// `Scene.cameras`), in the scene file's keys and units: x and y (m), then every key of the
// camera table (camera_keys.h) that the camera carries — angle (yaw, degrees), maxVelocity,
// maxAngularVelocity, cameraFoV (θ, degrees), a limited lens's sensingRange (m), an image
// model's imageWidth (pixels). A property added to the table is shown everywhere.
nlohmann::json describeCamera(const CameraSpec& camera);

// One Euler step of ṗ = u over dt, the yaw wrapped to [-π, π].
geometry::Pose moved(const geometry::Pose& pose, const CameraCommand& u, double dt);

}  // namespace camcov::scene
