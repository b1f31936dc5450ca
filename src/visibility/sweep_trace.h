#pragma once
// What the polar sweep (Algorithm 1, lines 7–15, paper section IV-B) did for one camera, event
// by event: which events it visited in which order, and which edge was in front after each
// ray. Plain data for looking at a corner case (`camcov inspect --camera J -o debug.svg`);
// Sweep::trace fills it by running the same sweep as segments() with an observer attached.
#include <cstdint>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "scene/camera.h"
#include "visibility/occluders.h"

namespace camcov::visibility {

// The closest edge on a ray.
struct TracedEdge {
  enum class Kind : std::uint8_t {
    None,   // nothing on the ray (only a camera outside every ring)
    Wedge,  // the camera stands on a ring: its solid side, blocked at distance zero
    Edge,   // a piece of a ring's edge
  };
  Kind kind = Kind::None;
  // For an Edge: the Occluders' piece id, which tells edges apart in a drawing; the ring it
  // belongs to (owner indexes World::obstacles or World::targets); the ring's edge from its
  // vertex `edge` to the next, of which the piece is all or, where another ring crosses it,
  // a part; and the piece's endpoints in the ring's direction. Where edges of several rings
  // lie on each other (twins, docs/visibility.md), the one the sweep keeps for all of them.
  std::uint32_t piece = 0;
  RingKind ring = RingKind::Boundary;
  std::uint32_t owner = 0;
  std::uint32_t edge = 0;
  geometry::Vec2 a, b;
};

struct TracedEvent {
  enum class Kind : std::uint8_t { Vertex, WedgeStart, WedgeEnd, FovEnter, FovLeave };
  Kind kind = Kind::Vertex;
  // Events with the same ray number lie exactly on one ray from the camera and are applied
  // as one batch (removals, then insertions), so they share frontAfter.
  std::uint32_t ray = 0;
  // The vertex; for a field-of-view ray, hitAfter.
  geometry::Vec2 point;
  double angle = 0.0;  // polar angle of the event's direction from the camera, in [0, 2π)
  // For a Vertex: how many of its two edges the event inserts into and removes from the
  // active edges (a vertex where the ring just passes by removes one and inserts one).
  std::uint8_t inserted = 0, removed = 0;
  TracedEdge frontAfter;    // closest on the rays just counter-clockwise of this one
  bool inFovAfter = false;  // those rays are in the field of view
  geometry::Vec2 hitAfter;  // where this event's ray meets frontAfter; the camera if no edge
};

struct SweepTrace {
  geometry::Pose camera;
  scene::Lens lens;  // θ, radians
  // The camera sees nothing (strictly inside an object or outside the boundary): no events.
  bool blind = false;
  // Before the first event: on the ray just below the +x axis, where the sweep starts.
  TracedEdge frontBefore;
  bool inFovBefore = false;
  std::vector<TracedEvent> events;  // in the order the sweep visits them
  geometry::Ring fieldOfView;       // as Sweep::fieldOfViewPolygon writes it
};

}  // namespace camcov::visibility
