#include "sim/simulator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "control/event_kind.h"
#include "kinematics/kinematics.h"
#include "reward/resolution_coverage.h"
#include "reward/reward_model.h"
#include "safety/safety_filter.h"
#include "safety/step_contacts.h"
#include "sim/team_knowledge.h"
#include "util/interruption.h"

namespace camcov::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Moves from `from` towards `to`, stopping at the last point strictly inside the boundary
// (bisection to 2^-40 of the step). Returns whether the move was cut short.
bool moveInside(const geometry::Ring& boundary, geometry::Vec2 from, geometry::Vec2& to) {
  auto inside = [&](geometry::Vec2 p) {
    return geometry::locate(boundary, p, 0.0) == geometry::Containment::Inside;
  };
  if (inside(to) || to == from) return false;
  double in = 0.0, out = 1.0;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (in + out);
    (inside(geometry::lerp(from, to, mid)) ? in : out) = mid;
  }
  to = geometry::lerp(from, to, in);
  return true;
}

// A camera's current stretch of steps closer than δ to something, if any.
struct Contact {
  bool active = false;
  bool unavoidable = false;
};

// Continuous-time accounting of the step that just ended (safety/step_contacts.h): the
// distances into `record` and `summary`, each contact that began in it as an event, and its
// time below δ split by whether the layer judged the contact unavoidable when the step began.
void accountStep(const safety::StepContacts& step, std::span<const safety::Verdict> verdicts,
                 double stepStart, std::vector<Contact>& contacts, StepRecord& record,
                 RunSummary& summary, std::vector<control::ControlEvent>& events) {
  record.minObjectDistanceInStep = step.minObjectDistance;
  record.minCameraDistanceInStep = step.minCameraDistance;
  summary.minObjectDistance = std::min(summary.minObjectDistance, step.minObjectDistance);
  summary.minCameraDistance = std::min(summary.minCameraDistance, step.minCameraDistance);
  summary.objectCollisionTime += step.objectContactTime;
  summary.cameraCollisionTime += step.cameraContactTime;
  bool allUnavoidable = true;
  for (std::size_t j = 0; j < contacts.size(); ++j) {
    Contact& c = contacts[j];
    if (step.contactStart[j] < 0.0) {
      c.active = false;
      continue;
    }
    if (!c.active) {
      // A contact is judged once, when it begins: one that the layer failed to avoid stays
      // avoidable while the camera recovers, even though recovering is itself "within δ".
      c = {true, !verdicts[j].keepsDelta};
      const int camera = static_cast<int>(j);
      if (c.unavoidable) {
        ++summary.unavoidableContacts;
        events.push_back({stepStart + step.contactStart[j],
                          std::string(control::eventName(control::EventKind::UnavoidableContact)),
                          camera,
                          verdicts[j].detail,
                          {},
                          safety::reasonName(verdicts[j].reason)});
      } else {
        ++summary.avoidableContacts;
        events.push_back({stepStart + step.contactStart[j],
                          std::string(control::eventName(control::EventKind::AvoidableContact)),
                          camera,
                          "camera " + std::to_string(j) +
                              " came closer than δ although an admissible velocity kept δ",
                          {},
                          ""});
      }
    }
    allUnavoidable = allUnavoidable && c.unavoidable;
  }
  (allUnavoidable ? record.unavoidableContactTime : record.avoidableContactTime) = step.contactTime;
  summary.avoidableContactTime += record.avoidableContactTime;
  summary.unavoidableContactTime += record.unavoidableContactTime;
}

}  // namespace

// Everything a run keeps between its instants.
struct Simulation::State {
  State(const scene::Scene& scene, const params::Parameters& params, std::uint64_t seed)
      : scene(scene),
        kinematics(scene),
        lenses(scene::lenses(scene)),
        measure(params.reward, lenses),
        safety(scene, params),
        accounting(kinematics, params.sim.delta),
        dt(params.sim.dt),
        comesAndGoes(scene.hasPresenceWindows()) {
    if (params.knowledge.limited) {
      team.emplace(scene, params, seed);
      knownMeasure.emplace(params.reward, scene::lenses(scene));
    }
  }

  const scene::Scene& scene;
  const kinematics::Kinematics kinematics;
  const std::vector<scene::Lens> lenses;
  reward::RewardModel measure;
  safety::SafetyFilter safety;
  const safety::StepAccounting accounting;
  const double dt;
  const bool comesAndGoes;

  kinematics::World world;
  StepRecord record;  // the present instant's, as measured so far
  std::vector<scene::CameraCommand> commands;
  std::vector<char> nonFiniteBefore;  // was camera j's last command so?
  std::vector<geometry::Vec2> velocities;
  std::vector<Contact> contacts;
  safety::Sample previousSample;
  std::vector<std::uint32_t> presentBefore;  // the targets present one step before
  int intervalsWithoutTargets = 0;
  reward::RewardTerms previous;
  double previousResolution = 0.0;  // StepRecord::resolutionCoverage one step before
  RunSummary summary;
  // Limited knowledge only: what the team knows, and the present measured in that world for
  // the methods.
  std::optional<TeamKnowledge> team;
  std::optional<reward::RewardModel> knownMeasure;
  reward::RewardTerms knownTerms;
  // The goals the method gave at the last instant recorded, which the cameras' messages carry.
  std::vector<std::optional<geometry::Pose>> goals;
};

Simulation::Simulation(const scene::Scene& scene, const params::Parameters& params,
                       std::uint64_t seed)
    : state_(std::make_unique<State>(scene, params, seed)),
      steps_(static_cast<int>(std::llround(params.sim.duration / params.sim.dt))) {
  for (const auto& c : scene.cameras)
    cameras_.push_back(c.initial);
  State& s = *state_;
  s.commands.resize(cameras_.size());
  s.nonFiniteBefore.assign(cameras_.size(), 0);
  s.velocities.resize(cameras_.size());
  s.contacts.resize(cameras_.size());
  s.summary.duration = steps_ * s.dt;
  s.summary.minObjectDistance = s.summary.minCameraDistance = kInf;
  if (scene.isWeighted()) s.summary.averageWeightedCoverage = 0.0;
  if (scene.resolution) s.summary.averageResolutionCoverage = 0.0;
  measure();
}

Simulation::~Simulation() = default;

double Simulation::time() const {
  return k_ * state_->dt;
}  // not accumulated: no drift

control::Observation Simulation::observation() const {
  const State& s = *state_;
  if (!s.team) return scored();
  if (s.team->knowsTheWorld()) {
    // The known world's S and terms are the true world's, measured once (measure()).
    return {time(),         s.team->known(), cameras_,     s.measure.segments(),
            s.record.terms, &s.measure,      s.team->own()};
  }
  return {time(),       s.team->known(),  cameras_,     s.knownMeasure->segments(),
          s.knownTerms, &*s.knownMeasure, s.team->own()};
}

control::Observation Simulation::scored() const {
  const State& s = *state_;
  return {time(), s.world, cameras_, s.measure.segments(), s.record.terms, &s.measure};
}

// Measures instant k_: the world, the terms, the distances, the step that led here (contacts,
// in continuous time) and the targets that came or went.
void Simulation::measure() {
  State& s = *state_;
  const int k = k_;
  const double t = time();
  s.kinematics.worldAt(t, s.world);
  s.measure.setWorld(s.world);

  StepRecord& record = s.record;
  record = StepRecord{};
  record.index = k;
  record.time = t;
  record.terms = s.measure.evaluate(cameras_);
  if (s.scene.resolution) {
    record.resolutionCoverage = reward::resolutionCoverage(
        s.measure.segments(), cameras_, s.lenses, *s.scene.resolution, s.measure.perimeter());
  }
  if (s.team) {
    s.team->update(s.world, cameras_, s.goals, s.measure.segments());
    // A team that knows the world as it is would only measure again what was just measured.
    if (!s.team->knowsTheWorld()) {
      s.knownMeasure->setWorld(s.team->known());
      s.knownTerms = s.knownMeasure->evaluate(cameras_);
    }
  }
  RunSummary& summary = s.summary;
  if (s.comesAndGoes) {
    record.targetsPresent = static_cast<int>(s.world.targets.size());
    if (s.world.targets.empty()) ++summary.stepsWithoutTargets;
  }
  safety::Sample sample = s.accounting.sample(s.world, cameras_);
  record.minObjectDistance = sample.minObjectDistance;
  record.minCameraDistance = sample.minCameraDistance;
  events_.clear();
  if (k == 0) {
    record.minObjectDistanceInStep = record.minObjectDistance;
    record.minCameraDistanceInStep = record.minCameraDistance;
    summary.minObjectDistance = record.minObjectDistance;
    summary.minCameraDistance = record.minCameraDistance;
  } else {
    // The layer's verdicts are still those of the step's start: apply() comes in command().
    accountStep(s.accounting.measure(s.previousSample, sample), s.safety.verdicts(),
                s.previousSample.time, s.contacts, record, summary, events_);
    if (s.comesAndGoes && (s.presentBefore.empty() || s.world.targets.empty())) {
      ++s.intervalsWithoutTargets;  // nothing to cover at one end: left out of the averages
    } else {
      // trapezoid rule, eq. (4)
      const double dt = s.dt;
      summary.averageCoverage += 0.5 * (s.previous.coverage + record.terms.coverage) * dt;
      const auto integrate = [dt](std::optional<double>& average, double before, double now) {
        if (average) *average += 0.5 * (before + now) * dt;
      };
      integrate(summary.averageWeightedCoverage, s.previous.weightedCoverage,
                record.terms.weightedCoverage);
      integrate(summary.averageResolutionCoverage, s.previousResolution, record.resolutionCoverage);
      summary.averageUtilization += 0.5 * (s.previous.utilization + record.terms.utilization) * dt;
      summary.averageReward += 0.5 * (s.previous.reward + record.terms.reward) * dt;
    }
  }
  if (s.comesAndGoes) {
    // Entering and leaving, as events of this step (ids ascend in both lists).
    const auto& now = s.world.targetIds;
    for (const std::uint32_t id : now) {
      if (!std::binary_search(s.presentBefore.begin(), s.presentBefore.end(), id) && k > 0)
        events_.push_back({t,
                           std::string(control::eventName(control::EventKind::TargetAppears)),
                           -1,
                           "target " + std::to_string(id) + " enters the scene",
                           {},
                           ""});
    }
    for (const std::uint32_t id : s.presentBefore) {
      if (!std::binary_search(now.begin(), now.end(), id))
        events_.push_back({t,
                           std::string(control::eventName(control::EventKind::TargetLeaves)),
                           -1,
                           "target " + std::to_string(id) + " leaves the scene",
                           {},
                           ""});
    }
    s.presentBefore = now;
  }
  s.previous = record.terms;
  s.previousResolution = record.resolutionCoverage;
  s.previousSample = std::move(sample);
}

void Simulation::command(std::span<const scene::CameraCommand> commands) {
  if (atLastInstant() || finished())
    throw std::logic_error("Simulation::command: the last instant takes no commands");
  State& s = *state_;
  const double t = time();
  for (std::size_t j = 0; j < cameras_.size(); ++j) {
    scene::CameraCommand u = j < commands.size() ? commands[j] : scene::CameraCommand{};
    const bool finite = u.isFinite();
    if (!finite && !s.nonFiniteBefore[j]) {
      events_.push_back(
          {t,
           std::string(control::eventName(control::EventKind::NonFiniteCommand)),
           static_cast<int>(j),
           fmt::format("camera {}'s command (vx {}, vy {}, yaw rate {}) is not finite: it "
                       "holds still",
                       j, u.velocity.x, u.velocity.y, u.angularVelocity),
           {},
           ""});
    }
    s.nonFiniteBefore[j] = !finite;
    s.commands[j] = s.scene.cameras[j].saturate(u);
    s.velocities[j] = s.commands[j].velocity;
  }
  s.safety.apply(s.world, cameras_, s.velocities);
}

void Simulation::advance(std::span<const std::optional<geometry::Pose>> goals, Recorder& recorder) {
  if (finished()) throw std::logic_error("Simulation::advance: the run is finished");
  State& s = *state_;
  StepRecord& record = s.record;
  record.cameras = cameras_;
  record.goals = goals;
  record.events = events_;
  if (s.team) {
    record.heard = s.team->heard();
    s.goals.assign(goals.begin(), goals.end());
  }
  recorder.step(record);
  if (k_ == steps_) {
    ++k_;
    return;
  }
  for (std::size_t j = 0; j < cameras_.size(); ++j) {
    // The position as the safety layer left it, the turn as commanded.
    const geometry::Pose next =
        scene::moved(cameras_[j], {s.velocities[j], s.commands[j].angularVelocity}, s.dt);
    geometry::Vec2 position = next.position();
    if (moveInside(s.world.boundary, cameras_[j].position(), position)) ++s.summary.boundaryClamps;
    cameras_[j] = {position.x, position.y, next.yaw};
  }
  // The commands were for this step only: a caller that gives none next holds still.
  std::fill(s.commands.begin(), s.commands.end(), scene::CameraCommand{});
  std::fill(s.velocities.begin(), s.velocities.end(), geometry::Vec2{});
  ++k_;
  measure();
}

RunSummary Simulation::summary() const {
  const State& s = *state_;
  RunSummary summary = s.summary;
  if (s.team) summary.messages = s.team->messages();
  if (!finished()) return summary;
  summary.steps = steps_ + 1;
  summary.finalCoverage = s.previous.coverage;
  // Without gaps this is steps · dt exactly, so runs without tracks keep their bytes.
  const double measured = (steps_ - s.intervalsWithoutTargets) * s.dt;
  // The coverages only some scenes record, each with its value at the last step.
  const std::pair<std::optional<double>*, double> someScenesOnly[] = {
      {&summary.averageWeightedCoverage, s.previous.weightedCoverage},
      {&summary.averageResolutionCoverage, s.previousResolution}};
  if (measured > 0.0) {
    summary.averageCoverage /= measured;
    summary.averageUtilization /= measured;
    summary.averageReward /= measured;
    for (const auto& [average, last] : someScenesOnly)
      if (*average) **average /= measured;
  } else if (summary.duration > 0.0) {
    summary.averageCoverage = summary.averageUtilization = summary.averageReward = 0.0;
    for (const auto& [average, last] : someScenesOnly)
      if (*average) *average = 0.0;
  } else {
    summary.averageCoverage = s.previous.coverage;
    summary.averageUtilization = s.previous.utilization;
    summary.averageReward = s.previous.reward;
    for (const auto& [average, last] : someScenesOnly)
      if (*average) *average = last;
  }
  if (summary.averageWeightedCoverage) summary.finalWeightedCoverage = s.previous.weightedCoverage;
  if (summary.averageResolutionCoverage) summary.finalResolutionCoverage = s.previousResolution;
  return summary;
}

RunSummary simulate(const scene::Scene& scene, const params::Parameters& params,
                    control::Controller& controller, Recorder& recorder, std::uint64_t seed) {
  Simulation simulation(scene, params, seed);
  std::vector<scene::CameraCommand> commands(scene.cameras.size());
  std::vector<std::optional<geometry::Pose>> goals(scene.cameras.size());
  while (!simulation.finished()) {
    throwIfInterrupted();  // a caller that can be interrupted (Python) stops within a step
    if (!simulation.atLastInstant()) {
      // The controller acts on the present; its events belong to this step's record.
      controller.control(simulation.observation(), commands);
      simulation.command(commands);
    }
    controller.takeEvents(simulation.events());
    for (std::size_t j = 0; j < goals.size(); ++j)
      goals[j] = controller.goal(j);
    simulation.advance(goals, recorder);
  }
  return simulation.summary();
}

}  // namespace camcov::sim
