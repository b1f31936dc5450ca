#include "planners/plan_executor.h"

#include <algorithm>
#include <cmath>

#include "reward/metrics.h"

namespace camcov::planners {

namespace {

// The largest u in [0, 1] with |a + u(b − a) − p| <= r, or a negative value if none.
double farthestReachable(geometry::Vec2 a, geometry::Vec2 b, geometry::Vec2 p, double r) {
  const geometry::Vec2 d = b - a, f = a - p;
  const double A = geometry::norm2(d), B = 2.0 * geometry::dot(f, d),
               C = geometry::norm2(f) - r * r;
  if (A == 0.0) return C <= 0.0 ? 1.0 : -1.0;
  const double disc = B * B - 4.0 * A * C;
  if (disc < 0.0) return -1.0;
  const double root = std::sqrt(disc);
  const double u0 = (-B - root) / (2.0 * A), u1 = (-B + root) / (2.0 * A);
  if (u1 < 0.0 || u0 > 1.0) return -1.0;
  return std::min(u1, 1.0);
}

geometry::Pose interpolate(const geometry::Pose& a, const geometry::Pose& b, double u) {
  const geometry::Vec2 p = geometry::lerp(a.position(), b.position(), u);
  return {p.x, p.y, geometry::wrapAngle(a.yaw + u * geometry::wrapAngle(b.yaw - a.yaw))};
}

}  // namespace

geometry::Vec2 repulsiveDirection(geometry::Vec2 p, const kinematics::World& world,
                                  std::span<const geometry::Pose> otherCameras, double d2) {
  geometry::Vec2 sum;
  auto push = [&](geometry::Vec2 towards, double distance) {
    const double weight = reward::invdist(distance, d2);
    const double length = geometry::norm(towards);
    if (weight > 0.0 && length > 0.0) sum += towards * (weight / length);
  };
  for (const auto* objects : {&world.targets, &world.obstacles}) {
    for (const auto& object : *objects) {
      const geometry::Vec2 closest = geometry::closestPointOnBoundary(object, p);
      const double d = geometry::distance(closest, p);
      // Inside an object the nearest way out is away from the object's interior.
      const bool inside = geometry::locate(object, p, 0.0) == geometry::Containment::Inside;
      push(inside ? p - closest : closest - p, inside ? 0.0 : d);
    }
  }
  for (const auto& c : otherCameras)
    push(c.position() - p, geometry::distance(c.position(), p));
  return sum;
}

void PlanExecutor::start(std::vector<geometry::Pose> path, double t) {
  path_ = std::move(path);
  arcLength_.assign(path_.size(), 0.0);
  for (std::size_t i = 1; i < path_.size(); ++i) {
    arcLength_[i] =
        arcLength_[i - 1] + geometry::distance(path_[i - 1].position(), path_[i].position());
  }
  progress_ = 0.0;
  intermediate_ = path_.front();
  status_ = path_.empty() ? Status::Idle : Status::Executing;
  bestRemaining_ = std::numeric_limits<double>::infinity();
  lastProgressTime_ = t;
}

void PlanExecutor::chooseIntermediateGoal(geometry::Vec2 p, double reach) {
  // Farthest point along the path, from the current intermediate goal on, within reach.
  double bestArc = -1.0;
  geometry::Pose best;
  for (std::size_t i = 0; i + 1 < path_.size(); ++i) {
    if (arcLength_[i + 1] < progress_) continue;
    const double u = farthestReachable(path_[i].position(), path_[i + 1].position(), p, reach);
    if (u < 0.0) continue;
    const double arc = arcLength_[i] + u * (arcLength_[i + 1] - arcLength_[i]);
    if (arc >= progress_ && arc >= bestArc) {
      bestArc = arc;
      best = interpolate(path_[i], path_[i + 1], u);
    }
  }
  if (path_.size() == 1 ||
      (bestArc >= arcLength_.back() && geometry::distance(goal().position(), p) <= reach)) {
    intermediate_ = goal();
    progress_ = arcLength_.back();
  } else if (bestArc >= 0.0) {
    intermediate_ = best;
    progress_ = bestArc;
  }
  // Else nothing of the path ahead is in reach (the camera was pushed off it): keep heading
  // for the current intermediate goal.
}

double PlanExecutor::distanceLeft(const geometry::Pose& pose) const {
  return geometry::distance(pose.position(), intermediate_.position()) +
         (arcLength_.back() - progress_);
}

std::vector<geometry::Pose> PlanExecutor::pathLeft(const geometry::Pose& pose) const {
  std::vector<geometry::Pose> left{pose, intermediate_};
  for (std::size_t i = 0; i < path_.size(); ++i) {
    if (arcLength_[i] > progress_) left.push_back(path_[i]);
  }
  return left;
}

double PlanExecutor::remaining(const geometry::Pose& pose) const {
  // SE(2) distance left, as OMPL measures it: the way left, and half the yaw still to turn.
  return distanceLeft(pose) + 0.5 * std::abs(geometry::wrapAngle(goal().yaw - pose.yaw));
}

scene::CameraCommand PlanExecutor::step(const geometry::Pose& pose, const kinematics::World& world,
                                        std::span<const geometry::Pose> otherCameras,
                                        double maxVelocity, double dt, double t) {
  if (status_ != Status::Executing) return {};
  const geometry::Vec2 p = pose.position();
  if (geometry::distance(p, goal().position()) <= kArrivalDistance &&
      std::abs(geometry::wrapAngle(goal().yaw - pose.yaw)) <= kArrivalYaw) {
    status_ = Status::Completed;
    return {};
  }
  chooseIntermediateGoal(p, maxVelocity * dt);

  const double left = remaining(pose);
  if (left < bestRemaining_ - 1e-3 * maxVelocity * dt) {
    bestRemaining_ = left;
    lastProgressTime_ = t;
  } else if (t - lastProgressTime_ > potential_.T3) {
    status_ = Status::Aborted;
    return {};
  }

  const geometry::Vec2 attractive = (intermediate_.position() - p) / dt;
  const geometry::Vec2 repulsive = repulsiveDirection(p, world, otherCameras, d2_) * maxVelocity;
  scene::CameraCommand u;
  u.velocity = attractive * potential_.lambda4 - repulsive * potential_.lambda5;
  u.angularVelocity = geometry::wrapAngle(intermediate_.yaw - pose.yaw) / dt;
  return u;
}

}  // namespace camcov::planners
