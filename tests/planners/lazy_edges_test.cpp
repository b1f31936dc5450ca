// The lazily checked roadmap against the eager one it stands for: random roadmaps grown as
// PRM* grows them (each new vertex proposed with its nearest earlier ones), with invalid
// motions, costs that tie, split components, queries between growth and growth between queries,
// searched by LazyEdges and by boost's A* over the eagerly checked graph as OMPL's
// PRM::constructSolution calls it (the independent reference): the same path, vertex for vertex,
// or none for both; every pair asked once at most, and far from all of them asked.
#include "planners/lazy_edges.h"

#include <gtest/gtest.h>

#include <ompl/base/Cost.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <vector>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/astar_search.hpp>
#include <boost/property_map/vector_property_map.hpp>

#include "geometry/vec2.h"
#include "support/splitmix64.h"

namespace camcov::planners {
namespace {

using Vertex = LazyEdges::Vertex;
namespace ob = ompl::base;

// PRM's own graph: valid edges only, each with its cost, in the order they were added.
using EagerGraph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                          boost::property<boost::edge_weight_t, ob::Cost>>;

struct FoundGoal {};
struct GoalVisitor : boost::default_astar_visitor {
  Vertex goal;
  explicit GoalVisitor(Vertex g) : goal(g) {}
  template <typename G>
  void examine_vertex(Vertex u, const G&) const {
    if (u == goal) throw FoundGoal{};
  }
};

// The reference: PRM::constructSolution's search, with an objective's default cost arithmetic.
std::optional<std::vector<Vertex>> eagerPath(const EagerGraph& g, Vertex start, Vertex goal,
                                             const std::function<double(Vertex)>& heuristic) {
  boost::vector_property_map<Vertex> prev(boost::num_vertices(g));
  try {
    boost::astar_search(
        g, start, [&heuristic](Vertex v) { return ob::Cost(heuristic(v)); },
        boost::predecessor_map(prev)
            .distance_compare([](ob::Cost a, ob::Cost b) { return a.value() < b.value(); })
            .distance_combine(
                [](ob::Cost a, ob::Cost b) { return ob::Cost(a.value() + b.value()); })
            .distance_inf(ob::Cost(std::numeric_limits<double>::infinity()))
            .distance_zero(ob::Cost(0.0))
            .visitor(GoalVisitor(goal)));
  } catch (const FoundGoal&) {
  }
  if (prev[goal] == goal) return std::nullopt;
  std::vector<Vertex> path;
  for (Vertex v = goal; prev[v] != v; v = prev[v])
    path.push_back(v);
  path.push_back(start);
  std::reverse(path.begin(), path.end());
  return path;
}

struct RandomRoadmap {
  testing::SplitMix64 random;
  bool tiedCosts;     // costs of whole units: many paths cost the same
  double validShare;  // of the motions
  bool wall;          // no motion crosses x = 0: two components
  std::vector<geometry::Vec2> points;
  std::map<std::pair<Vertex, Vertex>, bool> validOf;
  std::map<std::pair<Vertex, Vertex>, int> asked;

  bool valid(Vertex a, Vertex b) {
    ++asked[{a, b}];
    return validOf.at({a, b});
  }
  double cost(Vertex a, Vertex b) const {
    const double d = geometry::distance(points[a], points[b]);
    return tiedCosts ? std::ceil(d) : d;
  }

  // A new vertex, proposed with its k nearest earlier ones, nearest first (PRM*'s k).
  void grow(LazyEdges& lazy, EagerGraph& eager) {
    const Vertex m = points.size();
    points.push_back({random.uniform(0, 100), random.uniform(0, 100)});
    boost::add_vertex(eager);
    std::vector<Vertex> near(m);
    std::iota(near.begin(), near.end(), Vertex{0});
    std::stable_sort(near.begin(), near.end(), [&](Vertex a, Vertex b) {
      return geometry::distance(points[a], points[m]) < geometry::distance(points[b], points[m]);
    });
    const auto k = static_cast<std::size_t>(std::ceil(4.0 * std::log(double(m + 1))));
    near.resize(std::min(near.size(), k));
    for (const Vertex n : near) {
      const bool crosses = wall && (points[n].x < 50) != (points[m].x < 50);
      validOf[{n, m}] = !crosses && random.uniform(0, 1) < validShare;
      lazy.propose(n, m);
      if (validOf[{n, m}]) boost::add_edge(n, m, ob::Cost(cost(n, m)), eager);
    }
  }
};

TEST(LazyEdges, FindThePathsOfTheEagerlyCheckedRoadmapAndCheckFewOfItsEdges) {
  std::size_t firstProposed = 0, firstChecked = 0, found = 0, none = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    SCOPED_TRACE(seed);
    RandomRoadmap r{{seed}, seed % 2 == 0, seed % 3 == 0 ? 1.0 : 0.75, seed % 5 == 0, {}, {}, {}};
    LazyEdges lazy([&r](Vertex a, Vertex b) { return r.valid(a, b); },
                   [&r](Vertex a, Vertex b) { return r.cost(a, b); });
    EagerGraph eager;
    for (int i = 0; i < 300; ++i)
      r.grow(lazy, eager);
    for (int query = 0; query < 8; ++query) {
      // The roadmap grows by more than it had between two queries (its pairs are listed
      // afresh), or by a query's start and goal only.
      if (query == 5) {
        for (int i = 0; i < 400; ++i)
          r.grow(lazy, eager);
      }
      // Start and goal join the roadmap, as a query's do.
      r.grow(lazy, eager);
      r.grow(lazy, eager);
      const Vertex start = r.points.size() - 2, goal = r.points.size() - 1;
      const bool guided = query % 2 == 1;  // A* with the straight-line bound, else Dijkstra
      const auto heuristic = [&](Vertex v) {
        return guided ? std::floor(geometry::distance(r.points[v], r.points[goal])) * 0.999 : 0.0;
      };
      const auto want = eagerPath(eager, start, goal, heuristic);
      const auto got = lazy.shortestPath(start, goal, r.points.size(), heuristic);
      ASSERT_EQ(want.has_value(), got.has_value()) << "query " << query;
      if (want) {
        EXPECT_EQ(*want, *got) << "query " << query;
      }
      ++(want ? found : none);
      if (query == 0) {
        firstProposed += lazy.proposed();
        firstChecked += lazy.checked();
      }
    }
    for (const auto& [pair, times] : r.asked)
      ASSERT_EQ(times, 1) << pair.first << "-" << pair.second;
    EXPECT_EQ(lazy.checked(), r.asked.size());
  }
  EXPECT_GT(found, 300u);
  EXPECT_GT(none, 20u);  // the walled roadmaps, and starts with no valid motion
  // A query's search looks at the part of the roadmap nearer than its goal.
  EXPECT_LT(firstChecked, firstProposed * 3 / 4) << firstChecked << " of " << firstProposed;
}

}  // namespace
}  // namespace camcov::planners
