#pragma once
// Why a camera does not see a piece of a target's boundary: the run explorer's answer when a
// user points at an edge nobody sees. The sweep (sweep.h) says *whether* camera j sees a
// segment of S; this says *why not*, in the order a person would check: the camera is outside
// the boundary or inside an object, the edge faces away from it (behind its own target), it
// lies outside the field of view (or beyond the camera's range), or the first object the line of
// sight hits. Decided at the segment's midpoint, which is enough because a segment of S is seen by
// camera j wholly or not at all. O(n) in the scene's vertices: for clicks and per-step
// explanations, not the sweep.
#include <cstdint>
#include <string>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "scene/camera.h"
#include "visibility/segment.h"

namespace camcov::visibility {

enum class UnseenKind : std::uint8_t {
  InSight,             // nothing found that hides it: the camera sees it (or the sweep's
                       // tolerance decided a grazing case the other way, docs/visibility.md)
  OutsideBoundary,     // the camera is outside the boundary B
  InsideObject,        // the camera is inside object `blocker`
  BehindItsTarget,     // the edge faces away from the camera (or is seen edge-on)
  OutsideFieldOfView,  // the midpoint lies outside the lens's view: the wedge [γ − θ, γ + θ]
                       // within its sensing range
  Blocked,             // the line of sight first hits `blocker`
};

// An object of the world: the boundary, target i or obstacle i.
struct ObjectRef {
  enum class Kind : std::uint8_t { None, Boundary, Target, Obstacle };
  Kind kind = Kind::None;
  std::uint32_t index = 0;

  bool operator==(const ObjectRef&) const = default;
};

struct UnseenReason {
  UnseenKind kind = UnseenKind::InSight;
  ObjectRef blocker;  // for InsideObject and Blocked
};

// The words for a reason, "{blocker}" standing for the blocker's name ("target 2"): one wording
// for the explorer (which fills the blocker in its page) and the playground.
const char* unseenPhrase(UnseenKind kind);
// The phrase with the blocker named as the scene numbers it (World ids, not ring indices).
std::string describeUnseen(const kinematics::World& world, const UnseenReason& reason);

// Why the camera at `camera` with `lens` does not see segment `s` of S(world): s.target and
// s.edge name the edge it lies on.
UnseenReason whyUnseen(const kinematics::World& world, const geometry::Pose& camera,
                       const scene::Lens& lens, const Segment& s);

}  // namespace camcov::visibility
