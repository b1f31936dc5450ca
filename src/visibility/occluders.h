#pragma once
// createSegments(T, O, B) — Algorithm 1, line 1 (paper section IV-B): every edge of the
// boundary, the obstacles and the targets of one World, as one planar arrangement that all
// cameras of that instant share.
//
// Objects of a moving scene may overlap each other or poke through the boundary, so edges of
// different rings may cross. The sweep's active-edge order is only meaningful for edges that
// do not cross, so here each edge is split where an edge of another ring crosses or touches
// it (bounding boxes first, so disjoint objects cost nothing). Edges that run along each other
// become identical pieces; one of them stands for all ("twins"), so a target edge lying on an
// obstacle's edge or on the boundary is seen as the definition says (the open segment from
// the camera crosses no edge). Each ring is assumed simple, as the scene loader checks.
#include <compare>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "visibility/piece_blocks.h"

namespace camcov::visibility {

enum class RingKind : std::uint8_t { Boundary, Obstacle, Target };

// One ring of the World as a closed chain of pieces. Piece i runs from vertex i to vertex
// next(i); vertices of a chain are contiguous in Occluders::vertices().
struct Chain {
  std::uint32_t first = 0;  // first vertex
  std::uint32_t count = 0;  // vertices, and pieces
  RingKind kind = RingKind::Boundary;
  // The solid side of every piece: left for a counter-clockwise object, right for a
  // counter-clockwise boundary (its outside). Taken from the ring's signed area, so a ring of
  // the wrong orientation still occludes correctly.
  bool solidOnLeft = false;
  std::uint32_t owner = 0;  // index into World::obstacles or World::targets
  geometry::Box box;        // of the chain's vertices
  // Its pieces in blocks (Occluders::blocks()), for a long chain; none for a short one.
  std::uint32_t firstBlock = 0, blockCount = 0;
};

class Occluders {
 public:
  Occluders() = default;
  explicit Occluders(const kinematics::World& world) { build(world); }

  // Rebuilds from `world`, reusing this object's memory. O(n log n + k·m) for n edges, where
  // k·m counts edge pairs of rings whose bounding boxes overlap.
  void build(const kinematics::World& world);

  std::span<const Chain> chains() const { return chains_; }
  std::span<const geometry::Vec2> vertices() const { return vertices_; }
  std::uint32_t pieceCount() const { return static_cast<std::uint32_t>(vertices_.size()); }
  std::uint32_t next(std::uint32_t piece) const { return next_[piece]; }
  // Twins: a piece with the same endpoints as a piece with a smaller index (in either
  // direction) is not swept; the representative carries the target pieces of all its twins.
  bool isRepresentative(std::uint32_t piece) const { return isRepresentative_[piece] != 0; }
  // The piece has twins (pieces of other rings with the same endpoints).
  bool hasTwins(std::uint32_t piece) const { return hasTwins_[piece] != 0; }
  struct Member {
    std::uint32_t piece;
    bool reversed;  // runs against the representative: parameter s there is 1 − s here
  };
  // Target pieces seen wherever this piece is seen (itself first, if a target piece).
  std::span<const Member> targetMembers(std::uint32_t piece) const {
    return {members_.data() + memberBegin_[piece], members_.data() + memberBegin_[piece + 1]};
  }

  // For target pieces: which target edge it lies on (see targetEdgeOffset; other pieces give
  // kNoEdge), and the parameter range [t0, t1] it covers on that edge (0 at the edge's first
  // vertex, 1 at the next).
  static constexpr std::uint32_t kNoEdge = 0xffffffffu;
  std::uint32_t globalEdge(std::uint32_t piece) const { return globalEdge_[piece]; }
  double t0(std::uint32_t piece) const { return t0_[piece]; }
  double t1(std::uint32_t piece) const { return t1_[piece]; }

  // A long chain's pieces in runs, each with its box and the cone of its directions; empty for
  // a chain shorter than kMinBlockedChain.
  std::span<const PieceBlock> blocks(const Chain& chain) const {
    return std::span<const PieceBlock>(blocks_).subspan(chain.firstBlock, chain.blockCount);
  }

  // The ring a piece belongs to. O(log rings).
  const Chain& chainOf(std::uint32_t piece) const;
  // The edge of the World's ring the piece lies on: from vertex ringEdge(piece) of that ring
  // (the chain's owner) to the next one.
  std::uint32_t ringEdge(std::uint32_t piece) const {
    return inRingEdge_[inputEdgeOfPiece_[piece]];
  }

  // Target edges are numbered globally: edge e of target i is targetEdgeOffset(i) + e.
  std::uint32_t targetCount() const {
    return static_cast<std::uint32_t>(targetOffsets_.size()) - 1;
  }
  std::uint32_t targetEdgeOffset(std::uint32_t target) const { return targetOffsets_[target]; }
  std::uint32_t targetEdgeCount() const { return targetOffsets_.back(); }
  // Endpoints of a target edge as given in the World.
  geometry::Vec2 targetEdgeStart(std::uint32_t globalEdge) const {
    return targetVertices_[globalEdge];
  }
  geometry::Vec2 targetEdgeEnd(std::uint32_t globalEdge) const {
    return targetVertices_[targetNext_[globalEdge]];
  }

  // Different for every build() of every Occluders in the process: what a query's caches built
  // from this arrangement (OcclusionCulling's grid) are keyed on.
  std::uint64_t buildId() const { return buildId_; }

  // The World's bounding box.
  const geometry::Box& box() const { return box_; }
  // Side of the World's bounding box (at least 1e-300): the scale of every tolerance.
  double extent() const { return extent_; }
  // ε: two points closer than this are the same point. A camera within ε of an edge or vertex
  // is on it and sees only the free side; a target edge whose supporting line passes within ε
  // of the camera is seen edge-on (zero length). ε = kRelativeTolerance · extent().
  double tolerance() const { return tolerance_; }
  static constexpr double kRelativeTolerance = 1e-12;

 private:
  struct Split {
    std::uint32_t edge;  // input edge (index into input vertices)
    double t;            // parameter along it
    geometry::Vec2 point;
    bool exact;  // an input vertex, not a computed crossing
  };
  struct InputRing {
    std::uint32_t first, count;
  };
  // A split's cell in a grid of ε-squares over the World's box, for finding its neighbours.
  struct SplitCell {
    std::int64_t x, y;
    std::uint32_t split;
    auto operator<=>(const SplitCell&) const = default;
  };

  void addRing(const geometry::Ring& ring, RingKind kind, std::uint32_t owner);
  void findSplits();
  void intersectRings(std::uint32_t ringA, std::uint32_t ringB);
  void intersectEdges(std::uint32_t e, std::uint32_t f);
  void addSplit(std::uint32_t edge, geometry::Vec2 point, bool exact);
  void unifyCoincidentSplits();
  void buildChains();
  void findTwins();
  std::uint32_t findTwinRoot(std::uint32_t piece);
  void buildBlocks();

  // Input: the World's rings without repeated consecutive vertices.
  std::vector<geometry::Vec2> inVertices_;
  std::vector<std::uint32_t> inNext_;
  std::vector<std::uint32_t> inRingEdge_;  // k of the input edge: vertex k to k + 1 of its ring
  std::vector<InputRing> inRings_;
  std::vector<Chain> inChains_;  // chain attributes per input ring (first/count set later)
  std::vector<std::uint32_t> ringOrder_;
  std::vector<std::uint32_t> candidatesA_, candidatesB_;
  std::vector<Split> splits_;
  std::vector<std::uint64_t> collinearPairs_;  // input edges that overlap along a line
  std::vector<SplitCell> splitCells_;
  std::vector<std::uint32_t> splitGroup_;  // union-find over splits closer than ε

  // Output arrangement.
  std::vector<Chain> chains_;
  std::vector<geometry::Vec2> vertices_;
  std::vector<std::uint32_t> next_;
  std::vector<std::uint32_t> inputEdgeOfPiece_;
  std::vector<std::uint32_t> globalEdge_;
  std::vector<double> t0_, t1_;
  std::vector<std::uint8_t> isRepresentative_;
  std::vector<std::uint8_t> hasTwins_;
  std::vector<std::uint32_t> twinOf_;
  std::vector<std::uint8_t> twinReversed_;  // relative to its representative
  std::vector<std::uint32_t> memberBegin_, memberCursor_;
  std::vector<Member> members_;
  std::vector<PieceBlock> blocks_;

  std::vector<std::uint32_t> targetOffsets_{0};
  std::vector<geometry::Vec2> targetVertices_;
  std::vector<std::uint32_t> targetNext_;

  std::uint64_t buildId_ = 0;
  geometry::Box box_;
  double extent_ = 1.0;
  double tolerance_ = kRelativeTolerance;
};

}  // namespace camcov::visibility
