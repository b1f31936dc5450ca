#include "planners/motion_planner.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/ValidStateSampler.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "geometry/same_bits.h"
#include "planners/grid_nearest_neighbors.h"
#include "planners/lazy_edges.h"
#include "planners/se2_distance.h"
#include "planners/state_validity.h"
#include "planners/visibility_sampler.h"
#include "reward/metrics.h"
#include "reward/reward_model.h"

namespace camcov::planners {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

// eq. (10) divides by a single camera's reward; a pose that sees nothing (or is repelled)
// would divide by zero or flip the sign, so the reward is floored here: such poses cost
// 1/kMinReward per metre, hundreds of times more than a pose that sees a target well.
constexpr double kMinReward = 1e-3;
// Sample attempts allowed per milestone before the budget gives up (a world with almost no
// valid space must not loop forever).
constexpr std::size_t kSampleAttemptsPerMilestone = 50;

geometry::Pose toPose(const ob::State* s) {
  const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
  return {se2->getX(), se2->getY(), se2->getYaw()};
}

void fromPose(const geometry::Pose& p, ob::State* s) {
  auto* se2 = s->as<ob::SE2StateSpace::StateType>();
  se2->setXY(p.x, p.y);
  // OMPL's SO(2) is [-π, π): π itself (a camera at 180°) must become -π.
  const double yaw = geometry::wrapAngle(p.yaw);
  se2->setYaw(yaw >= std::numbers::pi ? yaw - 2.0 * std::numbers::pi : yaw);
}

// What the roadmap has worked out about a state's pose: eq. (10)'s state cost, whether it lies
// strictly inside the room, and whether it is clear of the objects; each at most once. OMPL asks
// again for every edge a milestone is tried with (about 25 a milestone), so the answers are kept in
// the state itself (FactfulSE2Space), for the very bits of the pose they were worked out at: a
// state OMPL writes again starts over.
struct PoseFacts {
  std::optional<double> cost;
  std::optional<bool> inside;
  std::optional<bool> clear;  // of every object (StateValidity::clearOfObjects)
};

// Its components are parts of it, so a state is one allocation rather than five (the compound
// state, its array of components, R²'s state and its values, SO(2)'s state): a roadmap makes
// and frees a thousand of them each global step.
struct FactfulState final : ob::SE2StateSpace::StateType {
  FactfulState() {
    xy.values = xyValues;
    slots[0] = &xy;
    slots[1] = &yaw;
    components = slots;
  }
  FactfulState(const FactfulState&) = delete;
  FactfulState& operator=(const FactfulState&) = delete;

  mutable geometry::Pose at{std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0};  // none yet
  mutable PoseFacts facts;

 private:
  ob::RealVectorStateSpace::StateType xy;
  double xyValues[2] = {0.0, 0.0};
  ob::SO2StateSpace::StateType yaw;
  ob::State* slots[2] = {nullptr, nullptr};
};

// SE(2) (R² then SO(2), as SE2StateSpace lays them out) whose states are FactfulStates.
class FactfulSE2Space final : public ob::SE2StateSpace {
 public:
  ob::State* allocState() const override { return new FactfulState(); }
  void freeState(ob::State* state) const override { delete static_cast<FactfulState*>(state); }
};

// The facts of state `s`, whose pose is `p`.
PoseFacts& factsOf(const ob::State* s, const geometry::Pose& p) {
  const auto* state = static_cast<const FactfulState*>(s);
  if (!geometry::sameBits(state->at, p)) {
    state->at = p;
    state->facts = {};
  }
  return state->facts;
}

// Everything the planner's callbacks share: the world at the planning instant.
struct PlanningWorld {
  PlanningWorld(const kinematics::World& w, const params::Parameters& params,
                const scene::Lens& lens, std::uint64_t seed, double detail)
      : world(w),
        validity(params.planner.d1),
        reward(params.reward, std::vector{lens}),
        random(seed),
        uniformProbability(params.planner.p),
        lens(lens),
        box(geometry::boundingBox(world.boundary)) {
    validity.setWorld(world);
    reward.setDetail(detail);
    reward.setWorld(world);
    // The points the sampler looks from lie on the rings its views are swept in.
    objects = reward.world().targets;
    objects.insert(objects.end(), reward.world().obstacles.begin(), reward.world().obstacles.end());
  }

  kinematics::World world;
  StateValidity validity;
  reward::RewardModel reward;
  Random random;
  double uniformProbability;
  scene::Lens lens;
  geometry::Box box;
  std::vector<geometry::Ring> objects;
  VisibilitySampler sampler;
  std::size_t samplesDrawn = 0;
};

// The sampler of section V-C: uniform with probability p, otherwise a pose that sees a point
// of some object's boundary.
class CoverageSampler final : public ob::ValidStateSampler {
 public:
  CoverageSampler(const ob::SpaceInformation* si, PlanningWorld& w) : ValidStateSampler(si), w_(w) {
    name_ = "coverage visibility sampler";
  }

  bool sample(ob::State* state) override {
    ++w_.samplesDrawn;
    std::optional<geometry::Pose> pose;
    if (w_.random.uniform() < w_.uniformProbability) {
      const geometry::Vec2 p{w_.random.uniform(w_.box.min.x, w_.box.max.x),
                             w_.random.uniform(w_.box.min.y, w_.box.max.y)};
      if (w_.validity.isValid(p)) {
        pose = geometry::Pose{p.x, p.y, w_.random.uniform(-std::numbers::pi, std::numbers::pi)};
      }
    } else if (const auto q1 = samplePointOnRings(w_.objects, w_.random)) {
      if (w_.sampler.focus(w_.reward, *q1))
        pose = w_.sampler.sample(w_.random, w_.validity, w_.lens);
    }
    if (!pose) return false;
    fromPose(*pose, state);
    return true;
  }

  bool sampleNear(ob::State* state, const ob::State*, double) override { return sample(state); }

 private:
  PlanningWorld& w_;
};

// Motions checked exactly against the objects (StateValidity::isValidMotion) instead of
// OMPL's sampling at a resolution: faster, and no thin object slips between two samples.
// Whether a milestone is inside the room, and clear of the objects, is worked out once, not once
// per edge tried.
class ExactMotionValidator final : public ob::MotionValidator {
 public:
  ExactMotionValidator(ob::SpaceInformation* si, PlanningWorld& w) : MotionValidator(si), w_(w) {}

  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const geometry::Pose a = toPose(s1), b = toPose(s2);
    const bool ok =
        inside(s1, a) && inside(s2, b) &&
        w_.validity.staysClear(a.position(), b.position(), clear(s1, a) && clear(s2, b));
    ok ? ++valid_ : ++invalid_;
    return ok;
  }

  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& lastValid) const override {
    const bool ok = checkMotion(s1, s2);
    if (!ok) {
      if (lastValid.first != nullptr) si_->copyState(lastValid.first, s1);
      lastValid.second = 0.0;
    }
    return ok;
  }

 private:
  bool inside(const ob::State* s, const geometry::Pose& p) const {
    PoseFacts& facts = factsOf(s, p);
    if (!facts.inside) facts.inside = w_.validity.insideBoundary(p.position());
    return *facts.inside;
  }
  bool clear(const ob::State* s, const geometry::Pose& p) const {
    PoseFacts& facts = factsOf(s, p);
    if (!facts.clear) facts.clear = w_.validity.clearOfObjects(p.position());
    return *facts.clear;
  }

  PlanningWorld& w_;
};

// eq. (10): cost(p1, p2) = ½(1/reward({p1}) + 1/reward({p2})) · (‖Δxy‖ + ½|Δγ|), after OMPL's
// StateCostIntegralObjective. A state's cost is computed once (PoseFacts).
class CoverageCostObjective final : public ob::OptimizationObjective {
 public:
  CoverageCostObjective(const ob::SpaceInformationPtr& si, PlanningWorld& w)
      : OptimizationObjective(si),
        w_(w),
        ceiling_(std::max(reward::rewardCeiling(w.reward.params()), kMinReward)),
        // Shrunk by 1e-9 so that the rounding of the distances never makes the bound exceed a
        // path's cost: the triangle inequality holds to far better than that in doubles.
        leastStateCost_(std::isinf(ceiling_) ? 0.0 : (1.0 - 1e-9) / ceiling_) {
    description_ = "camcov eq. (10): mean inverse single-camera reward times SE(2) distance";
  }

  // The reward is taken within [kMinReward, its ceiling]: the ceiling is the most a camera's
  // reward can be (reward::rewardCeiling, λ1 + λ2), so every state costs at least 1/ceiling.
  // A reward above it, where two targets share a seen edge, costs as the ceiling does.
  ob::Cost stateCost(const ob::State* s) const override {
    const geometry::Pose p = toPose(s);
    PoseFacts& facts = factsOf(s, p);
    if (!facts.cost)
      facts.cost = 1.0 / std::clamp(w_.reward.reward(std::span(&p, 1)), kMinReward, ceiling_);
    return ob::Cost(*facts.cost);
  }

  ob::Cost motionCost(const ob::State* a, const ob::State* b) const override {
    return ob::Cost(0.5 * (stateCost(a).value() + stateCost(b).value()) *
                    se2Distance(toPose(a), toPose(b)));
  }

  // A lower bound of eq. (10) along any path from a to b: each of its motions costs at least
  // the least state cost times its length, and the SE(2) distance is a metric. It is
  // consistent, so the query's A* still finds the cheapest path, and it costs and checks only
  // the milestones whose cost from the start plus this bound is below the path's, not every
  // milestone cheaper to reach than the goal.
  ob::Cost motionCostHeuristic(const ob::State* a, const ob::State* b) const override {
    return ob::Cost(leastStateCost_ * se2Distance(toPose(a), toPose(b)));
  }

 private:
  PlanningWorld& w_;
  double ceiling_;
  double leastStateCost_;
};

// PRM* whose roadmap is grown once and then queried by every camera: start and goal join the
// roadmap as milestones (PRM's own connection step), and A* as PRM's extracts the path. PRM's
// solve() is not used: it grows the roadmap in a second thread until a solution appears,
// which would make the roadmap depend on timing. Its edges are checked lazily (LazyEdges): the
// pairs PRM*'s connection strategy proposes become candidates, and a query's search checks
// the motions and works out the eq. (10) costs of those it looks at, finding PRM*'s paths.
class SharedRoadmap final : public og::PRMstar {
 public:
  explicit SharedRoadmap(const ob::SpaceInformationPtr& si)
      : PRMstar(si),
        edges_(
            [this](Vertex near, Vertex added) {
              return si_->checkMotion(stateProperty_[near], stateProperty_[added]);
            },
            [this](Vertex near, Vertex added) {
              return opt_->motionCost(stateProperty_[near], stateProperty_[added]).value();
            }) {
    setConnectionFilter([this](const Vertex& near, const Vertex& added) {
      edges_.propose(near, added);
      return false;  // PRM* itself connects nothing
    });
  }

  // Exact neighbours from a grid of cells of side `cell` (m) over `box`, with no random pivots
  // (GNAT's); before setup(), which hands them to PRM*'s connection strategy. The grid works
  // out the SE(2) distance itself, as PRM's distanceFunction would.
  void useGridNeighbours(double cell, const geometry::Box& box) {
    nn_ = std::make_shared<GridNearestNeighbors<Vertex>>(
        cell, box, [this](const Vertex v) { return toPose(stateProperty_[v]); });
  }

  std::optional<std::vector<geometry::Pose>> connect(const ob::State* start,
                                                     const ob::State* goal) {
    const Vertex s = addMilestone(si_->cloneState(start));
    const Vertex g = addMilestone(si_->cloneState(goal));
    const auto path = edges_.shortestPath(s, g, milestoneCount(), [this, g](Vertex v) {
      return opt_->motionCostHeuristic(stateProperty_[v], stateProperty_[g]).value();
    });
    if (!path) return std::nullopt;
    std::vector<geometry::Pose> poses;
    for (const Vertex v : *path)
      poses.push_back(toPose(stateProperty_[v]));
    return poses;
  }

 private:
  LazyEdges edges_;
};

}  // namespace

struct Roadmap::Impl {
  Impl(const kinematics::World& world, const params::Parameters& params, const scene::Lens& lens,
       std::uint64_t seed, double share, double detail)
      : w(world, params, lens, seed, detail), space(std::make_shared<FactfulSE2Space>()) {
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0, w.box.min.x);
    bounds.setLow(1, w.box.min.y);
    bounds.setHigh(0, w.box.max.x);
    bounds.setHigh(1, w.box.max.y);
    space->setBounds(bounds);
    si = std::make_shared<ob::SpaceInformation>(space);
    si->setStateValidityChecker([this](const ob::State* s) {
      const auto p = toPose(s);
      return w.validity.isValid(p.position());
    });
    si->setMotionValidator(std::make_shared<ExactMotionValidator>(si.get(), w));
    si->setValidStateSamplerAllocator(
        [this](const ob::SpaceInformation* s) { return std::make_shared<CoverageSampler>(s, w); });
    si->setup();
    objective = std::make_shared<CoverageCostObjective>(si, w);
    auto problem = std::make_shared<ob::ProblemDefinition>(si);
    problem->setOptimizationObjective(objective);
    planner = std::make_shared<SharedRoadmap>(si);
    const auto budget = static_cast<std::size_t>(
        std::ceil(share * (params.planner.T2 * params.planner.milestonesPerSecond)));
    // About four milestones a cell once the roadmap is grown.
    planner->useGridNeighbours(std::sqrt(4.0 * geometry::area(w.box) /
                                         static_cast<double>(std::max<std::size_t>(budget, 1))),
                               w.box);
    planner->setProblemDefinition(problem);
    planner->setup();
    planner->growRoadmap(ob::PlannerTerminationCondition([this, budget] {
      return planner->milestoneCount() >= budget ||
             w.samplesDrawn >= budget * kSampleAttemptsPerMilestone;
    }));
  }

  // f(a, b) of OMPL states of the two poses.
  template <typename F>
  auto onStates(const geometry::Pose& a, const geometry::Pose& b, F&& f) const {
    ob::ScopedState<ob::SE2StateSpace> s(space), g(space);
    fromPose(a, s.get());
    fromPose(b, g.get());
    return f(s.get(), g.get());
  }

  PlanningWorld w;
  std::shared_ptr<ob::SE2StateSpace> space;
  ob::SpaceInformationPtr si;
  std::shared_ptr<CoverageCostObjective> objective;
  std::shared_ptr<SharedRoadmap> planner;
};

Roadmap::Roadmap(const kinematics::World& world, const params::Parameters& params,
                 const scene::Lens& lens, std::uint64_t seed, double share, double detail)
    : impl_(std::make_unique<Impl>(world, params, lens, seed, share, detail)) {}

Roadmap::~Roadmap() = default;

std::optional<std::vector<geometry::Pose>> Roadmap::query(const geometry::Pose& start,
                                                          const geometry::Pose& goal) {
  return impl_->onStates(start, goal, [this](const ob::State* s, const ob::State* g) {
    return impl_->planner->connect(s, g);
  });
}

std::size_t Roadmap::milestones() const {
  return impl_->planner->milestoneCount();
}

bool Roadmap::motionValid(const geometry::Pose& a, const geometry::Pose& b) const {
  return impl_->w.validity.isValidMotion(a.position(), b.position());
}

double Roadmap::cost(const geometry::Pose& a, const geometry::Pose& b) const {
  return impl_->onStates(a, b, [this](const ob::State* s, const ob::State* g) {
    return impl_->objective->motionCost(s, g).value();
  });
}

double Roadmap::costLowerBound(const geometry::Pose& a, const geometry::Pose& b) const {
  return impl_->onStates(a, b, [this](const ob::State* s, const ob::State* g) {
    return impl_->objective->motionCostHeuristic(s, g).value();
  });
}

}  // namespace camcov::planners
