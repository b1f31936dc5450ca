#pragma once
// activeEdges — Algorithm 1, lines 6, 8 and 10 (paper section IV-B): the edges crossing the
// current ray, ordered by distance from the viewpoint along it. Internal to the visibility
// stage.
//
// The paper's priority queue must also remove arbitrary edges, so this is a balanced search
// tree: a treap with priorities hashed from the edge ids (expected depth O(log n),
// deterministic). Removal starts at the edge's node and never searches, so it cannot miss even
// if rounded crossing points made two edges cross by a hair. Nodes hold their edge's endpoints
// and come from a small pool of recycled slots, so the hot data stays in cache and nothing is
// allocated once the pool has grown to the largest active set.
//
// The order does not depend on the ray: for edges that do not cross, "a is in front of b" is
// decided by which side of each other's supporting line they lie on, with the exact
// orientation predicate. An edge inserted at its first vertex v needs less: v's side of the
// other edge's line decides, one orientation test per level of the tree.
#include <cstdint>
#include <vector>

#include "geometry/vec2.h"
#include "visibility/polar_edges.h"

namespace camcov::visibility {

class ActiveEdges {
 public:
  using Edge = PolarEdges::Edge;

  // Empties the tree, for ids below idCount of which those from wedgeBase on are wedges.
  void reset(std::uint32_t idCount, std::uint32_t wedgeBase);
  // Inserts an edge active on the start ray: the general comparison.
  void insert(std::uint32_t id, const Edge& edge);
  // Inserts a blocked wedge: at distance zero, in front of every edge.
  void insertWedge(std::uint32_t id);
  // Inserts an edge at its first vertex, edge.s.
  void insertAt(std::uint32_t id, const Edge& edge);
  // Inserts an edge next to `sibling`, which starts at the same vertex. Only valid when no other
  // edge passes through or starts at that vertex: then nothing can lie between them and the
  // search is skipped.
  void insertBeside(std::uint32_t id, const Edge& edge, std::uint32_t sibling);
  void erase(std::uint32_t id);
  // Puts newId where oldId was, in O(1): valid when newId starts at the vertex where oldId
  // ends and nothing else passes through that vertex, so every other edge keeps its side.
  void replace(std::uint32_t oldId, std::uint32_t newId, const Edge& edge);
  // The current edge (the closest), or PolarEdges::kNone.
  std::uint32_t front() const { return front_ == kNil ? PolarEdges::kNone : nodes_[front_].id; }

 private:
  static constexpr std::uint32_t kNil = 0xffffffffu;
  // Tree links are slot numbers; `id` is the piece or wedge the slot holds.
  struct Node {
    std::uint32_t left, right, parent, priority, id;
    Edge edge;
  };

  bool inFront(std::uint32_t a, std::uint32_t b) const;
  bool startsInFront(std::uint32_t a, std::uint32_t b) const;
  std::uint32_t allocate(std::uint32_t id, const Edge& edge);
  template <typename InFront>
  void descendAndLink(std::uint32_t slot, InFront inFront);
  void link(std::uint32_t slot, std::uint32_t parent, bool asLeft);
  void rotateUp(std::uint32_t x);
  void siftUp(std::uint32_t x);
  void setChild(std::uint32_t parent, std::uint32_t old, std::uint32_t child);

  std::uint32_t wedgeBase_ = 0;
  std::vector<Node> nodes_;            // the slot pool
  std::vector<std::uint32_t> free_;    // recycled slots
  std::vector<std::uint32_t> slotOf_;  // by id, valid while the id is in the tree
  std::uint32_t root_ = kNil;
  std::uint32_t front_ = kNil;
};

}  // namespace camcov::visibility
