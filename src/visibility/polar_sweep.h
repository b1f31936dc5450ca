#pragma once
// The angular sweep itself — Algorithm 1, lines 7–15 (paper section IV-B, after Asano's
// polar line sweep). Internal to the visibility stage.
//
// Events are visited in polar order, all events on one ray as one batch (removals, then
// insertions). Whenever the current edge or the field-of-view state changes (the paper's
// firstElementChanged), the angular span that just ended is handed to a SpanSink: the camera
// sweep turns spans into visible target intervals (update(S), update(visibleBy)), the polygon
// sweep into polygon vertices. The sweep covers the full 2π, as in the paper.
#include <cstdint>
#include <span>

#include "geometry/vec2.h"
#include "visibility/active_edges.h"
#include "visibility/polar_edges.h"

namespace camcov::visibility {

class SpanSink {
 public:
  // Between the rays through `from` and `to` (counter-clockwise), `front` (an active id or
  // PolarEdges::kNone) is the closest edge and the field-of-view state is `inFov`.
  virtual void span(std::uint32_t front, geometry::Vec2 from, geometry::Vec2 to, bool inFov) = 0;

 protected:
  ~SpanSink() = default;
};

// Watches the sweep ray by ray, for tracing (Sweep::trace); the sweep runs the same with or
// without one.
class SweepObserver {
 public:
  // On the start ray, before any event.
  virtual void start(std::uint32_t front, bool inFov) = 0;
  // The events of one ray have been applied; `front` and `inFov` hold just after it.
  virtual void ray(std::span<const PolarEdges::Event> batch, std::uint32_t front, bool inFov) = 0;

 protected:
  ~SweepObserver() = default;
};

class PolarSweep {
 public:
  // O(n log n) for n events: the event sort in PolarEdges, and O(log n) per tree update; a
  // vertex where one edge hands over to the next costs O(1). `observer` may be null.
  void run(const PolarEdges& edges, SpanSink& sink, SweepObserver* observer = nullptr);

 private:
  // Applies the events of one ray: removals, then insertions, so the order only ever compares
  // edges that are active on both sides of the ray. Returns the field-of-view flags seen.
  void apply(const PolarEdges& edges, std::span<const PolarEdges::Event> batch, bool& enter,
             bool& leave);

  ActiveEdges active_;
};

}  // namespace camcov::visibility
