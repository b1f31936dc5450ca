#include "visibility/polar_edges.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <utility>

#include "geometry/predicates.h"
#include "visibility/angle_keys.h"

namespace camcov::visibility {

using geometry::Vec2;

namespace {

constexpr std::uint8_t kTouching = 8;  // replaced by a blocked wedge

}  // namespace

void PolarEdges::build(const Occluders& occluders, Vec2 viewpoint, const FieldOfView* fov,
                       Faces faces) {
  start(occluders, viewpoint, fov);
  faces_ = faces;
  for (const Chain& chain : occluders.chains()) {
    if (!addChain(chain)) return;
  }
  finish(fov);
}

void PolarEdges::build(const Occluders& occluders, Vec2 viewpoint, const FieldOfView* fov,
                       std::span<const std::uint32_t> chains) {
  start(occluders, viewpoint, fov);
  faces_ = Faces::Seeable;
  for (const std::uint32_t c : chains) {
    if (!addChain(occluders.chains()[c])) return;
  }
  finish(fov);
}

void PolarEdges::start(const Occluders& occluders, Vec2 viewpoint, const FieldOfView* fov) {
  occluders_ = &occluders;
  p_ = viewpoint;
  eps2_ = occluders.tolerance() * occluders.tolerance();
  blind_ = false;
  state_.assign(occluders.pieceCount(), 0);

  wedges_.clear();
  events_.clear();
  initial_.clear();

  initiallyInFov_ = true;
  cullFrom_ = cullWidth_ = 0;
  narrowFov_ = false;
  if (fov != nullptr) {
    // Far points on the two rays, so that rounding p + r·u tilts them by about 2^-52 rad.
    const double r = occluders.extent() + std::abs(p_.x) + std::abs(p_.y);
    fovPoints_[0] = p_ + r * geometry::unitVector(fov->yaw - fov->halfAngle);
    fovPoints_[1] = p_ + r * geometry::unitVector(fov->yaw + fov->halfAngle);
    wideFov_ = fov->halfAngle > 0.5 * std::numbers::pi;
    // In view on the start ray iff the wedge from the right ray to the left one wraps past +x.
    const int order = geometry::compareAngle(p_, fovPoints_[0], fovPoints_[1]);
    initiallyInFov_ = order > 0 || (order == 0 && wideFov_);
    // Out of view: counter-clockwise from the left ray (FovLeave) to the right one (FovEnter).
    cullFrom_ = quantizedAngle(fovPoints_[1] - p_);
    cullWidth_ = quantizedAngle(fovPoints_[0] - p_) - cullFrom_;  // modulo 2^32, keys go round
    narrowFov_ = fov->halfAngle <= 0.5 * std::numbers::pi;
    if (narrowFov_) {
      rayRight_ = fovPoints_[0] - p_;
      rayLeft_ = fovPoints_[1] - p_;
      rayRightNorm_ = geometry::norm(rayRight_);
      rayLeftNorm_ = geometry::norm(rayLeft_);
      rayRightMargin_ = kBeyondRayMargin * rayRightNorm_;
      rayLeftMargin_ = kBeyondRayMargin * rayLeftNorm_;
    }
  }
}

bool PolarEdges::addChain(const Chain& chain) {
  const double eps = occluders_->tolerance();
  const geometry::Box& box = chain.box;
  const bool far = p_.x < box.min.x - eps || p_.x > box.max.x + eps || p_.y < box.min.y - eps ||
                   p_.y > box.max.y + eps;
  // Outside the boundary's box is outside the boundary; near a ring, look closer.
  if (far ? chain.kind == RingKind::Boundary : !classifyNearChain(chain)) {
    blind_ = true;
    return false;
  }
  // A far chain out of view as a whole needs no look at its pieces: they stay inactive.
  if (!(far && boxOutOfView(box))) addChainEvents(chain, far);
  return true;
}

void PolarEdges::finish(const FieldOfView* fov) {
  for (std::uint32_t w = 0; w < wedges_.size(); ++w) {
    addEvent(vertex(wedges_[w].start), w, EventKind::WedgeStart);
    addEvent(vertex(wedges_[w].end), w, EventKind::WedgeEnd);
  }
  if (fov != nullptr) {
    addEvent(fovPoints_[0], 0, EventKind::FovEnter);
    addEvent(fovPoints_[1], 1, EventKind::FovLeave);
  }

  sortEvents();
}

void PolarEdges::addChainEvents(const Chain& chain, bool classify) {
  const std::uint32_t first = chain.first, last = first + chain.count - 1;
  const auto nextOf = [first, last](std::uint32_t v) { return v == last ? first : v + 1; };
  // A chain far from the viewpoint has its pieces classified first, so that only the vertices
  // of active pieces get a key (a key costs a division; half an object's pieces face away).
  // A long chain's blocks that face away or lie out of view as a whole keep their pieces
  // inactive (start() left them so) without a look at each.
  if (classify) {
    const auto classifyPieces = [&](std::uint32_t from, std::uint32_t to) {
      for (std::uint32_t v = from; v < to; ++v)
        state_[v] = farPieceState(chain, v, vertex(v), vertex(nextOf(v)));
    };
    const std::span<const PieceBlock> blocks = occluders_->blocks(chain);
    if (blocks.empty()) classifyPieces(first, last + 1);
    for (const PieceBlock& block : blocks) {
      if (!blockHidden(chain, block)) classifyPieces(block.first, block.first + block.count);
    }
  }
  const auto active = [this](std::uint32_t piece) { return (state_[piece] & kActive) != 0; };
  const auto keyOf = [this](std::uint32_t v) { return quantizedAngle(vertex(v) - p_); };
  // Then one pass along the chain in memory order: vertex v ends the piece before it and starts
  // the piece after it. A vertex's key is taken where a piece at it is active, before culling.
  const std::uint32_t firstKey = active(last) || active(first) ? keyOf(first) : 0;
  if (active(last)) state_[last] = cull(state_[last], keyOf(last), firstKey);
  std::uint8_t before = state_[last];
  int beforeHalf = geometry::angleHalf(vertex(last) - p_);
  std::uint32_t key = firstKey;
  bool keyTaken = true;  // key is vertex v's
  for (std::uint32_t v = first; v <= last; ++v) {
    // Between two inactive pieces nothing happens: a run of them (a block passed over, the far
    // side of an object) costs a test a vertex.
    if (!(before & kActive) && !active(v)) {
      before = state_[v];
      keyTaken = false;
      continue;
    }
    if (!keyTaken) key = keyOf(v);
    std::uint32_t nextKey = firstKey;
    if (v != last) {
      nextKey = active(v) || active(v + 1) ? keyOf(v + 1) : 0;
      state_[v] = cull(state_[v], key, nextKey);
    }
    const std::uint8_t after = state_[v];
    const int half = geometry::angleHalf(vertex(v) - p_);
    // An active piece running with its chain is inserted at its chain start and removed at its
    // chain end; a reversed one the other way round.
    std::uint8_t actions = 0;
    if (before & kActive) actions |= (before & kReversed) ? kInsertBefore : kRemoveBefore;
    if (after & kActive) actions |= (after & kReversed) ? kRemoveAfter : kInsertAfter;
    if (actions != 0) {
      if (v == last) actions |= kAfterWraps;
      events_.push_back({key, v, v == first ? last : v - 1, EventKind::Vertex, actions});
    }
    // The piece before is active on the start ray iff it spans the +x axis: it starts below
    // and ends above.
    const bool reversed = (before & kReversed) != 0;
    if ((before & kActive) && (reversed ? half : beforeHalf) == 1 &&
        (reversed ? beforeHalf : half) == 0) {
      initial_.push_back(v == first ? last : v - 1);
    }
    key = nextKey;
    keyTaken = true;
    before = after;
    beforeHalf = half;
  }
}

bool PolarEdges::blockHidden(const Chain& chain, const PieceBlock& block) const {
  // Facing away is what farPieceState() finds piece by piece for Faces::Seeable.
  const bool facesAway =
      faces_ == Faces::Seeable && block.plain && block.facesAwayFrom(p_, chain.solidOnLeft);
  return facesAway || boxOutOfView(block.box);
}

bool PolarEdges::outOfView(std::uint32_t startKey, std::uint32_t endKey) const {
  // Offsets counter-clockwise from the left field-of-view ray, modulo 2^32. An arc of less
  // than π whose start and end both lie two quanta inside the out-of-view arc, start first,
  // lies inside it: less() puts events at its ends strictly between the FovLeave and FovEnter
  // events. (Start first is enough: an arc shorter than π cannot go the long way round.)
  const std::uint32_t s = startKey - cullFrom_, e = endKey - cullFrom_;
  return s >= 2 && s <= e && std::uint64_t{e} + 2 <= cullWidth_;
}

std::uint8_t PolarEdges::cull(std::uint8_t state, std::uint32_t startKey,
                              std::uint32_t endKey) const {
  // An active piece spans less than π from its start to its end; out of view on all of it,
  // the sweep would never have it active on a ray in view.
  if (!(state & kActive) || cullWidth_ == 0) return state;
  if (state & kReversed) std::swap(startKey, endKey);
  return outOfView(startKey, endKey) ? 0 : state;
}

bool PolarEdges::boxBeyondARay(const geometry::Box& box) const {
  if (!narrowFov_) return false;
  const Vec2 corners[4] = {box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  bool right = true, left = true;
  for (const Vec2 c : corners) {
    const Vec2 d = c - p_;
    const double l1 = std::abs(d.x) + std::abs(d.y);  // at least |d|
    // sin of the angle past the ray, times |ray| · |d|.
    right = right && geometry::cross(rayRight_, d) < -rayRightMargin_ * l1;
    left = left && geometry::cross(d, rayLeft_) < -rayLeftMargin_ * l1;
  }
  return right || left;
}

PolarEdges::DiscView PolarEdges::discView(const geometry::Box& box) const {
  if (!narrowFov_) return DiscView::Unsure;
  // Every point x of the box lies within r = (w + h)/2 of its centre c, so cross(ray, x − p)
  // lies within |ray|·r of cross(ray, c − p), and |x − p|₁ ≤ |c − p|₁ + 2r: past twice the
  // margin with the disc, past the margin with every corner (the factor 2 dwarfs rounding).
  const Vec2 c{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y)};
  const double r = 0.5 * ((box.max.x - box.min.x) + (box.max.y - box.min.y));
  const Vec2 d = c - p_;
  const double l1 = std::abs(d.x) + std::abs(d.y) + 2.0 * r;
  const double right = geometry::cross(rayRight_, d), left = geometry::cross(d, rayLeft_);
  const double rightMargin = 2.0 * rayRightMargin_ * l1, leftMargin = 2.0 * rayLeftMargin_ * l1;
  if (right + rayRightNorm_ * r < -rightMargin || left + rayLeftNorm_ * r < -leftMargin)
    return DiscView::BeyondARay;
  if (right - rayRightNorm_ * r > rightMargin && left - rayLeftNorm_ * r > leftMargin)
    return DiscView::WellInView;
  return DiscView::Unsure;
}

bool PolarEdges::boxOutOfView(const geometry::Box& box) const {
  if (cullWidth_ == 0) return false;
  switch (discView(box)) {
    case DiscView::BeyondARay:
      return true;
    case DiscView::WellInView:
      return false;
    case DiscView::Unsure:
      break;
  }
  return boxBeyondARay(box) || boxArcOutOfView(box);
}

bool PolarEdges::boxArcOutOfView(const geometry::Box& box) const {
  if (cullWidth_ == 0) return false;
  const std::optional<KeyArc> arc = boxArc(box, p_);
  return arc && outOfView(arc->start, arc->end());
}

bool PolarEdges::less(const Event& a, const Event& b) const {
  if (std::uint64_t{a.key} + 1 < b.key) return true;  // two quanta apart
  if (std::uint64_t{b.key} + 1 < a.key) return false;
  return geometry::compareAngle(p_, pointOf(a), pointOf(b)) < 0;
}

void PolarEdges::sortEvents() {
  // A stable sort by key ...
  if (events_.size() <= kFewEvents) {
    bucketSortByKey(events_, scratch_);
  } else {
    radixSortByKey(events_, scratch_);
  }
  const std::size_t n = events_.size();
  // ... then insertion sort in the exact order. Only events whose keys share a quantum or lie
  // within the pseudo-angle's error of each other can be out of place, so this pass is linear
  // unless many vertices lie on one ray.
  for (std::size_t i = 1; i < n; ++i) {
    if (!less(events_[i], events_[i - 1])) continue;
    const Event e = events_[i];
    std::size_t j = i;
    for (; j > 0 && less(e, events_[j - 1]); --j)
      events_[j] = events_[j - 1];
    events_[j] = e;
  }
}

void PolarEdges::radixSortByKey(std::vector<Event>& events, std::vector<Event>& scratch) {
  // LSD: four passes of 8 bits, each stable.
  const std::size_t n = events.size();
  scratch.resize(n);
  std::array<std::array<std::uint32_t, 256>, 4> count{};
  for (const Event& e : events) {
    for (int d = 0; d < 4; ++d)
      ++count[d][(e.key >> (8 * d)) & 0xff];
  }
  for (int d = 0; d < 4; ++d) {
    auto& c = count[d];
    if (n == 0 || c[(events[0].key >> (8 * d)) & 0xff] == n) continue;  // all in one bucket
    std::uint32_t sum = 0;
    for (std::uint32_t& slot : c)
      sum += std::exchange(slot, sum);
    for (const Event& e : events)
      scratch[c[(e.key >> (8 * d)) & 0xff]++] = e;
    events.swap(scratch);
  }
}

void PolarEdges::bucketSortByKey(std::vector<Event>& events, std::vector<Event>& scratch) {
  if (events.size() > kTinyEvents) {
    std::uint32_t lo = events[0].key, hi = lo;
    for (const Event& e : events) {
      lo = std::min(lo, e.key);
      hi = std::max(hi, e.key);
    }
    // About as many buckets as events over [lo, hi] (a power of two, at most 256): the events
    // spread over them, so each holds a few. Counting into them is stable.
    const int bits = std::min(static_cast<int>(std::bit_width(events.size() - 1)), 8);
    const int shift = std::max(static_cast<int>(std::bit_width(hi - lo)) - bits, 0);
    const std::size_t buckets = std::size_t{1} << bits;
    std::array<std::uint32_t, 257> start;  // start[b + 1]: bucket b's count, then its end
    std::fill_n(start.begin(), buckets + 1, 0u);
    for (const Event& e : events)
      ++start[((e.key - lo) >> shift) + 1];
    for (std::size_t b = 1; b <= buckets; ++b)
      start[b] += start[b - 1];
    scratch.resize(events.size());
    for (const Event& e : events)
      scratch[start[(e.key - lo) >> shift]++] = e;
    events.swap(scratch);
  }
  // Keys now only fall out of order within a bucket (or, for a tiny few, anywhere): stable
  // insertion by key.
  for (std::size_t i = 1; i < events.size(); ++i) {
    if (!(events[i].key < events[i - 1].key)) continue;  // in place: most are
    const Event e = events[i];
    std::size_t j = i;
    for (; j > 0 && e.key < events[j - 1].key; --j)
      events[j] = events[j - 1];
    events[j] = e;
  }
}

bool PolarEdges::classifyNearChain(const Chain& chain) {
  const std::uint32_t first = chain.first, count = chain.count;
  // Pieces first .. first + known have their final states already.
  const std::uint32_t known = chain.kind == RingKind::Boundary ? classifyFromKernel(chain) : 0;
  if (known == count) return true;

  near_.resize(count);
  bool touching = false;
  for (std::uint32_t k = 0; k < count; ++k) {
    near_[k] = norm2(vertex(first + k) - p_) <= eps2_;
    touching = touching || near_[k];
  }
  bool inside = false;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t kn = k + 1 == count ? 0 : k + 1;
    const Vec2 a = vertex(first + k), b = vertex(first + kn);
    if (!near_[k] && !near_[kn] && geometry::squaredDistanceToSegment(p_, a, b) <= eps2_) {
      // On the piece's interior: its solid side is a half-plane at distance zero.
      touching = true;
      state_[first + k] = kTouching;
      if (chain.solidOnLeft) {
        addWedge(first + kn, first + k);
      } else {
        addWedge(first + k, first + kn);
      }
    }
    // Crossing number with the half-open rule; p is farther than ε from every piece here, so
    // rounding cannot flip a crossing.
    if ((a.y > p_.y) != (b.y > p_.y) && p_.x < a.x + (p_.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
      inside = !inside;
    }
  }

  if (!touching) {
    // Strictly outside the boundary, or strictly inside an object: nothing is visible.
    if ((chain.kind == RingKind::Boundary) != inside) return false;
  } else {
    // On a vertex, or on a run of vertices closer together than ε: the solid side between the
    // nearest vertices before (u) and after (w) the run is blocked.
    std::uint32_t k0 = 0;
    while (k0 < count && near_[k0])
      ++k0;
    if (k0 == count) return true;  // the whole ring is within ε of p: a point, no wedge
    for (std::uint32_t step = 1; step <= count; ++step) {
      const std::uint32_t k = (k0 + step) % count, u = (k + count - 1) % count;
      if (!near_[k] || near_[u]) continue;
      std::uint32_t w = k;
      state_[first + u] = kTouching;
      for (; near_[w]; w = (w + 1) % count)
        state_[first + w] = kTouching;
      if (chain.solidOnLeft) {
        addWedge(first + w, first + u);
      } else {
        addWedge(first + u, first + w);
      }
    }
  }
  for (std::uint32_t i = first + known; i < first + count; ++i) {
    if (state_[i] != kTouching) state_[i] = pieceState(i, vertex(i), vertex(occluders_->next(i)));
  }
  return true;
}

std::uint32_t PolarEdges::classifyFromKernel(const Chain& chain) {
  // Strictly on the room's side of every side's line, and more than 2ε from each: the
  // viewpoint lies in the room's kernel (the intersection of those half-planes), so inside it,
  // and farther than ε from every piece however classifyNearChain()'s distances round, so near
  // no vertex or piece: what classifyNearChain() would find, piece by piece. A piece that
  // passes lies farther than 2ε from the viewpoint, so no piece found touching after it can
  // change its state.
  const int roomSide = chain.solidOnLeft ? -1 : 1;
  std::uint32_t known = 0;
  for (; known < chain.count; ++known) {
    const std::uint32_t i = chain.first + known;
    const Vec2 a = vertex(i), b = vertex(occluders_->next(i));
    const geometry::Orientation o = geometry::orientation(a, b, p_);
    if (o.sign != roomSide || o.det * o.det <= 4.0 * eps2_ * norm2(b - a)) break;
    state_[i] = occluders_->isRepresentative(i) ? stateOf(o, a, b) : 0;
  }
  return known;
}

std::uint8_t PolarEdges::farPieceState(const Chain& chain, std::uint32_t piece, Vec2 a,
                                       Vec2 b) const {
  const std::uint8_t state = pieceState(piece, a, b);
  if (faces_ == Faces::All || chain.kind == RingKind::Boundary || occluders_->hasTwins(piece)) {
    return state;
  }
  // Seen from its solid side: the viewpoint left of a → b (not kReversed) with the solid on the
  // left, or right of it with the solid on the right.
  const bool facesAway = ((state & kReversed) == 0) == chain.solidOnLeft;
  return facesAway ? 0 : state;
}

std::uint8_t PolarEdges::pieceState(std::uint32_t piece, Vec2 a, Vec2 b) const {
  if (!occluders_->isRepresentative(piece)) return 0;
  return stateOf(geometry::orientation(a, b, p_), a, b);
}

std::uint8_t PolarEdges::stateOf(const geometry::Orientation& o, Vec2 a, Vec2 b) const {
  if (o.sign == 0) return 0;  // p on the supporting line: the piece subtends no angle
  // det is the distance from p to the line times |b − a|.
  const bool edgeOn = o.det * o.det <= eps2_ * norm2(b - a);
  return kActive | (o.sign < 0 ? kReversed : 0) | (edgeOn ? kEdgeOn : 0);
}

void PolarEdges::addWedge(std::uint32_t start, std::uint32_t end) {
  const int order = geometry::compareAngle(p_, vertex(start), vertex(end));
  if (order == 0) return;  // both sides on one ray: a needle, no angle
  const auto id = wedgeBase() + static_cast<std::uint32_t>(wedges_.size());
  wedges_.push_back({start, end});
  if (order > 0) initial_.push_back(id);  // it wraps past the +x axis
}

void PolarEdges::addEvent(Vec2 point, std::uint32_t ref, EventKind kind) {
  events_.push_back({quantizedAngle(point - p_), ref, 0, kind});
}

Vec2 PolarEdges::pointOf(const Event& event) const {
  switch (event.kind) {
    case EventKind::Vertex:
      return vertex(event.ref);
    case EventKind::WedgeStart:
      return vertex(wedges_[event.ref].start);
    case EventKind::WedgeEnd:
      return vertex(wedges_[event.ref].end);
    case EventKind::FovEnter:
    case EventKind::FovLeave:
      break;
  }
  return fovPoints_[event.ref];
}

bool PolarEdges::sameRay(const Event& a, const Event& b) const {
  return std::uint64_t{a.key} + 1 >= b.key && std::uint64_t{b.key} + 1 >= a.key &&
         geometry::compareAngle(p_, pointOf(a), pointOf(b)) == 0;
}

PolarEdges::Edge PolarEdges::edgeOf(std::uint32_t piece) const {
  const Vec2 a = vertex(piece), b = vertex(occluders_->next(piece));
  return (state_[piece] & kReversed) ? Edge{b, a} : Edge{a, b};
}

double PolarEdges::param(std::uint32_t piece, Vec2 q) const {
  const Vec2 a = vertex(piece), b = vertex(occluders_->next(piece));
  if (q == a) return 0.0;
  if (q == b) return 1.0;
  // The hit divides a–b in the ratio of their signed distances to the ray's line; a and b lie
  // on opposite sides, so this stays in [0, 1] up to rounding, however flat the angle.
  const Vec2 d = q - p_;
  const double oa = cross(d, a - p_), ob = cross(d, b - p_);
  const double den = oa - ob;
  return den != 0.0 ? std::clamp(oa / den, 0.0, 1.0) : 0.0;
}

Vec2 PolarEdges::hit(std::uint32_t id, Vec2 q) const {
  if (id >= wedgeBase()) return p_;
  const Vec2 a = vertex(id), b = vertex(occluders_->next(id));
  if (q == a) return a;
  if (q == b) return b;
  return lerp(a, b, param(id, q));
}

}  // namespace camcov::visibility
