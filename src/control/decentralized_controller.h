#pragma once
// Our method decentralized (`--method camcov-dec`; docs/method.md, "Decentralized teams"):
// every camera runs our method's loop (PaperController, Variant::Camcov: the global step every
// T1 with its judgement over the horizon, the assignment, the compass local search) on its own
// knowledge only — the world as it saw it or was told (Observation::own), its teammates where
// they last said they were — and follows its own part of the plan it computes. The cameras
// share the run's seed, so where they know the same they compute the same plan: with full
// knowledge (or, once a target is known, messages that reach everyone at every step) each
// camera's part is the one the centralized method gives it, and with full knowledge the team's
// run is camcov's. A camera that knows no target (under limited knowledge) turns on the spot at
// its full rate, looking round for one.
//
// In a team larger than camcov.neighbours (N), each camera's loop plans for its neighbourhood
// only (control/neighbourhood.h): itself and the N - 1 teammates nearest to it as it believes
// them, chosen at t = 0 and again every T1, when its global step is due. A camera whose
// neighbourhood changed starts a new loop for the new one (its global step runs at once and
// judges the plan afresh), so each camera's work per step is bounded by N, not by the team.
//
// With camcov.claims = τ_c > 0 (docs/method.md, "Claims"), the goal a teammate last announced,
// sent less than τ_c ago, is its claim on that spot, bid with its estimated travel time from
// where it announced it: a camera's assignment gives a claimed spot to another camera only if
// that one bids better (ties to the lower index), and a camera that hears a better claim on its
// own goal gives it up and plans again at once. With camcov.heardOnly a camera plans with the
// teammates it has heard of only (chosen again whenever it hears of one more), not with one
// never heard believed where the scene starts it.
//
// Under limited knowledge a camera's loop moves that camera only (camcov.ownPartOnly, the
// default): its global step still plans for the whole neighbourhood, but takes the camera's own
// part only where that move alone, the teammates where it believes them committed, beats
// staying, and its local optimization improves its own pose only. Planning as if the teammates
// took their parts of a plan they never heard of sent cameras across the room at nearly every
// global step (docs/method.md, "One camera's part").
//
// In a team larger than N, a camera's loop plans in its neighbourhood's region
// (camcov.region, kinematics/world_region.h): the box around its members, widened on every side
// by camcov.region times its larger side, the room clipped to it and the objects within. In the
// whole room it knew, a camera sampled poses across the room, sent itself there past the
// teammates nearer to them, and swept every object it had heard of; in its region its work
// follows its neighbourhood, not the team or the room (docs/method.md, "A neighbourhood's
// region").
//
// Events: each camera's own (plans, aborts) and its global decisions, with its index.
//
// The loops of a step are independent (each has its own controller, world and workspace), so
// they run side by side on the run's threads (`camcov run --threads`, util/run_threads.h),
// their commands and events taken in camera order: the same results with any number.
//
// Holds a reference to `scene`: the scene must outlive the controller.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "control/controller.h"
#include "control/paper_controller.h"
#include "kinematics/world.h"
#include "params/parameters.h"
#include "scene/scene.h"

namespace camcov::control {

class DecentralizedController final : public Controller {
 public:
  DecentralizedController(const scene::Scene& scene, const params::Parameters& params,
                          std::uint64_t seed);

  void control(const Observation& observation, std::span<scene::CameraCommand> commands) override;
  std::optional<geometry::Pose> goal(std::size_t camera) const override;
  void takeEvents(std::vector<ControlEvent>& out) override;

 private:
  // Camera j's own loop, over the scene as its neighbourhood plans in it, with its own
  // workspace.
  struct Loop {
    std::vector<std::size_t> members;           // scene camera indices, increasing; j among them
    std::size_t self = 0;                       // j's place in members
    std::unique_ptr<const scene::Scene> scene;  // null: the whole scene's team
    std::unique_ptr<PaperController> controller;
    std::size_t heard = 0;             // camcov.heardOnly: the teammates it had heard of when made
    std::vector<ControlEvent> events;  // this step's, taken in camera order

    std::vector<geometry::Pose> believed;            // scratch: its believedTeam
    std::vector<geometry::Pose> memberPoses;         // scratch: its neighbourhood's poses
    std::vector<scene::CameraCommand> planned;       // scratch: its commands
    std::vector<std::optional<Claim>> claims;        // scratch: heardClaims, by scene camera
    std::vector<std::optional<Claim>> memberClaims;  // scratch: the same, by member
    std::optional<kinematics::World> region;         // scratch: plannedIn's region
    std::vector<ControlEvent> controllerEvents;      // scratch: its controller's
  };
  // Starts camera j's loop afresh for `members`, its first instant at `start` (it plans anew,
  // one step after its first instant as camcov does); its workspace and this step's events
  // stay.
  void startLoop(std::size_t j, std::vector<std::size_t> members, double start);
  // Camera j's step: its neighbourhood chosen again if due (`regroup`) or if it heard of
  // another teammate, then its loop's command.
  void controlCamera(const Observation& observation, std::size_t j, bool regroup,
                     scene::CameraCommand& command);
  // N: camcov.neighbours (at least 1, as the parameter table checks).
  std::size_t neighbourhoodSize() const {
    return static_cast<std::size_t>(std::max(1, params_.camcov.neighbours));
  }
  // camcov.heardOnly under limited knowledge: a camera plans with the teammates it heard of.
  bool heardOnly() const { return params_.camcov.heardOnly && params_.knowledge.limited; }
  // A team larger than N plans in neighbourhoods, chosen again every T1.
  bool inNeighbourhoods() const { return neighbourhoodSize() < scene_.cameras.size(); }
  // camcov.ownPartOnly under limited knowledge, or in neighbourhoods: a camera's loop moves it
  // only. (A team of at most N with full knowledge is camcov's, bit for bit.)
  bool ownPartOnly() const {
    return params_.camcov.ownPartOnly && (params_.knowledge.limited || inNeighbourhoods());
  }
  // The claims camera j has heard and still believes (camcov.claims), into its loop's claims.
  void heardClaims(const OwnKnowledge& own, std::size_t j, double time);
  // Camera j at `pose`, heading for its loop's goal: if a claim it heard outbids it there, it
  // gives the goal up.
  void yieldIfOutbid(std::size_t j, const geometry::Pose& pose, double time);

  // What camera j's loop plans in, the members at their memberPoses: in a team larger than N,
  // its neighbourhood's region (camcov.region) where that holds a target it knows, else
  // `known`.
  const kinematics::World& plannedIn(const kinematics::World& known, Loop& loop) const;

  const scene::Scene& scene_;
  params::Parameters params_;
  std::uint64_t seed_;
  std::vector<Loop> loops_;
  double nextRegroupTime_;  // when neighbourhoods are chosen again
  std::vector<ControlEvent> events_;
};

}  // namespace camcov::control
