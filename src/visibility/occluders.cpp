#include "visibility/occluders.h"

#include <algorithm>
#include <atomic>

#include "geometry/predicates.h"

namespace camcov::visibility {

using geometry::Box;
using geometry::Vec2;

namespace {

constexpr std::uint32_t kNone = Occluders::kNoEdge;

// Of two splits within ε of each other, the one both chains should use: an input vertex over
// a computed crossing, then the lexicographically smaller point. A fixed rule, so every edge
// that meets there picks the same point and their pieces match exactly.
bool preferred(Vec2 a, bool aExact, Vec2 b, bool bExact) {
  if (aExact != bExact) return aExact;
  return a.x != b.x ? a.x < b.x : a.y < b.y;
}

Box segmentBox(Vec2 a, Vec2 b) {
  return {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
}

}  // namespace

void Occluders::build(const kinematics::World& world) {
  static std::atomic<std::uint64_t> builds{0};
  buildId_ = ++builds;
  inVertices_.clear();
  inNext_.clear();
  inRingEdge_.clear();
  inRings_.clear();
  inChains_.clear();
  splits_.clear();
  collinearPairs_.clear();

  targetOffsets_.assign(1, 0);
  targetVertices_.clear();
  targetNext_.clear();
  for (const geometry::Ring& ring : world.targets) {
    const auto first = static_cast<std::uint32_t>(targetVertices_.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      targetVertices_.push_back(ring[k]);
      targetNext_.push_back(first + static_cast<std::uint32_t>((k + 1) % ring.size()));
    }
    targetOffsets_.push_back(static_cast<std::uint32_t>(targetVertices_.size()));
  }

  Box all = geometry::boundingBox(world.boundary);
  auto grow = [&all](const std::vector<geometry::Ring>& rings) {
    for (const geometry::Ring& ring : rings) {
      for (const Vec2 v : ring) {
        all.min = {std::min(all.min.x, v.x), std::min(all.min.y, v.y)};
        all.max = {std::max(all.max.x, v.x), std::max(all.max.y, v.y)};
      }
    }
  };
  grow(world.obstacles);
  grow(world.targets);
  // The floor also covers an empty World (a box of extent −inf).
  box_ = all;
  extent_ = std::max({all.max.x - all.min.x, all.max.y - all.min.y, 1e-300});
  tolerance_ = kRelativeTolerance * extent_;

  addRing(world.boundary, RingKind::Boundary, 0);
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    addRing(world.obstacles[i], RingKind::Obstacle, static_cast<std::uint32_t>(i));
  for (std::size_t i = 0; i < world.targets.size(); ++i)
    addRing(world.targets[i], RingKind::Target, static_cast<std::uint32_t>(i));

  findSplits();
  std::sort(splits_.begin(), splits_.end(), [](const Split& x, const Split& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.t < y.t;
  });
  unifyCollinearSplits();
  buildChains();
  findTwins();
}

const Chain& Occluders::chainOf(std::uint32_t piece) const {
  // Chains are contiguous and in vertex order: the last one starting at or before the piece.
  const auto after = std::upper_bound(chains_.begin(), chains_.end(), piece,
                                      [](std::uint32_t p, const Chain& c) { return p < c.first; });
  return *(after - 1);
}

void Occluders::addRing(const geometry::Ring& ring, RingKind kind, std::uint32_t owner) {
  const auto first = static_cast<std::uint32_t>(inVertices_.size());
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    // Of a run of repeated vertices keep the last: its edge is the one of non-zero length.
    if (ring[k] == ring[(k + 1) % n]) continue;
    inVertices_.push_back(ring[k]);
    inRingEdge_.push_back(static_cast<std::uint32_t>(k));
  }
  const auto count = static_cast<std::uint32_t>(inVertices_.size()) - first;
  if (count < 2) {  // a point occludes nothing and has no length to cover
    inVertices_.resize(first);
    inRingEdge_.resize(first);
    return;
  }
  for (std::uint32_t k = 0; k < count; ++k)
    inNext_.push_back(first + (k + 1) % count);
  const std::span<const Vec2> vertices(inVertices_.data() + first, count);
  Chain chain;
  chain.kind = kind;
  chain.solidOnLeft = (geometry::signedArea(vertices) > 0.0) != (kind == RingKind::Boundary);
  chain.owner = owner;
  chain.box = geometry::boundingBox(vertices);
  inRings_.push_back({first, count});
  inChains_.push_back(chain);
}

void Occluders::findSplits() {
  // Sweep and prune on the rings' boxes: sorted by left side, each ring meets only the rings
  // that start before it ends.
  const auto rings = static_cast<std::uint32_t>(inRings_.size());
  ringOrder_.resize(rings);
  for (std::uint32_t i = 0; i < rings; ++i)
    ringOrder_[i] = i;
  std::sort(ringOrder_.begin(), ringOrder_.end(), [this](std::uint32_t a, std::uint32_t b) {
    return inChains_[a].box.min.x < inChains_[b].box.min.x;
  });
  for (std::uint32_t i = 0; i < rings; ++i) {
    const Box& a = inChains_[ringOrder_[i]].box;
    for (std::uint32_t j = i + 1; j < rings && inChains_[ringOrder_[j]].box.min.x <= a.max.x; ++j) {
      if (geometry::overlaps(a, inChains_[ringOrder_[j]].box))
        intersectRings(ringOrder_[i], ringOrder_[j]);
    }
  }
}

void Occluders::intersectRings(std::uint32_t ringA, std::uint32_t ringB) {
  // Only edges that reach into the other ring's box can meet it.
  auto collect = [this](std::uint32_t ring, const Box& other, std::vector<std::uint32_t>& out) {
    out.clear();
    const InputRing& r = inRings_[ring];
    for (std::uint32_t e = r.first; e < r.first + r.count; ++e) {
      if (geometry::overlaps(segmentBox(inVertices_[e], inVertices_[inNext_[e]]), other))
        out.push_back(e);
    }
  };
  collect(ringA, inChains_[ringB].box, candidatesA_);
  collect(ringB, inChains_[ringA].box, candidatesB_);
  for (const std::uint32_t e : candidatesA_) {
    const Box be = segmentBox(inVertices_[e], inVertices_[inNext_[e]]);
    for (const std::uint32_t f : candidatesB_) {
      if (geometry::overlaps(be, segmentBox(inVertices_[f], inVertices_[inNext_[f]])))
        intersectEdges(e, f);
    }
  }
}

void Occluders::intersectEdges(std::uint32_t e, std::uint32_t f) {
  const Vec2 a = inVertices_[e], b = inVertices_[inNext_[e]];
  const Vec2 c = inVertices_[f], d = inVertices_[inNext_[f]];
  const int oc = geometry::orientSign(a, b, c), od = geometry::orientSign(a, b, d);
  if (oc == 0 && od == 0) {
    // Collinear: each is split at the other's endpoints that fall inside it (addSplit ignores
    // the rest), so the overlap becomes pieces with identical endpoints.
    addSplit(e, c, true);
    addSplit(e, d, true);
    addSplit(f, a, true);
    addSplit(f, b, true);
    collinearPairs_.push_back(std::uint64_t{e} << 32 | f);
    return;
  }
  const int oa = geometry::orientSign(c, d, a), ob = geometry::orientSign(c, d, b);
  if (oc * od > 0 || oa * ob > 0) return;  // one lies strictly on one side of the other
  // They touch or cross at one point. If an endpoint lies on the other edge, that endpoint is
  // the point, exactly.
  if (oc == 0) return addSplit(e, c, true);
  if (od == 0) return addSplit(e, d, true);
  if (oa == 0) return addSplit(f, a, true);
  if (ob == 0) return addSplit(f, b, true);
  // A proper crossing. The parameter as a ratio of distances to the other line stays in
  // [0, 1] and well conditioned. A crossing within ε of an endpoint becomes that endpoint, so
  // both chains share one exact vertex instead of two nearly equal ones.
  const double da = geometry::orient(c, d, a), db = geometry::orient(c, d, b);
  Vec2 x = lerp(a, b, std::clamp(da / (da - db), 0.0, 1.0));
  bool exact = false;
  for (const Vec2 v : {a, b, c, d}) {
    if (norm2(x - v) <= tolerance_ * tolerance_) {
      x = v;
      exact = true;
      break;
    }
  }
  addSplit(e, x, exact);
  addSplit(f, x, exact);
}

void Occluders::addSplit(std::uint32_t edge, Vec2 point, bool exact) {
  const Vec2 a = inVertices_[edge], b = inVertices_[inNext_[edge]];
  const double eps2 = tolerance_ * tolerance_;
  if (norm2(point - a) <= eps2 || norm2(point - b) <= eps2) return;
  const double t = dot(point - a, b - a) / norm2(b - a);
  if (!(t > 0.0 && t < 1.0)) return;  // a collinear neighbour's endpoint outside this edge
  splits_.push_back({edge, t, point, exact});
}

void Occluders::unifyCollinearSplits() {
  // An edge crossing a family of collinear overlapping edges meets each at "the same" point,
  // but computed from different endpoints, so the points differ by an ulp or so; unify them so
  // the overlapping pieces come out identical. Unifying one pair can make another pair
  // differ, hence the repetition; two or three passes settle any real configuration.
  const double eps2 = tolerance_ * tolerance_;
  auto range = [this](std::uint32_t edge) {
    return std::equal_range(splits_.begin(), splits_.end(), Split{edge, 0.0, {}, false},
                            [](const Split& x, const Split& y) { return x.edge < y.edge; });
  };
  bool changed = true;
  for (int pass = 0; changed && pass < 8; ++pass) {
    changed = false;
    for (const std::uint64_t pair : collinearPairs_) {
      const auto re = range(static_cast<std::uint32_t>(pair >> 32));
      const auto rf = range(static_cast<std::uint32_t>(pair));
      for (auto s = re.first; s != re.second; ++s) {
        for (auto r = rf.first; r != rf.second; ++r) {
          if (s->point == r->point || norm2(s->point - r->point) > eps2) continue;
          const Split& keep = preferred(s->point, s->exact, r->point, r->exact) ? *s : *r;
          s->point = r->point = keep.point;
          s->exact = r->exact = keep.exact;
          changed = true;
        }
      }
    }
  }
}

void Occluders::buildChains() {
  chains_.clear();
  vertices_.clear();
  inputEdgeOfPiece_.clear();
  t0_.clear();
  const double eps2 = tolerance_ * tolerance_;
  auto split = splits_.begin();
  for (std::size_t r = 0; r < inRings_.size(); ++r) {
    Chain chain = inChains_[r];
    chain.first = static_cast<std::uint32_t>(vertices_.size());
    const InputRing& ring = inRings_[r];
    for (std::uint32_t e = ring.first; e < ring.first + ring.count; ++e) {
      vertices_.push_back(inVertices_[e]);
      inputEdgeOfPiece_.push_back(e);
      t0_.push_back(0.0);
      bool lastExact = true;  // the input vertex itself
      for (; split != splits_.end() && split->edge == e; ++split) {
        // Several edges crossing at (nearly) one point give one vertex, chosen by the same
        // rule as in unifyCollinearSplits().
        if (norm2(split->point - vertices_.back()) <= eps2) {
          if (t0_.back() > 0.0 &&
              preferred(split->point, split->exact, vertices_.back(), lastExact)) {
            vertices_.back() = split->point;
            lastExact = split->exact;
          }
          continue;
        }
        vertices_.push_back(split->point);
        inputEdgeOfPiece_.push_back(e);
        t0_.push_back(split->t);
        lastExact = split->exact;
      }
    }
    chain.count = static_cast<std::uint32_t>(vertices_.size()) - chain.first;
    chains_.push_back(chain);
  }

  const std::size_t pieces = vertices_.size();
  next_.resize(pieces);
  t1_.resize(pieces);
  globalEdge_.resize(pieces);
  for (const Chain& chain : chains_) {
    for (std::uint32_t k = 0; k < chain.count; ++k) {
      const std::uint32_t i = chain.first + k, n = chain.first + (k + 1) % chain.count;
      next_[i] = n;
      t1_[i] = inputEdgeOfPiece_[n] == inputEdgeOfPiece_[i] ? t0_[n] : 1.0;
      globalEdge_[i] = chain.kind == RingKind::Target
                           ? targetOffsets_[chain.owner] + inRingEdge_[inputEdgeOfPiece_[i]]
                           : kNone;
    }
  }
}

std::uint32_t Occluders::findTwinRoot(std::uint32_t x) {
  // Union-find with parity: twinReversed_[x] is x's direction relative to twinOf_[x]. Walk to
  // the root summing parities, then point the whole path straight at the root.
  std::uint32_t root = x;
  std::uint8_t parity = 0;
  for (; twinOf_[root] != root; root = twinOf_[root])
    parity ^= twinReversed_[root];
  while (twinOf_[x] != x) {
    const std::uint32_t parent = twinOf_[x];
    const std::uint8_t parentParity = parity ^ twinReversed_[x];
    twinOf_[x] = root;
    twinReversed_[x] = parity;
    x = parent;
    parity = parentParity;
  }
  return root;
}

void Occluders::findTwins() {
  const std::size_t pieces = vertices_.size();
  twinOf_.resize(pieces);
  twinReversed_.assign(pieces, 0);
  for (std::uint32_t i = 0; i < pieces; ++i)
    twinOf_[i] = i;
  // Pieces of one input edge are consecutive in its chain, starting at the input vertex.
  // Overlaps are rare (only touching or overlapping objects), so the inverse map is searched,
  // not built.
  auto firstPiece = [this](std::uint32_t inputEdge) {
    const auto it = std::lower_bound(inputEdgeOfPiece_.begin(), inputEdgeOfPiece_.end(), inputEdge);
    return static_cast<std::uint32_t>(it - inputEdgeOfPiece_.begin());
  };
  for (const std::uint64_t pair : collinearPairs_) {
    const auto e = static_cast<std::uint32_t>(pair >> 32), f = static_cast<std::uint32_t>(pair);
    for (std::uint32_t p = firstPiece(e); p < pieces && inputEdgeOfPiece_[p] == e; ++p) {
      for (std::uint32_t q = firstPiece(f); q < pieces && inputEdgeOfPiece_[q] == f; ++q) {
        const Vec2 p0 = vertices_[p], p1 = vertices_[next_[p]];
        const Vec2 q0 = vertices_[q], q1 = vertices_[next_[q]];
        const bool same = p0 == q0 && p1 == q1, opposite = p0 == q1 && p1 == q0;
        if (!same && !opposite) continue;
        const std::uint32_t rp = findTwinRoot(p), rq = findTwinRoot(q);
        if (rp == rq) continue;
        // dir(p) ^ dir(q) = opposite, and each is its parity to its root ^ the root's direction.
        const auto parity =
            static_cast<std::uint8_t>(twinReversed_[p] ^ twinReversed_[q] ^ opposite);
        twinOf_[std::max(rp, rq)] = std::min(rp, rq);
        twinReversed_[std::max(rp, rq)] = parity;
      }
    }
  }

  isRepresentative_.resize(pieces);
  memberBegin_.assign(pieces + 1, 0);
  for (std::uint32_t i = 0; i < pieces; ++i) {
    isRepresentative_[i] = findTwinRoot(i) == i;
    if (globalEdge_[i] != kNone) ++memberBegin_[twinOf_[i] + 1];
  }
  for (std::size_t i = 0; i < pieces; ++i)
    memberBegin_[i + 1] += memberBegin_[i];
  members_.resize(memberBegin_[pieces]);
  memberCursor_.assign(memberBegin_.begin(), memberBegin_.end() - 1);
  for (std::uint32_t i = 0; i < pieces; ++i) {
    if (globalEdge_[i] != kNone) members_[memberCursor_[twinOf_[i]]++] = {i, twinReversed_[i] != 0};
  }
}

}  // namespace camcov::visibility
