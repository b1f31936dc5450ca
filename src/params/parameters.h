#pragma once
// Every tunable of the method in one place, Table I of the paper as defaults (SPEC section 5),
// plus the simulation settings of SPEC section 3. The field table in parameter_table.h
// declares each one's key, symbol, unit and valid range once; JSON, --set and the report all
// read that table.
#include <limits>

namespace camcov::params {

// Reward, eq. (5)-(8).
struct RewardParams {
  double lambda1 = 1.0;  // λ1, weight of coverage eq. (3)
  double lambda2 = 0.2;  // λ2, weight of utilization eq. (5)
  double lambda3 = 1.0;  // λ3, weight of repulsion eq. (6)
  double d2 = 2.0;       // d2, m, sensing radius of invdist eq. (7)
  // Our extension: coverage eq. (3) weighs each metre of target boundary by its importance
  // (the scene's edgeWeights and frontWeight); off, every metre the same. No effect on a scene
  // without weights.
  bool weighted = true;
  // Our extension (the paper's future work on resolution): coverage eq. (3) counts each point
  // of boundary by its credit min(1, ρ/ρ_min) at the scene's ρ_min (resolution_coverage.h), so
  // that the optimizers place cameras near enough and face-on. Unweighted; no effect on a scene
  // without a resolution requirement.
  bool resolution = false;
};

// Global optimization, Algorithm 2 and its trigger (section V-A).
struct GlobalParams {
  int K = 500;       // K, samples per camera
  double T1 = 5.0;   // T1, s, period of global optimization
  double tau = 1.2;  // τ, factor by which the global reward must beat the current one
  // Our extension (0 = the paper's rule): H, s. The global reward is discounted by the time
  // the slowest camera needs to reach its goal, reward · max(0, 1 − travel / H), before the
  // comparison with τ · current, so slow cameras do not chase goals that will have moved on
  // by the time they arrive (it costs static scenes with slow cameras; see the docs).
  double horizon = 0.0;
};

// Local optimization, gradient ascent (section V-E).
struct LocalParams {
  double epsilon = 1e-6;  // ε, numerical-gradient step (m for x, y; rad for γ)
  double alpha = 0.5;     // α, gradient step size for translation
  double beta = 0.005;    // β, gradient step size for rotation
};

// Motion planning, PRM* (section V-C).
struct PlannerParams {
  double p = 0.1;   // p, probability of a uniform sample instead of the visibility sampler
  double T2 = 0.5;  // T2, s, planning time budget (charged as milestones, see below)
  double d1 = 1.0;  // d1, m, clearance from every object for a state to be valid
  double milestonesPerSecond = 2000.0;  // roadmap milestones that stand for one second of T2
};

// Execution with artificial potentials (section V-D).
struct PotentialParams {
  double lambda4 = 1.0;  // λ4, weight of the attractive force eq. (11)
  double lambda5 = 1.0;  // λ5, weight of the repulsive force eq. (11)
  double T3 = 2.0;       // T3, s, abort a plan after this long without progress
};

// Simulation (SPEC section 3).
struct SimParams {
  double dt = 0.1;         // s, fixed time step
  double duration = 30.0;  // s, simulated time per run (the paper's 30 s)
  double delta = 0.5;      // δ, m, distance below which a camera is in collision
};

// The safety layer between every controller and the simulator (our extension; src/safety/):
// constraints 1 and 2 of Problems 2.2/2.3 (keep δ from every object and camera) enforced on
// the commanded velocities instead of only discouraged by the reward's repulsion, eq. (9).
struct SafetyParams {
  bool enabled = true;   // off: commands reach the simulator unchanged (the paper's behaviour)
  double margin = 0.1;   // m, kept beyond δ when the layer can (absorbs speed-estimate error)
  double horizon = 0.1;  // s, how far ahead a velocity held constant must keep δ + margin
                         // against objects moving at their observed speeds; at least dt
};

// The choices of camcov's own method (`--method camcov`; docs/method.md, "Our
// method"), which keeps the paper's loop and changes how a global optimization's candidate is
// made, judged and reached. The paper's method ignores them.
struct CamcovParams {
  // Pattern-search evaluations spent on improving each global candidate, camera by camera,
  // before it is judged (0: Algorithm 2's result as it is; measured not to help, so off).
  int refine = 0;
  // Judge a candidate by the coverage the team would average over the next H seconds, the
  // transit along its paths included (timed as V-B estimates), against the same for what the
  // team is committed to. H while anything moves, s:
  double horizon = 15.0;
  // and while nothing has moved in the last step (a static scene), s:
  double staticHorizon = 60.0;
  // Points of the transit at which its coverage is estimated.
  int transitSamples = 4;
  // The candidate must beat the committed team's value by this fraction.
  double margin = 0.02;
  // Go straight to a goal when the straight move is valid, instead of through the roadmap.
  bool straightPaths = true;
  // While following a plan, turn to the yaw (within reach this step) that sees most now, as
  // long as the goal's yaw can still be reached on arrival.
  bool transitYaw = true;
  // Local optimization by compass search (the best of the gradient's step and moves by the
  // step's limit along ±x, ±y, ±γ) instead of the paper's gradient ascent.
  bool compass = true;
  // Credit the committed team also with what it would see if the targets and obstacles went on
  // as they last moved (control/motion_watch.h), taking the better of that and the present.
  bool forecastStay = true;
  // Judge poses in a world whose finely drawn targets and obstacles are redrawn to within this
  // many metres (kinematics/world_simplification.h): a ring of thousands of vertices is swept
  // as one of dozens. 0: as drawn.
  double detail = 0.01;
  // camcov-dec: a camera plans for itself and at most N - 1 teammates, the nearest it believes
  // in (control/neighbourhood.h), so that its work is bounded by its neighbourhood, not by the
  // team. A team of at most N plans as one, as camcov does.
  int neighbours = 8;
  // camcov-dec: a teammate's announced goal is its claim on that spot for this long after it was
  // sent, s; a claimed spot goes to another camera only if that camera bids better (control/
  // goal_assignment.h), and a camera outbid on its goal gives it up. 0: no claims.
  double claims = 0.0;
  // camcov-dec: a camera plans with the teammates it has heard of only, not with one never heard
  // believed where the scene starts it.
  bool heardOnly = false;
  // camcov-dec under limited knowledge: a camera's loop moves it only. It takes its own part of
  // its neighbourhood's plan where that move alone, the teammates where it believes them
  // committed, beats staying, and optimizes locally for itself only; false: it judges the plan
  // as if every teammate took its part, and optimizes their poses with its own.
  bool ownPartOnly = true;
  // camcov-dec in a team larger than N: a camera plans in its neighbourhood's region only
  // (kinematics/world_region.h), the box around its members as it believes them, widened on
  // every side by this many times the box's larger side. inf: in everything it knows.
  double region = 0.5;
};

// What each camera knows (our extension; docs/method.md, "What a camera knows"). Full: every
// method reads the true world at each instant, as the paper assumes. Limited: a camera knows a
// target or obstacle only as it last saw it itself or was told (sim/knowledge.h), and the
// centralized methods read the union of what the team knows (camcov-dec: each camera its own);
// the world the simulator scores is the same.
struct KnowledgeParams {
  bool limited = false;
};

// How cameras tell each other what they know under limited knowledge (sim/communication.h).
struct CommsParams {
  double range =
      std::numeric_limits<double>::infinity();  // m: a receiver farther off hears nothing
  double period = 0.0;   // s between a camera's messages; up to one step: every step
  double latency = 0.0;  // s from sending to hearing
  double loss = 0.0;     // probability that one receiver does not get one message
  int sizeLimit = 0;     // object entries per message, the most recently seen first; 0: no limit
};

struct Parameters {
  RewardParams reward;
  GlobalParams global;
  LocalParams local;
  PlannerParams planner;
  PotentialParams potential;
  SimParams sim;
  SafetyParams safety;
  CamcovParams camcov;
  KnowledgeParams knowledge;
  CommsParams comms;
};

}  // namespace camcov::params
