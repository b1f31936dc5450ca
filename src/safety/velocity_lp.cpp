#include "safety/velocity_lp.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace camcov::safety {
namespace {

// Slack for rounding when a half-plane is tested or two bounds meet, m/s.
constexpr double kSlack = 1e-12;

// The point of line i (normal·u = offset) inside the disc and the earlier half-planes that
// is closest to `desired`, or nothing if that part of the line is empty.
std::optional<geometry::Vec2> closestOnLine(std::span<const HalfPlane> earlier,
                                            const HalfPlane& line, double maxSpeed,
                                            geometry::Vec2 desired) {
  // u(t) = origin + t·direction; origin is the line's point nearest the disc's centre.
  const geometry::Vec2 origin = line.normal * line.offset;
  const geometry::Vec2 direction{-line.normal.y, line.normal.x};
  const double chord2 = maxSpeed * maxSpeed - line.offset * line.offset;
  if (chord2 < -kSlack) return std::nullopt;  // the line misses the disc
  const double half = std::sqrt(std::max(0.0, chord2));
  double lo = -half, hi = half;
  for (const HalfPlane& h : earlier) {
    const double rate = geometry::dot(h.normal, direction);          // d(normal·u)/dt
    const double need = h.offset - geometry::dot(h.normal, origin);  // rate·t ≥ need
    if (std::abs(rate) <= 1e-15) {
      if (need > kSlack) return std::nullopt;  // parallel and on the wrong side
      continue;
    }
    if (rate > 0.0) {
      lo = std::max(lo, need / rate);
    } else {
      hi = std::min(hi, need / rate);
    }
    if (lo > hi + kSlack) return std::nullopt;
  }
  const double t =
      lo > hi ? 0.5 * (lo + hi) : std::clamp(geometry::dot(direction, desired - origin), lo, hi);
  return origin + direction * t;
}

}  // namespace

std::optional<geometry::Vec2> closestAdmissibleVelocity(std::span<const HalfPlane> constraints,
                                                        double maxSpeed, geometry::Vec2 desired) {
  const double speed = geometry::norm(desired);
  geometry::Vec2 u = speed > maxSpeed ? desired * (maxSpeed / speed) : desired;
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    if (geometry::dot(constraints[i].normal, u) >= constraints[i].offset - kSlack) continue;
    const auto onLine = closestOnLine(constraints.first(i), constraints[i], maxSpeed, desired);
    if (!onLine) return std::nullopt;
    u = *onLine;
  }
  return u;
}

LeastViolation leastViolatingVelocity(std::span<const HalfPlane> constraints, std::size_t hardCount,
                                      double maxSpeed, geometry::Vec2 desired) {
  std::vector<HalfPlane> relaxed(constraints.begin(), constraints.end());
  auto relax = [&](double s) {
    for (std::size_t i = hardCount; i < relaxed.size(); ++i)
      relaxed[i].offset = constraints[i].offset - s;
    return closestAdmissibleVelocity(relaxed, maxSpeed, desired);
  };
  // u = 0 meets the hard half-planes, and the soft ones once s reaches their largest offset.
  double feasible = 0.0;
  for (std::size_t i = hardCount; i < constraints.size(); ++i)
    feasible = std::max(feasible, constraints[i].offset);
  if (const auto u = relax(0.0)) return {*u, 0.0};
  double infeasible = 0.0;
  // 60 halvings take the bracket below 1e-18 of its width: as exact as doubles allow.
  for (int k = 0; k < 60 && feasible - infeasible > 1e-12 * std::max(1.0, feasible); ++k) {
    const double mid = 0.5 * (infeasible + feasible);
    (relax(mid) ? feasible : infeasible) = mid;
  }
  const auto u = relax(feasible);
  return {u.value_or(geometry::Vec2{}), feasible};
}

}  // namespace camcov::safety
