#pragma once
// Motion planning (paper section V-C): one PRM* roadmap in SE(2) per planning event, built
// with the world as it is at that moment and shared by every camera's query (multi-query).
//  - validity: inside the boundary and at least d1 from every target and obstacle;
//  - sampler: with probability p uniform, else the visibility sampler (a point q1 on an
//    object's boundary, its visibility polygon, a valid pose inside it that sees q1);
//  - cost: eq. (10), the mean of 1/reward of a single camera at both ends times OMPL's SE(2)
//    distance (‖Δxy‖ + ½|Δγ|), the reward taken as at most its ceiling λ1 + λ2;
//  - query: A* over the roadmap, guided by the least cost a metre any state can have;
//  - budget: T2 stands for T2 · milestonesPerSecond roadmap milestones, so runs do not
//    depend on the machine (SPEC section 3).
// OMPL's own random numbers are not used: sampling draws from the run's Random, and the
// roadmap's neighbour search is exact and draws nothing (GridNearestNeighbors), so a seed fixes
// the roadmap.
#include <memory>
#include <optional>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "params/parameters.h"
#include "scene/camera.h"
#include "util/random.h"

namespace camcov::planners {

class Roadmap {
 public:
  // Builds the roadmap now (the expensive part), sampled for a camera with `lens`. T2's budget
  // of milestones is for the whole room; a world that is a part of it (camcov-dec's region) is
  // given `share` of the budget, the part's share of the room, so milestones keep their density.
  // Its rewards (eq. (10)'s costs, the sampler's views) judge the objects simplified to within
  // `detail` metres (RewardModel::setDetail), as the method that plans does; its motions are
  // checked against the world as it is.
  Roadmap(const kinematics::World& world, const params::Parameters& params, const scene::Lens& lens,
          std::uint64_t seed, double share = 1.0, double detail = 0.0);
  ~Roadmap();
  Roadmap(const Roadmap&) = delete;
  Roadmap& operator=(const Roadmap&) = delete;

  // A path from start to goal through the roadmap (both ends included), or nullopt if they
  // cannot be connected to one component. Start and goal join the roadmap for later queries.
  std::optional<std::vector<geometry::Pose>> query(const geometry::Pose& start,
                                                   const geometry::Pose& goal);
  std::size_t milestones() const;
  // Is the straight motion between two poses valid at the roadmap's instant?
  bool motionValid(const geometry::Pose& a, const geometry::Pose& b) const;

  // eq. (10) between two poses, for tests and for the cost of a path.
  double cost(const geometry::Pose& a, const geometry::Pose& b) const;
  // A lower bound of eq. (10) summed along any path from a to b: the heuristic of a query's
  // A*, consistent (never more than one motion's cost plus the bound from its end).
  double costLowerBound(const geometry::Pose& a, const geometry::Pose& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace camcov::planners
