#include "visibility/active_edges.h"

#include "geometry/predicates.h"

namespace camcov::visibility {

namespace {

// Is edge a in front of edge b on every ray that crosses both? The viewpoint is strictly
// left of each edge (s → e counter-clockwise around it), so "on the viewpoint's side" of an
// edge's line is orientation > 0. For two edges that do not cross, at least one lies entirely
// on one side of the other's line, and that side decides. Ties (collinear edges, or edges
// crossing by a rounding hair) fall back to the ids, which keeps the order strict.
bool edgeInFront(const PolarEdges::Edge& a, const PolarEdges::Edge& b, std::uint32_t ia,
                 std::uint32_t ib) {
  const int as = geometry::orientSign(b.s, b.e, a.s), ae = geometry::orientSign(b.s, b.e, a.e);
  if (as >= 0 && ae >= 0 && (as | ae) != 0) return true;
  if (as <= 0 && ae <= 0 && (as | ae) != 0) return false;
  if (as == 0 && ae == 0) return ia < ib;
  const int bs = geometry::orientSign(a.s, a.e, b.s), be = geometry::orientSign(a.s, a.e, b.e);
  if (bs >= 0 && be >= 0) return false;
  if (bs <= 0 && be <= 0) return true;
  return ia < ib;
}

// Treap priorities: a multiplicative hash of the id, deterministic and well spread.
std::uint32_t priorityOf(std::uint32_t id) {
  const std::uint32_t x = id * 0x9e3779b1u;
  return x ^ (x >> 16);
}

}  // namespace

bool ActiveEdges::inFront(std::uint32_t a, std::uint32_t b) const {
  const Node &na = nodes_[a], &nb = nodes_[b];
  // Blocked wedges sit at distance zero, in front of every edge.
  const bool wa = na.id >= wedgeBase_, wb = nb.id >= wedgeBase_;
  if (wa || wb) return wa && wb ? na.id < nb.id : wa;
  return edgeInFront(na.edge, nb.edge, na.id, nb.id);
}

bool ActiveEdges::startsInFront(std::uint32_t a, std::uint32_t b) const {
  const Node &na = nodes_[a], &nb = nodes_[b];
  if (nb.id >= wedgeBase_) return false;
  // a starts at a.edge.s on the current ray, where b has its hit: that vertex nearer than the
  // hit (on the viewpoint's side of b's line) puts a in front, and non-crossing edges keep
  // their order over the angles they share. Only a vertex on b's line needs the whole test.
  const int side = geometry::orientSign(nb.edge.s, nb.edge.e, na.edge.s);
  if (side != 0) return side > 0;
  return edgeInFront(na.edge, nb.edge, na.id, nb.id);
}

void ActiveEdges::reset(std::uint32_t idCount, std::uint32_t wedgeBase) {
  wedgeBase_ = wedgeBase;
  slotOf_.resize(idCount);
  nodes_.clear();
  free_.clear();
  root_ = front_ = kNil;
}

std::uint32_t ActiveEdges::allocate(std::uint32_t id, const Edge& edge) {
  std::uint32_t slot;
  if (free_.empty()) {
    slot = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
  } else {
    slot = free_.back();
    free_.pop_back();
  }
  nodes_[slot] = {kNil, kNil, kNil, priorityOf(id), id, edge};
  slotOf_[id] = slot;
  return slot;
}

template <typename InFront>
void ActiveEdges::descendAndLink(std::uint32_t slot, InFront inFront) {
  if (root_ == kNil) {
    root_ = front_ = slot;
    return;
  }
  bool leftmost = true;
  for (std::uint32_t cur = root_;;) {
    const bool left = inFront(cur);
    leftmost = leftmost && left;
    const std::uint32_t next = left ? nodes_[cur].left : nodes_[cur].right;
    if (next == kNil) {
      link(slot, cur, left);
      break;
    }
    cur = next;
  }
  if (leftmost) front_ = slot;
  siftUp(slot);
}

void ActiveEdges::insert(std::uint32_t id, const Edge& edge) {
  const std::uint32_t slot = allocate(id, edge);
  descendAndLink(slot, [this, slot](std::uint32_t other) { return inFront(slot, other); });
}

void ActiveEdges::insertWedge(std::uint32_t id) {
  insert(id, Edge{});
}

void ActiveEdges::insertAt(std::uint32_t id, const Edge& edge) {
  const std::uint32_t slot = allocate(id, edge);
  descendAndLink(slot, [this, slot](std::uint32_t other) { return startsInFront(slot, other); });
}

void ActiveEdges::insertBeside(std::uint32_t id, const Edge& edge, std::uint32_t sibling) {
  const std::uint32_t slot = allocate(id, edge), at = slotOf_[sibling];
  // The free slot next to the sibling: its in-order predecessor's or successor's.
  if (inFront(slot, at)) {
    std::uint32_t cur = nodes_[at].left;
    if (cur == kNil) {
      link(slot, at, true);
    } else {
      while (nodes_[cur].right != kNil)
        cur = nodes_[cur].right;
      link(slot, cur, false);
    }
    if (front_ == at) front_ = slot;
  } else {
    std::uint32_t cur = nodes_[at].right;
    if (cur == kNil) {
      link(slot, at, false);
    } else {
      while (nodes_[cur].left != kNil)
        cur = nodes_[cur].left;
      link(slot, cur, true);
    }
  }
  siftUp(slot);
}

void ActiveEdges::erase(std::uint32_t id) {
  const std::uint32_t slot = slotOf_[id];
  if (front_ == slot) {  // the leftmost has no left child: its successor is below it or up
    std::uint32_t next = nodes_[slot].right;
    if (next == kNil) {
      next = nodes_[slot].parent;
    } else {
      while (nodes_[next].left != kNil)
        next = nodes_[next].left;
    }
    front_ = next;
  }
  // Rotate the node down to a leaf, keeping the heap order on priorities, then cut it off.
  for (;;) {
    const Node& n = nodes_[slot];
    if (n.left == kNil && n.right == kNil) break;
    const bool leftUp =
        n.right == kNil || (n.left != kNil && nodes_[n.left].priority > nodes_[n.right].priority);
    rotateUp(leftUp ? n.left : n.right);
  }
  setChild(nodes_[slot].parent, slot, kNil);
  free_.push_back(slot);
}

void ActiveEdges::replace(std::uint32_t oldId, std::uint32_t newId, const Edge& edge) {
  const std::uint32_t slot = slotOf_[oldId];
  nodes_[slot].id = newId;
  nodes_[slot].edge = edge;
  slotOf_[newId] = slot;
}

void ActiveEdges::link(std::uint32_t slot, std::uint32_t parent, bool asLeft) {
  nodes_[slot].parent = parent;
  (asLeft ? nodes_[parent].left : nodes_[parent].right) = slot;
}

void ActiveEdges::setChild(std::uint32_t parent, std::uint32_t old, std::uint32_t child) {
  if (parent == kNil) {
    root_ = child;
  } else if (nodes_[parent].left == old) {
    nodes_[parent].left = child;
  } else {
    nodes_[parent].right = child;
  }
  if (child != kNil) nodes_[child].parent = parent;
}

void ActiveEdges::rotateUp(std::uint32_t x) {
  // x takes its parent p's place; p becomes x's child on the other side.
  const std::uint32_t p = nodes_[x].parent, g = nodes_[p].parent;
  if (nodes_[p].left == x) {
    nodes_[p].left = nodes_[x].right;
    if (nodes_[x].right != kNil) nodes_[nodes_[x].right].parent = p;
    nodes_[x].right = p;
  } else {
    nodes_[p].right = nodes_[x].left;
    if (nodes_[x].left != kNil) nodes_[nodes_[x].left].parent = p;
    nodes_[x].left = p;
  }
  nodes_[p].parent = x;
  setChild(g, p, x);
}

void ActiveEdges::siftUp(std::uint32_t x) {
  while (nodes_[x].parent != kNil && nodes_[nodes_[x].parent].priority < nodes_[x].priority) {
    rotateUp(x);
  }
}

}  // namespace camcov::visibility
