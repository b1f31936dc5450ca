#include "safety/safety_filter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/ring.h"
#include "safety/step_contacts.h"

namespace camcov::safety {
namespace {

// Cameras keep this far inside the boundary, m, so the simulator never has to cut a move.
constexpr double kBoundaryClearance = 1e-3;
// What the second level keeps beyond δ where it can, m: the precision of the contact accounting
// (step_contacts.h). A velocity on a half-plane's edge keeps exactly δ at the step's end, and
// the accounting, which never undercounts, cannot tell a distance that touches δ from one that
// dips below it: it counted a contact in the step's last 1/4096, judged avoidable, which then
// went on as the contact the layer could not prevent (a target closing at twice the camera's
// speed on dynamic1). Kept by this much, a touch is told apart from a contact for closing
// speeds up to kDistanceTolerance · 2^(kContactDepth + 1) / dt (8 m/s at dt = 0.1 s). Where
// only δ itself can be kept, it is kept exactly, as before.
constexpr double kSecondLevelSlack = kDistanceTolerance;
// Below this a distance has no direction: the edge's normal is used instead, m.
constexpr double kTouching = 1e-12;

geometry::Vec2 leftNormal(geometry::Vec2 a, geometry::Vec2 b) {
  const geometry::Vec2 d = b - a;
  const double length = geometry::norm(d);
  return length > 0.0 ? geometry::Vec2{-d.y, d.x} / length : geometry::Vec2{1.0, 0.0};
}

// Unit vector from `from` to `to`, or `fallback` when they (nearly) coincide.
geometry::Vec2 direction(geometry::Vec2 from, geometry::Vec2 to, geometry::Vec2 fallback) {
  const double d = geometry::distance(from, to);
  return d > kTouching ? (to - from) / d : fallback;
}

}  // namespace

const char* reasonName(ContactReason reason) {
  switch (reason) {
    case ContactReason::WithinDelta:
      return "within-delta";
    case ContactReason::Outpaced:
      return "outpaced";
    case ContactReason::Cornered:
      return "cornered";
    case ContactReason::None:
      break;
  }
  return "";
}

SafetyFilter::SafetyFilter(const scene::Scene& scene, const params::Parameters& params)
    : enabled_(params.safety.enabled),
      dt_(params.sim.dt),
      delta_(params.sim.delta),
      margin_(params.safety.margin),
      horizon_(std::max(params.safety.horizon, params.sim.dt)) {
  for (const auto& c : scene.cameras)
    maxSpeeds_.push_back(c.maxVelocity);
}

void SafetyFilter::addObject(const geometry::Ring& ring, bool isTarget, std::size_t index,
                             geometry::Vec2 p, double reach) {
  const auto source = isTarget ? Threat::Source::Target : Threat::Source::Obstacle;
  const double fastest = isTarget ? speeds_.fastestTarget(index) : speeds_.fastestObstacle(index);
  const geometry::Box box =
      geometry::grown(geometry::boundingBox(ring), reach + fastest * horizon_);
  if (!geometry::contains(box, p)) return;
  auto speedOf = [&](std::size_t v) {
    return isTarget ? speeds_.target(index, v) : speeds_.obstacle(index, v);
  };
  const std::size_t n = ring.size();
  if (geometry::locate(ring, p, 0.0) == geometry::Containment::Inside) {
    // Inside: one threat, towards the nearest way out, at minus the depth.
    double best = std::numeric_limits<double>::infinity();
    Threat inside{source, index, {}, 0.0, 0.0, 1.0};
    for (std::size_t v = 0; v < n; ++v) {
      const geometry::Vec2 a = ring[v], b = ring[(v + 1) % n];
      const geometry::Vec2 c = geometry::closestPointOnSegment(p, a, b);
      const double d = geometry::distance(p, c);
      if (d < best) {
        best = d;
        inside.normal = direction(p, c, -leftNormal(a, b));
        inside.distance = -d;
        inside.base = std::max(speedOf(v), speedOf((v + 1) % n));
      }
    }
    threats_.push_back(inside);
    return;
  }
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t w = (v + 1) % n;
    const double speed = std::max(speedOf(v), speedOf(w));
    const geometry::Vec2 c = geometry::closestPointOnSegment(p, ring[v], ring[w]);
    const double d = geometry::distance(p, c);
    // Farther than this, no velocity of the camera can make the half-plane bind.
    if (d >= reach + speed * horizon_) continue;
    // CCW ring: the outward normal is the right-hand one.
    threats_.push_back({source, index, direction(c, p, -leftNormal(ring[v], ring[w])), d, speed});
  }
}

void SafetyFilter::collect(const kinematics::World& world, std::span<const geometry::Pose> cameras,
                           std::span<const geometry::Vec2> velocities, std::size_t j) {
  threats_.clear();
  const geometry::Vec2 p = cameras[j].position();
  const double vmax = maxSpeeds_[j];
  // Hard: do not cross the boundary (inward normals: left of each CCW edge).
  const geometry::Ring& boundary = world.boundary;
  for (std::size_t v = 0; v < boundary.size(); ++v) {
    const geometry::Vec2 a = boundary[v], b = boundary[(v + 1) % boundary.size()];
    const geometry::Vec2 c = geometry::closestPointOnSegment(p, a, b);
    const double d = geometry::distance(p, c);
    if (d >= kBoundaryClearance + vmax * dt_) continue;
    threats_.push_back({Threat::Source::Boundary, v, direction(c, p, leftNormal(a, b)), d});
  }
  hardCount_ = threats_.size();
  const double reach = delta_ + margin_ + vmax * horizon_;
  for (std::size_t i = 0; i < world.targets.size(); ++i)
    addObject(world.targets[i], true, i, p, reach);
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    addObject(world.obstacles[i], false, i, p, reach);
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    if (i == j) continue;
    const geometry::Vec2 q = cameras[i].position();
    const double d = geometry::distance(p, q);
    // Beyond this neither camera's share of the closing can bind (the half share at most
    // doubles what camera j must give up).
    if (d >= reach + (vmax + maxSpeeds_[i]) * horizon_) continue;
    // Coincident cameras: separate along the index order's x axis, deterministically.
    const geometry::Vec2 n = direction(q, p, {i < j ? 1.0 : -1.0, 0.0});
    if (i < j) {
      threats_.push_back({Threat::Source::Camera, i, n, d, geometry::dot(n, velocities[i]), 1.0});
    } else {
      threats_.push_back({Threat::Source::Camera, i, n, d, 0.0, 0.5});
    }
  }
}

std::vector<HalfPlane> SafetyFilter::planes(double clearance, double T) const {
  std::vector<HalfPlane> result;
  result.reserve(threats_.size());
  for (const Threat& t : threats_) {
    if (t.source == Threat::Source::Boundary) {
      // Keep the clearance; a camera already nearer the wall must just not get closer.
      const double offset =
          t.distance >= kBoundaryClearance ? (kBoundaryClearance - t.distance) / dt_ : 0.0;
      result.push_back({t.normal, offset});
    } else {
      result.push_back({t.normal, t.base + t.share * (clearance - t.distance) / T});
    }
  }
  return result;
}

Verdict SafetyFilter::explain(const kinematics::World& world, std::size_t j, double vmax,
                              std::span<const HalfPlane> hard) const {
  // Objects by their index in the scene (the world lists only those present).
  auto name = [&world](const Threat& t) {
    switch (t.source) {
      case Threat::Source::Target:
        return fmt::format("target {}", kinematics::targetId(world, t.index));
      case Threat::Source::Obstacle:
        return fmt::format("obstacle {}", kinematics::obstacleId(world, t.index));
      case Threat::Source::Camera:
        return fmt::format("camera {}", t.index);
      case Threat::Source::Boundary:
        break;
    }
    return fmt::format("boundary edge {}", t.index);
  };
  Verdict verdict{false, ContactReason::None, {}};
  const Threat* nearest = nullptr;
  for (const Threat& t : std::span(threats_).subspan(hardCount_)) {
    if (nearest == nullptr || t.distance < nearest->distance) nearest = &t;
  }
  if (nearest != nullptr && nearest->distance < delta_) {
    verdict.reason = ContactReason::WithinDelta;
    verdict.detail = fmt::format("camera {} is {:.3f} m from {}, already closer than δ = {} m", j,
                                 nearest->distance, name(*nearest), delta_);
    return verdict;
  }
  for (std::size_t i = hardCount_; i < threats_.size(); ++i) {
    if (hard[i].offset > vmax) {
      const Threat& t = threats_[i];
      verdict.reason = ContactReason::Outpaced;
      verdict.detail = fmt::format(
          "{} is {:.3f} m from camera {} and may close at {:.2f} m/s; the camera can move "
          "away at {:.2f} m/s, and needs {:.2f} m/s to keep δ = {} m for the next {} s",
          name(t), t.distance, j, t.base, vmax, hard[i].offset, delta_, dt_);
      return verdict;
    }
  }
  // Each threat alone can be escaped: list what hems the camera in.
  std::string what;
  for (std::size_t i = 0; i < threats_.size(); ++i) {
    const Threat& t = threats_[i];
    if (t.source == Threat::Source::Boundary && t.distance > kBoundaryClearance + vmax * dt_)
      continue;
    what += fmt::format("{}{} at {:.3f} m", what.empty() ? "" : ", ", name(t), t.distance);
  }
  verdict.reason = ContactReason::Cornered;
  verdict.detail = fmt::format("camera {} (up to {:.2f} m/s) is hemmed in by {}", j, vmax, what);
  return verdict;
}

void SafetyFilter::apply(const kinematics::World& world, std::span<const geometry::Pose> cameras,
                         std::span<geometry::Vec2> velocities) {
  speeds_.observe(world);
  verdicts_.assign(cameras.size(), Verdict{});
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    collect(world, cameras, velocities, j);
    const double vmax = maxSpeeds_[j];
    const geometry::Vec2 desired = velocities[j];
    std::optional<geometry::Vec2> u =
        closestAdmissibleVelocity(planes(delta_ + margin_, horizon_), vmax, desired);
    if (!u) u = closestAdmissibleVelocity(planes(delta_ + kSecondLevelSlack, dt_), vmax, desired);
    const std::vector<HalfPlane> hard = planes(delta_, dt_);
    const std::optional<geometry::Vec2> keeping = closestAdmissibleVelocity(hard, vmax, desired);
    if (!u) u = keeping;
    // δ is kept over the step only if it holds now, at the step's first instant, too.
    const bool withinDelta =
        std::any_of(threats_.begin() + static_cast<std::ptrdiff_t>(hardCount_), threats_.end(),
                    [this](const Threat& t) { return t.distance < delta_; });
    if (!keeping || withinDelta) verdicts_[j] = explain(world, j, vmax, hard);
    if (!u) u = leastViolatingVelocity(hard, hardCount_, vmax, desired).velocity;
    if (enabled_) velocities[j] = *u;
  }
}

}  // namespace camcov::safety
