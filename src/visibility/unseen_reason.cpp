#include "visibility/unseen_reason.h"

#include <cmath>
#include <limits>
#include <span>

#include "geometry/predicates.h"
#include "geometry/ring.h"

namespace camcov::visibility {
namespace {

using geometry::Vec2;

// Where the segment p → q first enters the object bounded by `ring` (or, for the boundary,
// leaves the room), as a fraction of p → q in [0, 1); infinity if it does not. Edge `skip`
// (the one q lies on) is left out, and so are crossings at q itself: a line of sight that ends
// on the edge is not hidden by it. A camera on an edge (docs/visibility.md: within the
// tolerance it is on it) is hidden by it when the sight line starts into the solid side.
double firstCrossing(std::span<const Vec2> ring, Vec2 p, Vec2 q, std::size_t skip,
                     bool isBoundary) {
  constexpr double kEnd = 1.0 - 1e-9;
  constexpr double kOnEdge = 1e-9;  // m, as the sweep's tolerance
  double first = std::numeric_limits<double>::infinity();
  const Vec2 d = q - p;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (i == skip) continue;
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    const Vec2 e = b - a;
    // On the edge but not at a vertex (at a vertex the other edge's test decides).
    if (geometry::distanceToSegment(p, a, b) <= kOnEdge && geometry::distance(p, a) > kOnEdge &&
        geometry::distance(p, b) > kOnEdge) {
      // Rings are counter-clockwise: an object's inside is left of its edges, the room's too.
      const double side = geometry::cross(e, d);
      if (isBoundary ? side < 0.0 : side > 0.0) first = 0.0;
      continue;
    }
    if (!geometry::segmentsIntersect(p, q, a, b)) continue;
    const double denominator = geometry::cross(d, e);
    // Parallel and touching: the sight line runs along the edge, which hides what is beyond.
    const double t =
        denominator == 0.0
            ? std::min(geometry::dot(a - p, d), geometry::dot(b - p, d)) / geometry::dot(d, d)
            : geometry::cross(a - p, e) / denominator;
    if (t >= 0.0 && t < kEnd) first = std::min(first, t);
  }
  return first;
}

}  // namespace

UnseenReason whyUnseen(const kinematics::World& world, const geometry::Pose& camera,
                       const scene::Lens& lens, const Segment& s) {
  constexpr std::size_t kNoEdge = std::numeric_limits<std::size_t>::max();
  const Vec2 p = camera.position();
  using Kind = ObjectRef::Kind;
  if (geometry::locate(world.boundary, p) == geometry::Containment::Outside) {
    return {UnseenKind::OutsideBoundary, {Kind::Boundary, 0}};
  }
  const auto inside = [&](const std::vector<geometry::Ring>& rings, Kind kind) -> ObjectRef {
    for (std::size_t i = 0; i < rings.size(); ++i) {
      if (geometry::locate(rings[i], p) == geometry::Containment::Inside) {
        return {kind, static_cast<std::uint32_t>(i)};
      }
    }
    return {};
  };
  for (const ObjectRef o :
       {inside(world.targets, Kind::Target), inside(world.obstacles, Kind::Obstacle)}) {
    if (o.kind != Kind::None) return {UnseenKind::InsideObject, o};
  }
  // Rings are counter-clockwise, so the free side of edge a → b is on its right.
  const geometry::Ring& target = world.targets.at(s.target);
  const Vec2 a = target[s.edge], b = target[(s.edge + 1) % target.size()];
  if (geometry::orientSign(a, b, p) >= 0) return {UnseenKind::BehindItsTarget, {}};
  const Vec2 q = (s.a + s.b) * 0.5;
  if (!lens.sees(q - p, camera.yaw)) return {UnseenKind::OutsideFieldOfView, {}};

  UnseenReason reason;
  double nearest = std::numeric_limits<double>::infinity();
  const auto consider = [&](std::span<const Vec2> ring, ObjectRef object, std::size_t skip) {
    const double t = firstCrossing(ring, p, q, skip, object.kind == Kind::Boundary);
    if (t < nearest) {
      nearest = t;
      reason = {UnseenKind::Blocked, object};
    }
  };
  consider(world.boundary, {Kind::Boundary, 0}, kNoEdge);
  for (std::size_t i = 0; i < world.targets.size(); ++i) {
    consider(world.targets[i], {Kind::Target, static_cast<std::uint32_t>(i)},
             i == s.target ? s.edge : kNoEdge);
  }
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    consider(world.obstacles[i], {Kind::Obstacle, static_cast<std::uint32_t>(i)}, kNoEdge);
  return reason;
}

const char* unseenPhrase(UnseenKind kind) {
  switch (kind) {
    case UnseenKind::OutsideBoundary:
      return "the camera is outside the boundary";
    case UnseenKind::InsideObject:
      return "the camera is inside {blocker}";
    case UnseenKind::BehindItsTarget:
      return "behind its own target (the edge faces away or is seen edge-on)";
    case UnseenKind::OutsideFieldOfView:
      return "outside the field of view";
    case UnseenKind::Blocked:
      return "blocked by {blocker}";
    case UnseenKind::InSight:
      break;
  }
  return "in sight, but at the sweep's tolerance (a grazing case)";
}

std::string describeUnseen(const kinematics::World& world, const UnseenReason& reason) {
  std::string blocker = "nothing";
  switch (reason.blocker.kind) {
    case ObjectRef::Kind::Boundary:
      blocker = "the boundary";
      break;
    case ObjectRef::Kind::Target:
      blocker = "target " + std::to_string(kinematics::targetId(world, reason.blocker.index));
      break;
    case ObjectRef::Kind::Obstacle:
      blocker = "obstacle " + std::to_string(kinematics::obstacleId(world, reason.blocker.index));
      break;
    case ObjectRef::Kind::None:
      break;
  }
  std::string text = unseenPhrase(reason.kind);
  if (const auto at = text.find("{blocker}"); at != std::string::npos) text.replace(at, 9, blocker);
  return text;
}

}  // namespace camcov::visibility
