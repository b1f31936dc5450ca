#include "visibility/polar_sweep.h"

namespace camcov::visibility {

using EventKind = PolarEdges::EventKind;

void PolarSweep::run(const PolarEdges& edges, SpanSink& sink, SweepObserver* observer) {
  if (edges.blind()) return;
  active_.reset(edges.idCount(), edges.wedgeBase());
  for (const std::uint32_t id : edges.initiallyActive()) {
    if (id < edges.wedgeBase()) {
      active_.insert(id, edges.edgeOf(id));
    } else {
      active_.insertWedge(id);
    }
  }

  const auto events = edges.events();
  std::uint32_t front = active_.front();
  bool inFov = edges.initiallyInFov();
  if (observer != nullptr) observer->start(front, inFov);
  // Spans run from one change to the next; the last one closes on the first change, across
  // the +x axis, so no span is cut where the sweep happens to start.
  bool changed = false;
  geometry::Vec2 firstRay, lastRay;

  for (std::size_t i = 0; i < events.size();) {
    std::size_t end = i + 1;
    while (end < events.size() && edges.sameRay(events[i], events[end]))
      ++end;

    bool enter = false, leave = false;
    const auto batch = events.subspan(i, end - i);
    apply(edges, batch, enter, leave);
    const bool nextInFov = enter && leave ? edges.wideFov() : enter || (inFov && !leave);
    const std::uint32_t nextFront = active_.front();
    if (observer != nullptr) observer->ray(batch, nextFront, nextInFov);

    if (nextFront != front || nextInFov != inFov) {
      const geometry::Vec2 ray = edges.pointOf(events[i]);
      if (changed) {
        sink.span(front, lastRay, ray, inFov);
      } else {
        changed = true;
        firstRay = ray;
      }
      lastRay = ray;
      front = nextFront;
      inFov = nextInFov;
    }
    i = end;
  }
  if (changed) sink.span(front, lastRay, firstRay, inFov);
}

void PolarSweep::apply(const PolarEdges& edges, std::span<const PolarEdges::Event> batch,
                       bool& enter, bool& leave) {
  using E = PolarEdges;
  const auto vertices = edges.occluders().vertices();
  // A piece inserted at vertex v runs from v to its other end: the vertex before v for the
  // piece before, the next vertex in the chain for the piece after.
  const auto beforeEdge = [vertices](const E::Event& e) {
    return E::Edge{vertices[e.ref], vertices[e.before]};
  };
  const auto afterEdge = [&](const E::Event& e) {
    const std::uint32_t end =
        (e.actions & E::kAfterWraps) ? edges.occluders().next(e.ref) : e.ref + 1;
    return E::Edge{vertices[e.ref], vertices[end]};
  };
  if (batch.size() == 1 && batch[0].kind == EventKind::Vertex) {
    // A vertex the boundary just passes: one piece hands over to the next in place.
    const E::Event& v = batch[0];
    const std::uint8_t handOver = v.actions & ~E::kAfterWraps;
    if (handOver == (E::kRemoveBefore | E::kInsertAfter)) {
      return active_.replace(v.before, v.ref, afterEdge(v));
    }
    if (handOver == (E::kRemoveAfter | E::kInsertBefore)) {
      return active_.replace(v.ref, v.before, beforeEdge(v));
    }
  }
  for (const E::Event& e : batch) {
    if (e.kind == EventKind::Vertex) {
      if (e.actions & E::kRemoveBefore) active_.erase(e.before);
      if (e.actions & E::kRemoveAfter) active_.erase(e.ref);
    } else if (e.kind == EventKind::WedgeEnd) {
      active_.erase(edges.wedgeBase() + e.ref);
    } else if (e.kind == EventKind::FovLeave) {
      leave = true;
    }
  }
  // Both pieces of a vertex facing the viewpoint start there: the second goes beside the first
  // without a search, unless other events share the ray. Rings touching at that vertex would
  // start pieces there too, and those may belong between the two.
  const bool alone = batch.size() == 1;
  for (const E::Event& e : batch) {
    if (e.kind == EventKind::Vertex) {
      const bool before = (e.actions & E::kInsertBefore) != 0;
      if (before) active_.insertAt(e.before, beforeEdge(e));
      if (e.actions & E::kInsertAfter) {
        if (before && alone) {
          active_.insertBeside(e.ref, afterEdge(e), e.before);
        } else {
          active_.insertAt(e.ref, afterEdge(e));
        }
      }
    } else if (e.kind == EventKind::WedgeStart) {
      active_.insertWedge(edges.wedgeBase() + e.ref);
    } else if (e.kind == EventKind::FovEnter) {
      enter = true;
    }
  }
}

}  // namespace camcov::visibility
