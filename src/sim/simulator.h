#pragma once
// The deterministic simulator (SPEC section 3): fixed dt, the controller sees only the
// present, commands are saturated to each camera's limits and integrated (ṗ_j = u_j), cameras
// are kept inside the boundary, and every step is measured and handed to a recorder.
// Computation takes no simulated time, so a run depends only on its inputs.
#include <optional>
#include <span>
#include <vector>

#include "control/controller.h"
#include "params/parameters.h"
#include "reward/metrics.h"
#include "scene/scene.h"

namespace camcov::sim {

// Everything measured at one step; spans are valid only during Recorder::step().
struct StepRecord {
  int index = 0;
  double time = 0.0;
  reward::RewardTerms terms;
  std::span<const geometry::Pose> cameras;
  std::span<const std::optional<geometry::Pose>> goals;
  double minObjectDistance = 0.0;  // closest camera to any target or obstacle, m
  double minCameraDistance = 0.0;  // closest pair of cameras, m (infinity for one camera)
  std::span<const control::ControlEvent> events;  // raised by the controller since last step
};

struct RunSummary {
  int steps = 0;                    // recorded steps, including t = 0
  double duration = 0.0;            // simulated seconds
  double averageCoverage = 0.0;     // eq. (4) by the trapezoid rule over [0, duration]
  double averageUtilization = 0.0;  // the same for utilization, eq. (5)
  double averageReward = 0.0;
  double minObjectDistance = 0.0;  // over the whole run
  double minCameraDistance = 0.0;
  double objectCollisionTime = 0.0;  // s with some camera closer than δ to an object
  double cameraCollisionTime = 0.0;  // s with some pair of cameras closer than δ
  int boundaryClamps = 0;            // steps where a move was cut short at the boundary
};

class Recorder {
 public:
  virtual ~Recorder() = default;
  virtual void step(const StepRecord& record) = 0;
};

RunSummary simulate(const scene::Scene& scene, const params::Parameters& params,
                    control::Controller& controller, Recorder& recorder);

}  // namespace camcov::sim
