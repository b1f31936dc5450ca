#include "visibility/occluders.h"

#include <algorithm>
#include <atomic>
#include <cmath>

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
  unifyCoincidentSplits();
  std::sort(splits_.begin(), splits_.end(), [](const Split& x, const Split& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.t < y.t;
  });
  buildChains();
  findTwins();
  buildBlocks();
}

void Occluders::buildBlocks() {
  blocks_.clear();
  for (Chain& chain : chains_) {
    chain.firstBlock = static_cast<std::uint32_t>(blocks_.size());
    appendPieceBlocks(vertices_, next_, chain.first, chain.count, hasTwins_, blocks_);
    chain.blockCount = static_cast<std::uint32_t>(blocks_.size()) - chain.firstBlock;
  }
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
  // Sweep and prune on the rings' boxes, grown by ε (a vertex within ε of an edge touches it):
  // sorted by left side, each ring meets only the rings that start before it ends.
  const auto rings = static_cast<std::uint32_t>(inRings_.size());
  ringOrder_.resize(rings);
  for (std::uint32_t i = 0; i < rings; ++i)
    ringOrder_[i] = i;
  std::sort(ringOrder_.begin(), ringOrder_.end(), [this](std::uint32_t a, std::uint32_t b) {
    return inChains_[a].box.min.x < inChains_[b].box.min.x;
  });
  for (std::uint32_t i = 0; i < rings; ++i) {
    const Box a = geometry::grown(inChains_[ringOrder_[i]].box, tolerance_);
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
  collect(ringA, geometry::grown(inChains_[ringB].box, tolerance_), candidatesA_);
  collect(ringB, geometry::grown(inChains_[ringA].box, tolerance_), candidatesB_);
  for (const std::uint32_t e : candidatesA_) {
    const Box be = geometry::grown(segmentBox(inVertices_[e], inVertices_[inNext_[e]]), tolerance_);
    for (const std::uint32_t f : candidatesB_) {
      if (geometry::overlaps(be, segmentBox(inVertices_[f], inVertices_[inNext_[f]])))
        intersectEdges(e, f);
    }
  }
}

void Occluders::intersectEdges(std::uint32_t e, std::uint32_t f) {
  const Vec2 a = inVertices_[e], b = inVertices_[inNext_[e]];
  const Vec2 c = inVertices_[f], d = inVertices_[inNext_[f]];
  // An endpoint within ε of the other edge lies on it: the edge is split there, at the vertex
  // itself. Exact orientation alone would let a vertex an ulp off an edge pass it by, and the
  // sweep would then find the vertex's pieces and that edge crossing by a hair.
  const double eps2 = tolerance_ * tolerance_;
  const bool cOnE = geometry::squaredDistanceToSegment(c, a, b) <= eps2;
  const bool dOnE = geometry::squaredDistanceToSegment(d, a, b) <= eps2;
  const bool aOnF = geometry::squaredDistanceToSegment(a, c, d) <= eps2;
  const bool bOnF = geometry::squaredDistanceToSegment(b, c, d) <= eps2;
  if (cOnE) addSplit(e, c, true);
  if (dOnE) addSplit(e, d, true);
  if (aOnF) addSplit(f, a, true);
  if (bOnF) addSplit(f, b, true);
  if (cOnE + dOnE + aOnF + bOnF >= 2) {
    // They run along each other between two such endpoints (or merely share one): the pieces
    // there now have the same endpoints, and findTwins() looks for them.
    collinearPairs_.push_back(std::uint64_t{e} << 32 | f);
    return;
  }
  // Otherwise they may still cross properly, even with one endpoint touching (a sliver at a
  // tiny angle); a crossing within ε of that endpoint is dropped by addSplit on the edge it
  // ends and merged into the endpoint's split on the other.
  if (geometry::orientSign(a, b, c) * geometry::orientSign(a, b, d) >= 0) return;
  if (geometry::orientSign(c, d, a) * geometry::orientSign(c, d, b) >= 0) return;
  // The parameter as a ratio of distances to the other line stays in [0, 1] and well
  // conditioned.
  const double da = geometry::orient(c, d, a), db = geometry::orient(c, d, b);
  const Vec2 x = lerp(a, b, std::clamp(da / (da - db), 0.0, 1.0));
  addSplit(e, x, false);
  addSplit(f, x, false);
}

void Occluders::addSplit(std::uint32_t edge, Vec2 point, bool exact) {
  const Vec2 a = inVertices_[edge], b = inVertices_[inNext_[edge]];
  const double eps2 = tolerance_ * tolerance_;
  if (norm2(point - a) <= eps2 || norm2(point - b) <= eps2) return;
  const double t = dot(point - a, b - a) / norm2(b - a);
  if (!(t > 0.0 && t < 1.0)) return;  // a collinear neighbour's endpoint outside this edge
  splits_.push_back({edge, t, point, exact});
}

void Occluders::unifyCoincidentSplits() {
  // Where several edges cross at (nearly) one point, every pair computes its own crossing, and
  // the results differ by an ulp or so. Every chain through that point must take one and the
  // same vertex there: pieces meeting at points an ulp apart cross each other by a hair, and
  // the sweep's order of active edges breaks at such a point (three rings crossing at one
  // point hid a target behind an obstacle it is in front of). So splits closer than ε are
  // grouped, transitively, over the whole arrangement, and each group takes the point that
  // preferred() picks among its members. Neighbours are found in a grid of ε-cells: sorted
  // by cell, each split looks into its own cell and the four after it.
  const auto count = static_cast<std::uint32_t>(splits_.size());
  const double eps2 = tolerance_ * tolerance_;
  splitCells_.resize(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const Vec2 q = (splits_[i].point - box_.min) / tolerance_;
    splitCells_[i] = {static_cast<std::int64_t>(std::floor(q.x)),
                      static_cast<std::int64_t>(std::floor(q.y)), i};
  }
  std::sort(splitCells_.begin(), splitCells_.end());
  splitGroup_.resize(count);
  for (std::uint32_t i = 0; i < count; ++i)
    splitGroup_[i] = i;
  const auto root = [this](std::uint32_t x) {
    while (splitGroup_[x] != x)
      x = splitGroup_[x] = splitGroup_[splitGroup_[x]];
    return x;
  };
  const auto joinWithin = [&](std::uint32_t i, std::int64_t cx, std::int64_t cy0, std::int64_t cy1,
                              auto from) {
    const SplitCell low{cx, cy0, 0};
    for (auto it = std::lower_bound(from, splitCells_.end(), low);
         it != splitCells_.end() && it->x == cx && it->y <= cy1; ++it) {
      if (it->split == i || norm2(splits_[it->split].point - splits_[i].point) > eps2) continue;
      splitGroup_[root(it->split)] = root(i);
    }
  };
  for (auto cell = splitCells_.begin(); cell != splitCells_.end(); ++cell) {
    // Cells are ε wide, so a neighbour closer than ε is at most one cell away; the cells before
    // this one in the order have already looked at it.
    joinWithin(cell->split, cell->x, cell->y, cell->y + 1, cell + 1);
    joinWithin(cell->split, cell->x + 1, cell->y - 1, cell->y + 1, cell + 1);
  }
  // Each group's point: the member preferred over all others, then copied to every member.
  for (std::uint32_t i = 0; i < count; ++i) {
    Split& best = splits_[root(i)];
    const Split& s = splits_[i];
    if (preferred(s.point, s.exact, best.point, best.exact)) {
      best.point = s.point;
      best.exact = s.exact;
    }
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    const Split& best = splits_[root(i)];
    splits_[i].point = best.point;
    splits_[i].exact = best.exact;
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
      for (; split != splits_.end() && split->edge == e; ++split) {
        // Several edges crossing here: their splits are one group with one point, and one
        // vertex. A group that ended up within ε of the input vertex gives way to it.
        if (norm2(split->point - vertices_.back()) <= eps2) continue;
        vertices_.push_back(split->point);
        inputEdgeOfPiece_.push_back(e);
        t0_.push_back(split->t);
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
  hasTwins_.assign(pieces, 0);
  for (std::uint32_t i = 0; i < pieces; ++i) {
    const std::uint32_t root = findTwinRoot(i);
    isRepresentative_[i] = root == i;
    if (root != i) hasTwins_[i] = hasTwins_[root] = 1;
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
