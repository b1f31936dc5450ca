#pragma once
// A roadmap's edges checked lazily (after LazyPRM, Bohlin & Kavraki, ICRA 2000), for a roadmap
// whose searches must find what the eagerly checked roadmap would give.
//
// PRM* tries each new milestone with its k nearest, checks each motion and works out each
// valid edge's cost at once, although a query's search looks at a part of the roadmap only.
// Here the pairs PRM* would try are proposed in its order, and whether a pair's motion is valid,
// and its cost, are asked the first time a search looks at it. A search runs over the valid
// pairs alone: the graph it sees is the eager one, edge for edge and in each vertex's order, so
// it takes the same steps and finds the same path, ties included (tests/planners/
// lazy_edges_test.cpp against boost's A* on the eager graph). A path found also says that its
// ends are in one component, which the eager roadmap knows up front; here a search that finds
// none has checked the start's whole component.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace camcov::planners {

class LazyEdges {
 public:
  using Vertex = std::size_t;
  // Asked at most once per proposed pair, (near, added) as proposed.
  using Valid = std::function<bool(Vertex near, Vertex added)>;
  using Cost = std::function<double(Vertex near, Vertex added)>;
  // A lower bound of the cost from a vertex to the search's goal (0 for none: Dijkstra).
  using Heuristic = std::function<double(Vertex)>;

  LazyEdges(Valid valid, Cost cost);
  ~LazyEdges();
  LazyEdges(const LazyEdges&) = delete;
  LazyEdges& operator=(const LazyEdges&) = delete;

  // The pair PRM* tries next: `added`, the new milestone, with `near`.
  void propose(Vertex near, Vertex added);
  // The cheapest path from `start` to `goal` (both included) over the valid pairs among
  // `vertices` vertices, by A* with `heuristic`, stopping when the goal is taken from the queue
  // (as OMPL's PRM does); nullopt if there is none.
  std::optional<std::vector<Vertex>> shortestPath(Vertex start, Vertex goal, std::size_t vertices,
                                                  const Heuristic& heuristic);

  std::size_t proposed() const;  // pairs
  std::size_t checked() const;   // pairs whose motion was asked

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace camcov::planners
