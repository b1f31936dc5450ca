#pragma once
// createPolarEdges(segments, p_j) and the sorted event list — Algorithm 1, lines 3–5
// (paper section IV-B). Internal to the visibility stage; sweep.h is the public interface.
//
// For one viewpoint p every piece of the Occluders becomes either
//  - a polar edge: its endpoints ordered counter-clockwise around p, inserted into the active
//    edges at the first and removed at the second (the paper's firstVertex test), or
//  - nothing, when p lies exactly on its supporting line (it subtends no angle).
// Where p is within ε of a ring (on an edge or a vertex), the pieces touching p are replaced
// by a blocked wedge: the ring's solid side around p, at distance zero, so the camera sees
// only the free side. p strictly inside an object or strictly outside the boundary is blind.
//
// With a field of view, a piece out of view on every ray it spans is left out (inactive, no
// events): what is out of view needs no front edge, and a narrow view sorts a fraction of the
// events.
//
// Events are the chain vertices (one event per vertex: the edge ending there and the edge
// starting there are handled together), the wedges' sides, and the two field-of-view rays.
// They are sorted by polar angle from the +x axis: a radix sort on the pseudo-angle, then an
// insertion pass that orders near-ties with the exact compareAngle(), so the order is exact
// and the sort linear in practice.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/predicates.h"
#include "geometry/vec2.h"
#include "visibility/occluders.h"

namespace camcov::visibility {

// A camera's field of view: the closed wedge [yaw − halfAngle, yaw + halfAngle].
struct FieldOfView {
  double yaw = 0.0;        // γ, radians
  double halfAngle = 0.0;  // θ, radians, in (0, π)
};

class PolarEdges {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  enum class EventKind : std::uint8_t { Vertex, WedgeStart, WedgeEnd, FovEnter, FovLeave };
  // What a vertex event does to the piece ending there ("before", in chain order) and to the
  // piece starting there ("after"), worked out when the events are built so that the sweep
  // itself reads nothing but the events.
  static constexpr std::uint8_t kRemoveBefore = 1, kInsertBefore = 2, kRemoveAfter = 4,
                                kInsertAfter = 8;
  // The piece after ends at the chain's first vertex, not at the next one in memory.
  static constexpr std::uint8_t kAfterWraps = 16;
  struct Event {
    std::uint32_t key;     // pseudo-angle of the event's direction, in units of 2^-30
    std::uint32_t ref;     // chain vertex (= the piece after), wedge, or field-of-view ray
    std::uint32_t before;  // for a vertex: the piece ending there
    EventKind kind;
    // For a vertex: the k…Before / k…After flags. Two bytes, so that an event fills its 16
    // bytes with no padding and is copied as whole words (a 14-byte copy is two overlapping
    // 8-byte moves, whose second load stalls on the first store in the sorts' inner loops).
    std::uint16_t actions = 0;
  };
  static_assert(sizeof(Event) == 16);
  // A polar edge: s comes first counter-clockwise around the viewpoint, so the viewpoint is
  // strictly left of s → e.
  struct Edge {
    geometry::Vec2 s, e;
  };
  // A blocked wedge from the direction of vertex `start` counter-clockwise to `end`.
  struct Wedge {
    std::uint32_t start, end;
  };

  // Which pieces of the objects the viewpoint is outside of take part: those that may be the
  // front edge (farPieceState()), or all of them, for the sweep debugger's trace.
  enum class Faces : std::uint8_t { Seeable, All };

  // Prepares the sweep from `viewpoint` over all chains; `fov` is null for an omnidirectional
  // viewpoint.
  void build(const Occluders& occluders, geometry::Vec2 viewpoint, const FieldOfView* fov,
             Faces faces = Faces::Seeable);
  // The same for the chains `chains` only (ascending indices). Every chain the viewpoint may
  // see or lies near must be among them, and the boundary: then the front edge is the same on
  // every ray as with all chains (OcclusionCulling::kept()).
  void build(const Occluders& occluders, geometry::Vec2 viewpoint, const FieldOfView* fov,
             std::span<const std::uint32_t> chains);

  bool blind() const { return blind_; }
  geometry::Vec2 viewpoint() const { return p_; }
  const Occluders& occluders() const { return *occluders_; }

  std::span<const Event> events() const { return events_; }
  // Ids active on the ray just below the +x axis, where the sweep starts and ends.
  std::span<const std::uint32_t> initiallyActive() const { return initial_; }
  bool initiallyInFov() const { return initiallyInFov_; }
  // Wider than a half-plane: decides which side wins when both rays fall on one ray.
  bool wideFov() const { return wideFov_; }

  // Active ids: pieces are 0 .. pieceCount − 1, wedges follow from wedgeBase().
  std::uint32_t wedgeBase() const { return occluders_->pieceCount(); }
  std::uint32_t idCount() const { return wedgeBase() + static_cast<std::uint32_t>(wedges_.size()); }
  // An active piece as a polar edge.
  Edge edgeOf(std::uint32_t piece) const;

  // Seen edge-on (its line passes within ε of the viewpoint): it occludes, but has no length
  // to be seen.
  bool edgeOn(std::uint32_t piece) const { return (state_[piece] & kEdgeOn) != 0; }

  geometry::Vec2 pointOf(const Event& event) const;
  bool sameRay(const Event& a, const Event& b) const;

  // The box, seen from a viewpoint outside it, is out of view as a whole (after build()):
  // discView() first, then boxBeyondARay(), then boxArcOutOfView().
  bool boxOutOfView(const geometry::Box& box) const;
  // The arc the box spans, in keys, lies in the out-of-view arc with two quanta to spare.
  bool boxArcOutOfView(const geometry::Box& box) const;
  // A quick first test, for a field of view no wider than a half-plane (θ ≤ π/2): the box
  // lies wholly on the far side of one of the rays, by an angle of more than kBeyondRayMargin.
  // That side lies inside the out-of-view arc, so boxArcOutOfView() says so too: the margin,
  // 1e-6 rad, dwarfs the two quanta of slack its keys keep (about 1e-8 rad), so the quick test
  // never culls a chain the other would keep, and the sweep's output is unchanged.
  bool boxBeyondARay(const geometry::Box& box) const;
  static constexpr double kBeyondRayMargin = 1e-6;
  // Quicker tests both ways, for θ ≤ π/2, on the disc about the box's centre that holds it
  // (radius (w + h)/2, which bounds each corner's distance and |·|₁ offset from the centre):
  //  - BeyondARay: the disc lies beyond one of the rays by twice boxBeyondARay()'s margin, so
  //    every corner lies beyond it by that margin and boxBeyondARay() says so too. Most chains
  //    lie out of a narrow view, and are culled at the cost of one point's test.
  //  - WellInView: it lies inside both rays by twice the margin, so neither test above can say
  //    out of view. Most chains a camera looks at pass it, and skip them.
  enum class DiscView : std::uint8_t { BeyondARay, WellInView, Unsure };
  DiscView discView(const geometry::Box& box) const;

  // Two stable sorts of events by key, one result: an LSD radix sort (four passes of 8 bits),
  // and for a few events, as a camera's narrow view holds, a counting sort into 256 buckets
  // over the keys' range followed by insertion within them (insertion alone up to kTinyEvents).
  // sortEvents() takes the second up to kFewEvents events.
  static void radixSortByKey(std::vector<Event>& events, std::vector<Event>& scratch);
  static void bucketSortByKey(std::vector<Event>& events, std::vector<Event>& scratch);
  static constexpr std::size_t kFewEvents = 256, kTinyEvents = 24;

  // Where the ray from the viewpoint through q meets the piece: its parameter from the
  // piece's chain start (0) to its chain end (1), exact when q is one of the two.
  double param(std::uint32_t piece, geometry::Vec2 q) const;
  // The nearest point of active id `id` on the ray through q (the viewpoint for a wedge).
  geometry::Vec2 hit(std::uint32_t id, geometry::Vec2 q) const;

 private:
  static constexpr std::uint8_t kActive = 1, kReversed = 2, kEdgeOn = 4;

  void start(const Occluders& occluders, geometry::Vec2 viewpoint, const FieldOfView* fov);
  // Adds chain's events; false when the viewpoint is found blind.
  bool addChain(const Chain& chain);
  void finish(const FieldOfView* fov);
  bool classifyNearChain(const Chain& chain);
  // classifyNearChain()'s states of the boundary's pieces, in chain order, while the viewpoint
  // lies well inside each one's half-plane: all of them when it lies well inside the kernel.
  // How many it set.
  std::uint32_t classifyFromKernel(const Chain& chain);
  std::uint8_t pieceState(std::uint32_t piece, geometry::Vec2 a, geometry::Vec2 b) const;
  // pieceState() of a representative piece from its orientation test, taken already.
  std::uint8_t stateOf(const geometry::Orientation& o, geometry::Vec2 a, geometry::Vec2 b) const;
  // pieceState() of a piece of an object whose box the viewpoint is outside, and so strictly
  // outside the object: a piece the viewpoint sees from the object's solid side is never the
  // front edge (a ray reaching it from inside the object has crossed the object's boundary
  // nearer), so it is left inactive, with no events. Pieces with twins (shared with another
  // ring) and the boundary's keep their state, and so does every piece for Faces::All.
  std::uint8_t farPieceState(const Chain& chain, std::uint32_t piece, geometry::Vec2 a,
                             geometry::Vec2 b) const;
  // Culling what is out of view (keys as in Event::key). The arc counter-clockwise from
  // startKey to endKey, shorter than π, lies inside the out-of-view arc.
  bool outOfView(std::uint32_t startKey, std::uint32_t endKey) const;
  // `state`, or 0 when the piece is out of view on every ray from its ends' keys.
  std::uint8_t cull(std::uint8_t state, std::uint32_t startKey, std::uint32_t endKey) const;

  // For a chain far from the viewpoint: every piece of the block is inactive, as it faces away
  // (farPieceState()) or lies out of view (cull()), told from the block's cone and box.
  bool blockHidden(const Chain& chain, const PieceBlock& block) const;
  void addChainEvents(const Chain& chain, bool classify);
  void addWedge(std::uint32_t start, std::uint32_t end);
  void addEvent(geometry::Vec2 point, std::uint32_t ref, EventKind kind);

  bool less(const Event& a, const Event& b) const;
  void sortEvents();

  geometry::Vec2 vertex(std::uint32_t i) const { return occluders_->vertices()[i]; }

  const Occluders* occluders_ = nullptr;
  geometry::Vec2 p_;
  double eps2_ = 0.0;
  bool blind_ = false;
  bool initiallyInFov_ = true;
  bool wideFov_ = true;
  geometry::Vec2 fovPoints_[2];
  // The out-of-view arc in keys: from cullFrom_ counter-clockwise over cullWidth_ quanta (0 for
  // an omnidirectional viewpoint: nothing is culled).
  std::uint32_t cullFrom_ = 0, cullWidth_ = 0;
  // For boxBeyondARay(): the rays' directions (fovPoints_ − p_) and margins times their length.
  bool narrowFov_ = false;
  Faces faces_ = Faces::Seeable;
  geometry::Vec2 rayRight_, rayLeft_;
  double rayRightNorm_ = 0.0, rayLeftNorm_ = 0.0;
  double rayRightMargin_ = 0.0, rayLeftMargin_ = 0.0;

  std::vector<std::uint8_t> state_;  // per piece: kActive, kReversed, kEdgeOn
  std::vector<Wedge> wedges_;
  std::vector<std::uint8_t> near_;  // per vertex of the chain being classified
  std::vector<Event> events_, scratch_;
  std::vector<std::uint32_t> initial_;
};

}  // namespace camcov::visibility
