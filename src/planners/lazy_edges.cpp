#include "planners/lazy_edges.h"

#include <algorithm>
#include <limits>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/astar_search.hpp>
#include <boost/graph/filtered_graph.hpp>
#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/vector_property_map.hpp>

namespace camcov::planners {

namespace {

// As PRM's roadmap: vertices and each vertex's edges in vectors, in the order added; the edges
// themselves in a vector too (never removed), not one allocation each.
using Graph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                          boost::property<boost::edge_index_t, std::size_t>, boost::no_property,
                          boost::vecS>;
using Edge = boost::graph_traits<Graph>::edge_descriptor;

struct FoundGoal {};

// Stops the search when the goal is taken from the queue.
struct GoalVisitor : boost::default_astar_visitor {
  LazyEdges::Vertex goal;
  explicit GoalVisitor(LazyEdges::Vertex g) : goal(g) {}
  template <typename G>
  void examine_vertex(LazyEdges::Vertex u, const G&) const {
    if (u == goal) throw FoundGoal{};
  }
};

}  // namespace

struct LazyEdges::Impl {
  struct Pair {
    Vertex near, added;
    std::optional<bool> valid;
    std::optional<double> cost;
  };

  Valid validOf;
  Cost costOf;
  Graph graph;
  std::vector<Pair> pairs;  // by edge index
  std::size_t checked = 0;

  bool valid(const Edge& e) {
    Pair& p = pairs[boost::get(boost::edge_index, graph, e)];
    if (!p.valid) {
      p.valid = validOf(p.near, p.added);
      ++checked;
    }
    return *p.valid;
  }
  double cost(const Edge& e) {
    Pair& p = pairs[boost::get(boost::edge_index, graph, e)];
    if (!p.cost) p.cost = costOf(p.near, p.added);
    return *p.cost;
  }

  struct IsValid {
    Impl* edges = nullptr;
    bool operator()(const Edge& e) const { return edges->valid(e); }
  };
  struct CostOf {
    Impl* edges = nullptr;
    double operator()(const Edge& e) const { return edges->cost(e); }
  };
};

LazyEdges::LazyEdges(Valid valid, Cost cost) : impl_(std::make_unique<Impl>()) {
  impl_->validOf = std::move(valid);
  impl_->costOf = std::move(cost);
}

LazyEdges::~LazyEdges() = default;

void LazyEdges::propose(Vertex near, Vertex added) {
  while (boost::num_vertices(impl_->graph) <= std::max(near, added))
    boost::add_vertex(impl_->graph);
  boost::add_edge(near, added, impl_->pairs.size(), impl_->graph);
  impl_->pairs.push_back({near, added, std::nullopt, std::nullopt});
}

std::optional<std::vector<LazyEdges::Vertex>> LazyEdges::shortestPath(Vertex start, Vertex goal,
                                                                      std::size_t vertices,
                                                                      const Heuristic& heuristic) {
  Graph& graph = impl_->graph;
  while (boost::num_vertices(graph) < std::max({vertices, start + 1, goal + 1}))
    boost::add_vertex(graph);
  const boost::filtered_graph<Graph, Impl::IsValid> valid(graph, Impl::IsValid{impl_.get()});
  boost::vector_property_map<Vertex> previous(boost::num_vertices(graph));
  // OMPL's PRM::constructSolution, with an objective whose costs add and compare as numbers.
  try {
    boost::astar_search(
        valid, start, [&heuristic](Vertex v) { return heuristic(v); },
        boost::predecessor_map(previous)
            .weight_map(boost::make_function_property_map<Edge>(Impl::CostOf{impl_.get()}))
            .distance_compare([](double a, double b) { return a < b; })
            .distance_combine([](double a, double b) { return a + b; })
            .distance_inf(std::numeric_limits<double>::infinity())
            .distance_zero(0.0)
            .visitor(GoalVisitor(goal)));
  } catch (const FoundGoal&) {
  }
  if (previous[goal] == goal) return std::nullopt;
  std::vector<Vertex> path;
  for (Vertex v = goal; previous[v] != v; v = previous[v])
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
