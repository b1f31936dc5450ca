#pragma once
// The pieces our method (`--method camcov`; docs/method.md, "Our method") adds to
// the paper's loop in PaperController: how a global candidate is judged against what the team
// is committed to (in the present world, and for staying also in the worlds the motion seen
// forecasts: motion_watch.h), and where a camera following a plan looks on the way.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "control/motion_watch.h"
#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "reward/reward_model.h"
#include "scene/camera.h"

namespace camcov::control {

// A team on its way: camera j along paths[j] (its pose now first, its goal last), at an even
// pace that takes travel[j] seconds, then staying at its goal.
struct TeamMove {
  std::span<const std::vector<geometry::Pose>> paths;
  std::span<const double> travel;
};

// How long a path takes at the camera's limits: section V-B's estimate
// (CameraSpec::travelTime) with the path's length and the turn from its first yaw to its last.
double pathTravelTime(std::span<const geometry::Pose> path, const scene::CameraSpec& camera);

// The coverage, eq. (3), the team would average over the next `horizon` seconds along `move`,
// at the model's instant: the transit's coverage at its two ends and `samples` instants between
// them (each camera's position that far along its path, its yaw turned that far from its first
// to its goal's), by the trapezoid rule, then the goals' coverage for the rest of the horizon.
// A transit longer than the horizon counts up to the horizon only.
double averageCoverageAhead(reward::RewardModel& model, const TeamMove& move, double horizon,
                            int samples);

// averageCoverageAhead in the worlds `forecast` foresees instead of the present one: the team
// along `move` against Forecast::at(t) at kForecastIntervals + 1 instants evenly over the
// horizon (trapezoid rule). Sets `model`'s world.
inline constexpr int kForecastIntervals = 8;  // 16: the same means to 1e-4 (docs/method.md)
double forecastCoverageAhead(reward::RewardModel& model, const Forecast& forecast,
                             const TeamMove& move, double horizon);

// Where camera j, following a plan, should look: of `directions` yaws evenly round and the
// executor's `plannedYaw`, the one from which the team (camera j turned so) has the highest
// reward now, among those it can turn to and then on to the goal's yaw within `timeLeft` s at
// `turnRate`; ties go to the planned yaw.
double lookoutYaw(reward::RewardModel& model, std::span<geometry::Pose> team, std::size_t j,
                  double plannedYaw, double goalYaw, double timeLeft, double turnRate,
                  int directions);

}  // namespace camcov::control
