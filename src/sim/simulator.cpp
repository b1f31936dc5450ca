#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kinematics/kinematics.h"
#include "reward/reward_model.h"

namespace camcov::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double minObjectDistance(const kinematics::World& world, std::span<const geometry::Pose> cameras) {
  double best = kInf;
  for (const auto& c : cameras) {
    for (const auto* objects : {&world.targets, &world.obstacles}) {
      for (const auto& object : *objects) {
        best = std::min(best, geometry::distanceToPolygon(object, c.position()));
      }
    }
  }
  return best;
}

double minCameraDistance(std::span<const geometry::Pose> cameras) {
  double best = kInf;
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      best = std::min(best, geometry::distance(cameras[i].position(), cameras[j].position()));
    }
  }
  return best;
}

// Constraint 3 of Problem 2.2: ‖[ẋ ẏ]‖ ≤ v_max and |γ̇| ≤ γ̇_max. Non-finite commands stop.
control::CameraCommand saturate(control::CameraCommand u, const scene::CameraSpec& limits) {
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

}  // namespace

RunSummary simulate(const scene::Scene& scene, const params::Parameters& params,
                    control::Controller& controller, Recorder& recorder) {
  const kinematics::Kinematics kinematics(scene);
  reward::RewardModel measure(params.reward, scene.fovHalfAngle);
  const double dt = params.sim.dt;
  const int steps = static_cast<int>(std::llround(params.sim.duration / dt));

  std::vector<geometry::Pose> cameras;
  for (const auto& c : scene.cameras)
    cameras.push_back(c.initial);
  std::vector<control::CameraCommand> commands(cameras.size());
  std::vector<std::optional<geometry::Pose>> goals(cameras.size());
  std::vector<control::ControlEvent> events;
  kinematics::World world;

  RunSummary summary;
  summary.duration = steps * dt;
  summary.minObjectDistance = summary.minCameraDistance = kInf;
  reward::RewardTerms previous;
  for (int k = 0; k <= steps; ++k) {
    const double t = k * dt;  // not accumulated: no drift over long runs
    kinematics.worldAt(t, world);
    measure.setWorld(world);

    StepRecord record;
    record.index = k;
    record.time = t;
    record.terms = measure.evaluate(cameras);
    record.minObjectDistance = minObjectDistance(world, cameras);
    record.minCameraDistance = minCameraDistance(cameras);
    summary.minObjectDistance = std::min(summary.minObjectDistance, record.minObjectDistance);
    summary.minCameraDistance = std::min(summary.minCameraDistance, record.minCameraDistance);
    if (k > 0) {  // trapezoid rule, eq. (4)
      summary.averageCoverage += 0.5 * (previous.coverage + record.terms.coverage) * dt;
      summary.averageUtilization += 0.5 * (previous.utilization + record.terms.utilization) * dt;
      summary.averageReward += 0.5 * (previous.reward + record.terms.reward) * dt;
    }
    previous = record.terms;

    if (k < steps) {
      // The controller acts on the present; its events belong to this step's record.
      controller.control({t, world, cameras}, commands);
      if (record.minObjectDistance < params.sim.delta) summary.objectCollisionTime += dt;
      if (record.minCameraDistance < params.sim.delta) summary.cameraCollisionTime += dt;
    }
    events.clear();
    controller.takeEvents(events);
    for (std::size_t j = 0; j < cameras.size(); ++j)
      goals[j] = controller.goal(j);
    record.cameras = cameras;
    record.goals = goals;
    record.events = events;
    recorder.step(record);
    if (k == steps) break;

    for (std::size_t j = 0; j < cameras.size(); ++j) {
      const control::CameraCommand u = saturate(commands[j], scene.cameras[j]);
      geometry::Vec2 next = cameras[j].position() + u.velocity * dt;
      if (moveInside(world.boundary, cameras[j].position(), next)) ++summary.boundaryClamps;
      cameras[j] = {next.x, next.y, geometry::wrapAngle(cameras[j].yaw + u.angularVelocity * dt)};
    }
  }
  summary.steps = steps + 1;
  if (summary.duration > 0.0) {
    summary.averageCoverage /= summary.duration;
    summary.averageUtilization /= summary.duration;
    summary.averageReward /= summary.duration;
  } else {
    summary.averageCoverage = previous.coverage;
    summary.averageUtilization = previous.utilization;
    summary.averageReward = previous.reward;
  }
  return summary;
}

}  // namespace camcov::sim
