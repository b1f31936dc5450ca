#pragma once
// The deterministic simulator (SPEC section 3): fixed dt, the controller sees only the
// present, commands are saturated to each camera's limits, passed through the safety layer
// (src/safety/) and integrated (ṗ_j = u_j), cameras are kept inside the boundary, and every
// step is measured — at the samples and, for distances and contacts, in continuous time over
// the step — and handed to a recorder. Computation takes no simulated time, so a run depends
// only on its inputs.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "control/controller.h"
#include "params/parameters.h"
#include "reward/metrics.h"
#include "scene/scene.h"
#include "sim/communication.h"

namespace camcov::sim {

// Everything measured at one step; spans are valid only during Recorder::step().
struct StepRecord {
  int index = 0;
  double time = 0.0;
  reward::RewardTerms terms;
  // Coverage with resolution (reward/resolution_coverage.h) of a scene that asks for it
  // (scene::Scene::resolution); 0 elsewhere.
  double resolutionCoverage = 0.0;
  std::span<const geometry::Pose> cameras;
  std::span<const std::optional<geometry::Pose>> goals;
  double minObjectDistance = 0.0;  // closest camera to any target or obstacle, m, at t
  double minCameraDistance = 0.0;  // closest pair of cameras, m (infinity for one camera), at t
  // Over the step that ended at t, in continuous time (at step 0: the samples above).
  double minObjectDistanceInStep = 0.0;
  double minCameraDistanceInStep = 0.0;
  double avoidableContactTime = 0.0;    // s closer than δ that the safety layer could avoid
  double unavoidableContactTime = 0.0;  // s closer than δ in unavoidable contacts
  // Targets present at t, where they come and go (scene::Scene::hasPresenceWindows); else −1.
  int targetsPresent = -1;
  // Raised since the last step: contacts that began in the step that ended at t, targets
  // appearing or leaving, commands at t that are not finite, then the controller's events at t.
  std::span<const control::ControlEvent> events;
  // Under limited knowledge: who heard whom at t (TeamKnowledge::heard); else empty.
  std::span<const Hearing> heard;
};

struct RunSummary {
  int steps = 0;          // recorded steps, including t = 0
  double duration = 0.0;  // simulated seconds
  // eq. (4) by the trapezoid rule over [0, duration], leaving out every step interval with an
  // end where no target is present (coverage is undefined there: nothing to cover)
  double averageCoverage = 0.0;
  double averageUtilization = 0.0;  // the same for utilization, eq. (5)
  double averageReward = 0.0;
  // Coverage at the last step, t = duration: where the team ended up (the report sets it
  // against the offline optimum of a scene that holds still).
  double finalCoverage = 0.0;
  // The same two with importance weights (RewardTerms::weightedCoverage), for a scene that has
  // them (scene::Scene::isWeighted); none otherwise, so such runs' records stay as they were.
  std::optional<double> averageWeightedCoverage;
  std::optional<double> finalWeightedCoverage;
  // The same two with resolution (StepRecord::resolutionCoverage), for a scene that asks for it;
  // none otherwise.
  std::optional<double> averageResolutionCoverage;
  std::optional<double> finalResolutionCoverage;
  // Safety, measured in continuous time (safety/step_contacts.h), whatever the layer did.
  double minObjectDistance = 0.0;  // over the whole run, m
  double minCameraDistance = 0.0;
  double objectCollisionTime = 0.0;  // s with some camera closer than δ to an object
  double cameraCollisionTime = 0.0;  // s with some pair of cameras closer than δ
  // The time with any contact, split: a contact is unavoidable when, at the step it began,
  // no admissible velocity of its cameras kept δ (the layer's verdict, safety_filter.h);
  // a step counts as unavoidable only if every camera in contact during it is.
  double avoidableContactTime = 0.0;
  double unavoidableContactTime = 0.0;
  int avoidableContacts = 0;    // contacts (a camera's stretch of steps closer than δ)
  int unavoidableContacts = 0;  // each one begins with an "unavoidable-contact" event
  int boundaryClamps = 0;       // steps where a move was cut short at the boundary
  int stepsWithoutTargets = 0;  // recorded steps with no target present (recorded tracks)
  // Under limited knowledge (params::KnowledgeParams), the cameras' messages; none otherwise,
  // so such runs' records stay as they were.
  std::optional<MessageCounts> messages;
};

class Recorder {
 public:
  virtual ~Recorder() = default;
  virtual void step(const StepRecord& record) = 0;
};

// One run, a step at a time, for callers that choose the commands themselves (a learning
// environment, an interactive page) as well as for simulate(). At each instant t_k = k · dt,
// k = 0 … steps: observation() is the present, measured; command() takes the cameras'
// commands for [t_k, t_k+1) (none at the last instant); events() holds what the simulator
// raised at t_k, to which the caller may append (a controller's events); advance() hands the
// instant to the recorder, then moves the cameras and measures t_k+1.
class Simulation {
 public:
  // `seed`: the run's, from which limited knowledge draws its message losses (unused else).
  Simulation(const scene::Scene& scene, const params::Parameters& params, std::uint64_t seed = 0);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  int index() const { return k_; }
  double time() const;
  int steps() const { return steps_; }
  // The last instant is recorded without commands; after it the run is finished.
  bool atLastInstant() const { return k_ == steps_; }
  bool finished() const { return k_ > steps_; }

  // The present instant as a controller sees it; valid until advance(). Under limited
  // knowledge its world is what the team knows (team_knowledge.h), and S and the terms are
  // measured in that world: a method never reads the true one.
  control::Observation observation() const;
  std::span<const geometry::Pose> cameras() const { return cameras_; }
  // The present instant as the run is scored and recorded: the true world, S and the terms
  // in it. observation() but under limited knowledge; for a learner's reward, never for a
  // method. Valid until advance().
  control::Observation scored() const;
  // Commands for the present instant: a non-finite one holds the camera still and is a
  // NonFiniteCommand event at the first step of each such stretch (a controller's bug shows in
  // the results instead of hiding in them); each is saturated to its camera's limits
  // (constraint 3 of Problem 2.2) and passed through the safety layer. Not at the last
  // instant; once per instant.
  void command(std::span<const scene::CameraCommand> commands);
  std::vector<control::ControlEvent>& events() { return events_; }
  // Records the present instant (with each camera's goal, if any) and, unless it is the last,
  // integrates ṗ_j = u_j over dt (kept inside the boundary) and measures the next instant.
  void advance(std::span<const std::optional<geometry::Pose>> goals, Recorder& recorder);
  // The whole run's; the averages only once finished().
  RunSummary summary() const;

 private:
  struct State;
  void measure();
  std::unique_ptr<State> state_;
  int k_ = 0;
  int steps_ = 0;
  std::vector<geometry::Pose> cameras_;
  std::vector<control::ControlEvent> events_;
};

// A whole run with `controller` choosing the commands: Simulation stepped to the end.
RunSummary simulate(const scene::Scene& scene, const params::Parameters& params,
                    control::Controller& controller, Recorder& recorder, std::uint64_t seed = 0);

}  // namespace camcov::sim
