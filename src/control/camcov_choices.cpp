#include "control/camcov_choices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "reward/added_camera_bound.h"

namespace camcov::control {

namespace {

double pathLength(std::span<const geometry::Pose> path) {
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    length += geometry::distance(path[i - 1].position(), path[i].position());
  return length;
}

// The pose a fraction u of the way along `path` (by length; the yaw turned that far).
geometry::Pose along(std::span<const geometry::Pose> path, double u) {
  const geometry::Pose& first = path.front();
  const geometry::Pose& last = path.back();
  const double yaw = geometry::wrapAngle(first.yaw + u * geometry::wrapAngle(last.yaw - first.yaw));
  double left = u * pathLength(path);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double piece = geometry::distance(path[i - 1].position(), path[i].position());
    if (left <= piece && piece > 0.0) {
      const geometry::Vec2 p =
          geometry::lerp(path[i - 1].position(), path[i].position(), left / piece);
      return {p.x, p.y, yaw};
    }
    left -= piece;
  }
  return {last.x, last.y, yaw};
}

// Each camera of `move` t seconds into it (staying at its goal once there).
void teamAt(const TeamMove& move, double t, std::vector<geometry::Pose>& team) {
  team.resize(move.paths.size());
  for (std::size_t j = 0; j < team.size(); ++j) {
    const double u = move.travel[j] > 0.0 ? std::min(1.0, t / move.travel[j]) : 1.0;
    team[j] = along(move.paths[j], u);
  }
}

}  // namespace

double pathTravelTime(std::span<const geometry::Pose> path, const scene::CameraSpec& camera) {
  return camera.travelTime(pathLength(path),
                           geometry::wrapAngle(path.back().yaw - path.front().yaw));
}

double averageCoverageAhead(reward::RewardModel& model, const TeamMove& move, double horizon,
                            int samples) {
  const double transit =
      move.travel.empty() ? 0.0 : *std::max_element(move.travel.begin(), move.travel.end());
  std::vector<geometry::Pose> team;
  for (const auto& path : move.paths)
    team.push_back(path.back());
  // The coverage the reward takes (weighted, unless the parameters say plain).
  const auto coverageOf = [&model](const std::vector<geometry::Pose>& poses) {
    return reward::coverageTerm(model.params(), model.terms(poses));
  };
  const double arrived = coverageOf(team);
  if (!(transit > 0.0)) return arrived;
  const double end = std::min(transit, horizon);
  const auto coverageAt = [&](double t) {
    teamAt(move, t, team);
    return coverageOf(team);
  };
  // The trapezoid rule over the transit's first `end` seconds.
  double integral = 0.0, before = coverageAt(0.0), tBefore = 0.0;
  for (int k = 1; k <= samples + 1; ++k) {
    const double t = end * k / (samples + 1);
    const double c = t >= transit ? arrived : coverageAt(t);
    integral += 0.5 * (before + c) * (t - tBefore);
    before = c;
    tBefore = t;
  }
  integral += arrived * std::max(0.0, horizon - transit);
  return integral / horizon;
}

double forecastCoverageAhead(reward::RewardModel& model, const Forecast& forecast,
                             const TeamMove& move, double horizon) {
  std::vector<geometry::Pose> team;
  double integral = 0.0, before = 0.0;
  for (int k = 0; k <= kForecastIntervals; ++k) {
    const double t = horizon * k / kForecastIntervals;
    model.setWorld(forecast.at(t));
    teamAt(move, t, team);
    const double c = reward::coverageTerm(model.params(), model.terms(team));
    if (k > 0) integral += 0.5 * (before + c) / kForecastIntervals;
    before = c;
  }
  return integral;
}

double lookoutYaw(reward::RewardModel& model, std::span<geometry::Pose> team, std::size_t j,
                  double plannedYaw, double goalYaw, double timeLeft, double turnRate,
                  int directions) {
  const geometry::Pose kept = team[j];
  const double reach = turnRate * std::max(0.0, timeLeft);
  // The planned yaw first: sweeping it leaves the model's kept terms those of this team, which
  // the bound takes.
  team[j].yaw = plannedYaw;
  double best = model.reward(team), bestYaw = plannedYaw;
  int bestK = -1;
  // A direction whose bound (added_camera_bound.h: camera j turned there, the others as they
  // are) cannot beat the best so far, nor tie it, is not swept: most look away from what the
  // camera could add. They are swept from the highest bound down, so that the best comes early
  // and bounds more of the rest; the choice is still the first best in index order (the
  // planned yaw, then k = 0, 1, ...). Where the reward counts resolution no bound holds, and
  // every direction is swept.
  const bool bounded = !model.countsResolution();
  reward::AddedCameraBound bound;
  std::vector<double> terms;
  if (bounded) {
    bound.prepareMoving(model, team, j);
    bound.placeAt(kept.position(), terms);
  }
  struct Direction {
    int k;
    double yaw, bound;
  };
  std::vector<Direction> candidates;
  for (int k = 0; k < directions; ++k) {
    const double yaw = geometry::wrapAngle(2.0 * std::numbers::pi * k / directions);
    // Turning there, then on to the goal's yaw, must fit in the time left.
    if (std::abs(geometry::wrapAngle(yaw - kept.yaw)) +
            std::abs(geometry::wrapAngle(goalYaw - yaw)) >
        reach) {
      continue;
    }
    candidates.push_back(
        {k, yaw, bounded ? bound.ofYaw(yaw) : std::numeric_limits<double>::infinity()});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Direction& a, const Direction& b) { return a.bound > b.bound; });
  for (const Direction& d : candidates) {
    if (bounded && reward::AddedCameraBound::cannotBeat(d.bound, best)) continue;
    team[j].yaw = d.yaw;
    const double r = model.reward(team);
    if (r > best || (r == best && d.k < bestK)) {
      best = r;
      bestYaw = d.yaw;
      bestK = d.k;
    }
  }
  team[j] = kept;
  return bestYaw;
}

}  // namespace camcov::control
