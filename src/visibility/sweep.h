#pragma once
// Visibility of the targets' boundaries from cameras, and visibility polygons — the polar
// sweep of paper section IV-B (Algorithm 1), one code path for both.
//
// Usage, per instant t:
//   Occluders occluders(world);            // Algorithm 1 line 1, shared by all queries
//   sweep.segments(occluders, poses, thetas, s);     // S and visibleBy (lines 2–18)
//   sweep.visibilityPolygon(occluders, q1, polygon); // Algorithm 2 line 6
// A Sweep is a workspace: it keeps every buffer between calls, so after the first few calls
// it allocates nothing (as long as the caller reuses its output vectors too). One Sweep per
// thread; an Occluders may be shared by threads once built.
//
// Visibility: a camera at p with yaw γ and half-angle θ sees a point q if q lies in the closed
// wedge [γ − θ, γ + θ] around p, within the lens's sensing range r (|q − p| ≤ r; unlimited
// unless a scene gives one: scene/camera.h), and the open segment from p to q crosses no edge of
// the boundary, the obstacles or the targets. Conventions for degenerate cases
// (docs/visibility.md):
//  - p strictly inside an object, or strictly outside the boundary: sees nothing.
//  - p within ε (Occluders::tolerance()) of an edge or a vertex: p is on it and sees only the
//    free side; the edge itself is seen edge-on.
//  - a target edge whose supporting line passes within ε of p is seen edge-on: zero length.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "scene/camera.h"
#include "visibility/occluders.h"
#include "visibility/segment.h"
#include "visibility/sweep_trace.h"

namespace camcov::visibility {

// Large scenes are culled first: from `fromPieces` pieces on, a query walks a grid of the
// chains outwards from the viewpoint and leaves out every chain it can prove hidden behind
// those nearer (OcclusionCulling, docs/visibility.md), then sweeps the rest. Where the view
// is local, as among many obstacles, the cost follows what is seen rather than the whole
// scene. What is left out depends on the scene and the viewpoint only, so results do too.
struct Culling {
  std::uint32_t fromPieces = 1024;  // scenes with fewer pieces are swept whole
  double cellsPerChain = 1.0;       // fineness of the culling grid
};
// How a Sweep's queries were answered so far (each camera of segments() is one query).
struct CullingCounts {
  std::uint64_t culled = 0;         // queries culled first
  std::uint64_t whole = 0;          // queries swept over the whole scene
  std::uint64_t chainsLeftOut = 0;  // chains left out, summed over the culled queries
  std::uint64_t reused = 0;         // cameras of segments() answered by a kept sweep
};

class Sweep {
 public:
  explicit Sweep(Culling culling = {});
  ~Sweep();
  Sweep(Sweep&&) noexcept;
  Sweep& operator=(Sweep&&) noexcept;

  // S(T, O, C) and visibleBy(s_l) (paper equation (1), Algorithm 1) for `cameras` (camera j
  // is j of visibleBy), camera j with lens lenses[j] (half-angle θ_j in radians). Writes into
  // `out` (cleared first) every target's boundary as segments, ordered by target, edge and along
  // the edge; segments nobody sees are included with an empty mask. O(M · n log n).
  // Each camera slot j keeps its last six sweeps: a camera whose arrangement
  // (Occluders::buildId()), pose and lens are bit for bit those of a kept sweep is not swept
  // again, so a call where one camera moved costs one sweep and the union, O(n log n + k log k)
  // for k seen intervals (the optimizers move one camera at a time).
  // Throws std::invalid_argument for more than scene::kMaxCameras cameras, fewer lenses than
  // cameras, θ_j outside (0, π), a range that is not positive (NaN included), or a non-finite
  // pose.
  void segments(const Occluders& occluders, std::span<const geometry::Pose> cameras,
                std::span<const scene::Lens> lenses, std::vector<Segment>& out);
  // The same for a team of like cameras, every one with lens `lens`.
  void segments(const Occluders& occluders, std::span<const geometry::Pose> cameras,
                const scene::Lens& lens, std::vector<Segment>& out);

  // What camera slot `slot` (< scene::kMaxCameras; camera `slot` of segments()) at `camera` with
  // `lens` sees of the targets' edges: the intervals segments() unites into S, from the
  // slot's kept sweeps when they hold this query. Valid until the slot's next sweep. Throws
  // like segments().
  std::span<const SeenInterval> seenBy(const Occluders& occluders, std::size_t slot,
                                       const geometry::Pose& camera, const scene::Lens& lens);

  const CullingCounts& counts() const;
  // Keeps the latest sweep of each of `other`'s camera slots, beside this one's own (those of
  // the same arrangement still hold: a world that did not change keeps its Occluders), for a
  // workspace that takes up another's instant: a query they answer is not swept again.
  void keepSweepsOf(const Sweep& other);

  // The omnidirectional visibility polygon of `point` (Algorithm 2, line 6; the motion
  // planner's sampler): the region seen from it, inside the boundary, among the objects.
  // Written into `out` counter-clockwise and star-shaped from `point`, so the triangles
  // (point, out[i], out[i + 1]) tile it (a fan; those touching `point` may be flat). When
  // `point` lies on an object's or the boundary's edge (a sampled q1), it is a vertex of the
  // polygon, which then covers the free side only. Empty if `point` sees nothing.
  // O(n log n). Throws std::invalid_argument for a non-finite point.
  void visibilityPolygon(const Occluders& occluders, geometry::Vec2 point, geometry::Ring& out);

  // What one camera sees: the visibility polygon cut to its field of view, "defined by p_j
  // itself and the event points inside the field of view" (section IV-B), cut to the lens's
  // range by arcs of its circle. For drawing.
  void fieldOfViewPolygon(const Occluders& occluders, const geometry::Pose& camera,
                          const scene::Lens& lens, geometry::Ring& out);

  // The sweep of one camera event by event, for debugging: fieldOfViewPolygon() with every ray
  // recorded (see SweepTrace). Same sweep, same event order and same active edges as
  // segments() in a scene swept whole; allocates while it records. Throws like
  // fieldOfViewPolygon().
  void trace(const Occluders& occluders, const geometry::Pose& camera, const scene::Lens& lens,
             SweepTrace& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace camcov::visibility
