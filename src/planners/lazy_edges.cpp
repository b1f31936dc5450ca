#include "planners/lazy_edges.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace camcov::planners {

// The roadmap as PRM's boost graph holds it, without the graph: each vertex's edges in the
// order they were proposed (as an undirected adjacency list lists them), each naming its pair.
// The search is boost's astar_search, step for step (breadth_first_visit with the A* visitor,
// relax() as for an undirected graph, a 4-ary indirect heap on f = g + h), written out over
// these lists: the same vertices taken in the same order, ties included, without the graph's
// descriptors, filters and property maps, which cost most of a search whose edges are known.
struct LazyEdges::Impl {
  struct Incidence {
    std::uint32_t other, pair;
  };
  // What is known of a pair, a byte each: a search reads them for every edge it meets, and
  // they stay in cache where whole records would not.
  enum Fact : std::uint8_t { kChecked = 1, kValid = 2, kCosted = 4 };
  enum class Color : std::uint8_t { White, Gray, Black };

  Valid validOf;
  Cost costOf;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (near, added), as proposed
  std::vector<std::uint8_t> facts;                             // by pair
  std::vector<double> costs;                                   // by pair, where kCosted
  std::size_t checked = 0;

  // Each vertex's incidences in the order their pairs were proposed. The pairs known at a
  // search are packed vertex after vertex (packed[firstOf[v] .. firstOf[v + 1]]), once: a
  // roadmap proposes tens of thousands before its first query. Those proposed later, a query's
  // start and goal joining the roadmap, follow in short lists of their own (later[v]), until
  // they outnumber the packed ones and everything is packed again.
  std::vector<std::uint32_t> firstOf;
  std::vector<Incidence> packed;
  std::vector<std::vector<Incidence>> later;
  std::size_t listed = 0;    // pairs packed or in later lists
  std::size_t vertices = 0;  // one past the largest vertex proposed

  // Lists every pair proposed so far, for a search over n vertices.
  void list(std::size_t n) {
    later.resize(std::max(later.size(), n));
    facts.resize(pairs.size(), 0);
    costs.resize(pairs.size());
    if (pairs.size() - listed <= packed.size() / 2) {
      for (; listed < pairs.size(); ++listed) {
        const auto [near, added] = pairs[listed];
        const auto pair = static_cast<std::uint32_t>(listed);
        later[near].push_back({added, pair});
        later[added].push_back({near, pair});
      }
      return;
    }
    // Counted, then placed: a vertex's incidences in the order of its pairs.
    firstOf.assign(later.size() + 1, 0);
    for (const auto& [near, added] : pairs) {
      ++firstOf[near + 1];
      ++firstOf[added + 1];
    }
    for (std::size_t v = 1; v < firstOf.size(); ++v)
      firstOf[v] += firstOf[v - 1];
    packed.resize(2 * pairs.size());
    std::vector<std::uint32_t> next(firstOf.begin(), firstOf.end() - 1);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const auto [near, added] = pairs[i];
      const auto pair = static_cast<std::uint32_t>(i);
      packed[next[near]++] = {added, pair};
      packed[next[added]++] = {near, pair};
    }
    for (auto& l : later)
      l.clear();
    listed = pairs.size();
  }
  // Vertex u's incidences: its packed ones, then its later ones (a self-pair lists u twice).
  // Nothing is proposed while a search runs, so the lists hold still under it.
  template <typename F>
  void forEachIncidence(Vertex u, F&& f) const {
    if (u + 1 < firstOf.size()) {
      for (std::uint32_t i = firstOf[u]; i < firstOf[u + 1]; ++i)
        f(packed[i]);
    }
    for (const Incidence& e : later[u])
      f(e);
  }

  // The search's state, kept between searches for its buffers.
  std::vector<double> distance, estimate;  // g, and f = g + h (the heap's key)
  std::vector<Vertex> previous;
  std::vector<Color> color;
  std::vector<std::size_t> indexInHeap;
  std::vector<Vertex> heap;

  bool valid(std::uint32_t pair) {
    std::uint8_t& f = facts[pair];
    if (!(f & kChecked)) {
      f |= kChecked | (validOf(pairs[pair].first, pairs[pair].second) ? kValid : 0);
      ++checked;
    }
    return (f & kValid) != 0;
  }
  double cost(std::uint32_t pair) {
    if (!(facts[pair] & kCosted)) {
      costs[pair] = costOf(pairs[pair].first, pairs[pair].second);
      facts[pair] |= kCosted;
    }
    return costs[pair];
  }

  // boost::d_ary_heap_indirect<Vertex, 4, ...> with std::less on `estimate`.
  static constexpr std::size_t kArity = 4;
  static constexpr std::size_t kNotInHeap = std::numeric_limits<std::size_t>::max();
  void push(Vertex v) {
    const std::size_t index = heap.size();
    heap.push_back(v);
    indexInHeap[v] = index;
    siftUp(index);
  }
  void pop() {
    indexInHeap[heap[0]] = kNotInHeap;
    if (heap.size() != 1) {
      heap[0] = heap.back();
      indexInHeap[heap[0]] = 0;
      heap.pop_back();
      siftDown();
    } else {
      heap.pop_back();
    }
  }
  void update(Vertex v) { siftUp(indexInHeap[v]); }
  void siftUp(std::size_t index) {
    if (index == 0) return;
    const std::size_t start = index;
    std::size_t levels = 0;
    const Vertex moving = heap[index];
    const double key = estimate[moving];
    while (index != 0) {
      const std::size_t parent = (index - 1) / kArity;
      if (!(key < estimate[heap[parent]])) break;
      ++levels;
      index = parent;
    }
    index = start;
    for (std::size_t i = 0; i < levels; ++i) {
      const std::size_t parent = (index - 1) / kArity;
      indexInHeap[heap[parent]] = index;
      heap[index] = heap[parent];
      index = parent;
    }
    heap[index] = moving;
    indexInHeap[moving] = index;
  }
  void siftDown() {
    if (heap.empty()) return;
    std::size_t index = 0;
    const double key = estimate[heap[0]];
    const std::size_t size = heap.size();
    for (;;) {
      const std::size_t first = index * kArity + 1;
      if (first >= size) break;
      std::size_t smallest = 0;
      double smallestKey = estimate[heap[first]];
      const std::size_t children = std::min(kArity, size - first);
      for (std::size_t i = 1; i < children; ++i) {
        const double k = estimate[heap[first + i]];
        if (k < smallestKey) {
          smallest = i;
          smallestKey = k;
        }
      }
      if (!(smallestKey < key)) break;
      const Vertex a = heap[first + smallest], b = heap[index];
      heap[first + smallest] = b;
      heap[index] = a;
      indexInHeap[a] = index;
      indexInHeap[b] = first + smallest;
      index = first + smallest;
    }
  }

  // boost::relax for an undirected edge {u, v} met from u, weight w: v through u, else u
  // through v. (boost compares again once a distance is stored, against x87's wider
  // registers; doubles in SSE registers store as computed.)
  bool relax(Vertex u, Vertex v, double w) {
    const double du = distance[u], dv = distance[v];
    if (du + w < dv) {
      distance[v] = du + w;
      previous[v] = u;
      return true;
    }
    if (dv + w < du) {
      distance[u] = dv + w;
      previous[u] = v;
      return true;
    }
    return false;
  }
};

LazyEdges::LazyEdges(Valid valid, Cost cost) : impl_(std::make_unique<Impl>()) {
  impl_->validOf = std::move(valid);
  impl_->costOf = std::move(cost);
}

LazyEdges::~LazyEdges() = default;

void LazyEdges::propose(Vertex near, Vertex added) {
  Impl& s = *impl_;
  // Numbered in 32 bits, a pair's two incidences too: a roadmap has thousands of milestones,
  // tens of thousands of pairs.
  constexpr std::size_t kMost = std::numeric_limits<std::uint32_t>::max();
  if (std::max(near, added) >= kMost || s.pairs.size() >= kMost / 2)
    throw std::length_error("LazyEdges: more vertices or pairs than 32-bit numbers hold");
  s.pairs.emplace_back(static_cast<std::uint32_t>(near), static_cast<std::uint32_t>(added));
  s.vertices = std::max(s.vertices, std::max(near, added) + 1);
}

std::optional<std::vector<LazyEdges::Vertex>> LazyEdges::shortestPath(Vertex start, Vertex goal,
                                                                      std::size_t vertices,
                                                                      const Heuristic& heuristic) {
  Impl& s = *impl_;
  using Color = Impl::Color;
  const std::size_t n = std::max({vertices, start + 1, goal + 1, s.vertices});
  s.list(n);
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  s.distance.assign(n, kInfinity);
  s.estimate.assign(n, kInfinity);
  s.color.assign(n, Color::White);
  s.indexInHeap.assign(n, Impl::kNotInHeap);
  s.previous.resize(n);
  for (Vertex v = 0; v < n; ++v)
    s.previous[v] = v;
  s.heap.clear();
  s.distance[start] = 0.0;
  s.estimate[start] = heuristic(start);
  s.color[start] = Color::Gray;
  s.push(start);
  while (!s.heap.empty()) {
    const Vertex u = s.heap[0];
    s.pop();
    if (u == goal) break;  // taken from the queue: OMPL's PRM stops there
    s.forEachIncidence(u, [&](const Impl::Incidence edge) {
      const Vertex v = edge.other;
      const std::uint32_t pair = edge.pair;
      if (!s.valid(pair)) return;
      const double w = s.cost(pair);
      // As boost's examine_edge: Dijkstra's order holds for weights of at least 0 only.
      if (w < 0.0) throw std::invalid_argument("LazyEdges: an edge with a negative cost");
      const Color c = s.color[v];
      const bool decreased = s.relax(u, v, w);
      if (decreased) s.estimate[v] = s.distance[v] + heuristic(v);
      if (c == Color::White) {
        s.color[v] = Color::Gray;
        s.push(v);
      } else if (c == Color::Gray) {
        if (decreased) s.update(v);
      } else if (decreased) {
        s.push(v);
        s.color[v] = Color::Gray;
      }
    });
    s.color[u] = Color::Black;
  }
  if (s.previous[goal] == goal) return std::nullopt;
  std::vector<Vertex> path;
  for (Vertex v = goal; s.previous[v] != v; v = s.previous[v])
    path.push_back(v);
  path.push_back(start);
  std::reverse(path.begin(), path.end());
  return path;
}

std::size_t LazyEdges::proposed() const {
  return impl_->pairs.size();
}

std::size_t LazyEdges::checked() const {
  return impl_->checked;
}

}  // namespace camcov::planners
