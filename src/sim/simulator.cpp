#include "sim/simulator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "kinematics/kinematics.h"
#include "reward/reward_model.h"
#include "safety/safety_filter.h"
#include "safety/step_contacts.h"
#include "util/interruption.h"

namespace camcov::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool isFinite(const kinematics::CameraCommand& u) {
  return std::isfinite(u.velocity.x) && std::isfinite(u.velocity.y) &&
         std::isfinite(u.angularVelocity);
}

// Constraint 3 of Problem 2.2: ‖[ẋ ẏ]‖ ≤ v_max and |γ̇| ≤ γ̇_max. Non-finite commands stop.
kinematics::CameraCommand saturate(kinematics::CameraCommand u, const scene::CameraSpec& limits) {
  if (!std::isfinite(u.velocity.x) || !std::isfinite(u.velocity.y)) u.velocity = {};
  if (!std::isfinite(u.angularVelocity)) u.angularVelocity = 0.0;
  const double speed = geometry::norm(u.velocity);
  if (speed > limits.maxVelocity) u.velocity = u.velocity * (limits.maxVelocity / speed);
  u.angularVelocity =
      std::clamp(u.angularVelocity, -limits.maxAngularVelocity, limits.maxAngularVelocity);
  return u;
}

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
                          std::string(kUnavoidableContact),
                          camera,
                          verdicts[j].detail,
                          {},
                          safety::reasonName(verdicts[j].reason)});
      } else {
        ++summary.avoidableContacts;
        events.push_back({stepStart + step.contactStart[j],
                          std::string(kAvoidableContact),
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

RunSummary simulate(const scene::Scene& scene, const params::Parameters& params,
                    control::Controller& controller, Recorder& recorder) {
  const kinematics::Kinematics kinematics(scene);
  reward::RewardModel measure(params.reward, scene::halfFovs(scene));
  safety::SafetyFilter safety(scene, params);
  const safety::StepAccounting accounting(kinematics, params.sim.delta);
  const double dt = params.sim.dt;
  const int steps = static_cast<int>(std::llround(params.sim.duration / dt));

  std::vector<geometry::Pose> cameras;
  for (const auto& c : scene.cameras)
    cameras.push_back(c.initial);
  std::vector<kinematics::CameraCommand> commands(cameras.size());
  std::vector<char> nonFiniteBefore(cameras.size(), 0);  // was camera j's last command so?
  std::vector<geometry::Vec2> velocities(cameras.size());
  std::vector<std::optional<geometry::Pose>> goals(cameras.size());
  std::vector<control::ControlEvent> events;
  std::vector<Contact> contacts(cameras.size());
  kinematics::World world;
  safety::Sample previousSample;

  RunSummary summary;
  summary.duration = steps * dt;
  const bool comesAndGoes = scene.hasPresenceWindows();
  std::vector<std::uint32_t> presentBefore;  // the targets present one step before
  int intervalsWithoutTargets = 0;
  summary.minObjectDistance = summary.minCameraDistance = kInf;
  reward::RewardTerms previous;
  for (int k = 0; k <= steps; ++k) {
    throwIfInterrupted();     // a caller that can be interrupted (Python) stops within a step
    const double t = k * dt;  // not accumulated: no drift over long runs
    kinematics.worldAt(t, world);
    measure.setWorld(world);

    StepRecord record;
    record.index = k;
    record.time = t;
    record.terms = measure.evaluate(cameras);
    if (comesAndGoes) {
      record.targetsPresent = static_cast<int>(world.targets.size());
      if (world.targets.empty()) ++summary.stepsWithoutTargets;
    }
    safety::Sample sample = accounting.sample(world, cameras);
    record.minObjectDistance = sample.minObjectDistance;
    record.minCameraDistance = sample.minCameraDistance;
    events.clear();
    if (k == 0) {
      record.minObjectDistanceInStep = record.minObjectDistance;
      record.minCameraDistanceInStep = record.minCameraDistance;
      summary.minObjectDistance = record.minObjectDistance;
      summary.minCameraDistance = record.minCameraDistance;
    } else {
      // The layer's verdicts are still those of the step's start: apply() comes below.
      accountStep(accounting.measure(previousSample, sample), safety.verdicts(),
                  previousSample.time, contacts, record, summary, events);
      if (comesAndGoes && (presentBefore.empty() || world.targets.empty())) {
        ++intervalsWithoutTargets;  // nothing to cover at one end: left out of the averages
      } else {
        // trapezoid rule, eq. (4)
        summary.averageCoverage += 0.5 * (previous.coverage + record.terms.coverage) * dt;
        summary.averageUtilization += 0.5 * (previous.utilization + record.terms.utilization) * dt;
        summary.averageReward += 0.5 * (previous.reward + record.terms.reward) * dt;
      }
    }
    if (comesAndGoes) {
      // Entering and leaving, as events of this step (ids ascend in both lists).
      const auto& now = world.targetIds;
      for (const std::uint32_t id : now) {
        if (!std::binary_search(presentBefore.begin(), presentBefore.end(), id) && k > 0)
          events.push_back({t,
                            std::string(kTargetAppears),
                            -1,
                            "target " + std::to_string(id) + " enters the scene",
                            {},
                            ""});
      }
      for (const std::uint32_t id : presentBefore) {
        if (!std::binary_search(now.begin(), now.end(), id))
          events.push_back({t,
                            std::string(kTargetLeaves),
                            -1,
                            "target " + std::to_string(id) + " leaves the scene",
                            {},
                            ""});
      }
      presentBefore = now;
    }
    previous = record.terms;
    previousSample = std::move(sample);

    if (k < steps) {
      // The controller acts on the present; its events belong to this step's record.
      controller.control({t, world, cameras, measure.segments(), record.terms, &measure}, commands);
      for (std::size_t j = 0; j < cameras.size(); ++j) {
        const bool finite = isFinite(commands[j]);
        if (!finite && !nonFiniteBefore[j]) {
          events.push_back(
              {t,
               std::string(kNonFiniteCommand),
               static_cast<int>(j),
               fmt::format("camera {}'s command (vx {}, vy {}, yaw rate {}) is not finite: it "
                           "holds still",
                           j, commands[j].velocity.x, commands[j].velocity.y,
                           commands[j].angularVelocity),
               {},
               ""});
        }
        nonFiniteBefore[j] = !finite;
        commands[j] = saturate(commands[j], scene.cameras[j]);
        velocities[j] = commands[j].velocity;
      }
      safety.apply(world, cameras, velocities);
    }
    controller.takeEvents(events);
    for (std::size_t j = 0; j < cameras.size(); ++j)
      goals[j] = controller.goal(j);
    record.cameras = cameras;
    record.goals = goals;
    record.events = events;
    recorder.step(record);
    if (k == steps) break;

    for (std::size_t j = 0; j < cameras.size(); ++j) {
      geometry::Vec2 next = cameras[j].position() + velocities[j] * dt;
      if (moveInside(world.boundary, cameras[j].position(), next)) ++summary.boundaryClamps;
      cameras[j] = {next.x, next.y,
                    geometry::wrapAngle(cameras[j].yaw + commands[j].angularVelocity * dt)};
    }
  }
  summary.steps = steps + 1;
  summary.finalCoverage = previous.coverage;
  // Without gaps this is steps · dt exactly, so runs without tracks keep their bytes.
  const double measured = (steps - intervalsWithoutTargets) * dt;
  if (measured > 0.0) {
    summary.averageCoverage /= measured;
    summary.averageUtilization /= measured;
    summary.averageReward /= measured;
  } else if (summary.duration > 0.0) {
    summary.averageCoverage = summary.averageUtilization = summary.averageReward = 0.0;
  } else {
    summary.averageCoverage = previous.coverage;
    summary.averageUtilization = previous.utilization;
    summary.averageReward = previous.reward;
  }
  return summary;
}

}  // namespace camcov::sim
