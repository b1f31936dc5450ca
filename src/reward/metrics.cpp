#include "reward/metrics.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "visibility/sweep.h"

namespace camcov::reward {

double visibleLength(std::span<const visibility::Segment> segments) {
  double total = 0.0;
  for (const auto& s : segments) {
    if (s.visibleBy != 0) total += visibility::length(s);
  }
  return total;
}

double targetPerimeter(const kinematics::World& world) {
  double total = 0.0;
  for (const auto& target : world.targets)
    total += geometry::perimeter(target);
  return total;
}

double coverage(std::span<const visibility::Segment> segments, double perimeter) {
  return perimeter > 0.0 ? visibleLength(segments) / perimeter : 0.0;
}

double utilization(std::span<const visibility::Segment> segments,
                   std::span<const geometry::Pose> cameras, std::span<const double> halfFovs) {
  if (cameras.empty()) return 0.0;
  // Σ_j angle_j / 2θ_j, summed as Σ_j (θ_0/θ_j) · angle_j, then over 2θ_0: for a team of
  // like cameras every weight θ_0/θ_0 is exactly 1 (IEEE division), so the sum is eq. (5)
  // as written, to the bit.
  const double theta0 = halfFovs[0];
  std::array<double, visibility::Sweep::kMaxCameras> weight;  // θ_0/θ_j, once per camera
  for (std::size_t j = 0; j < cameras.size(); ++j)
    weight[j] = theta0 / halfFovs[j];
  double angles = 0.0;
  for (const auto& s : segments) {
    for (std::uint64_t bits = s.visibleBy; bits != 0; bits &= bits - 1) {
      const int j = std::countr_zero(bits);
      const geometry::Vec2 p = cameras[j].position();
      const geometry::Vec2 u = s.a - p, v = s.b - p;
      angles += weight[j] * std::abs(std::atan2(geometry::cross(u, v), geometry::dot(u, v)));
    }
  }
  return angles / (2.0 * theta0) / static_cast<double>(cameras.size());
}

double visibleLengthOf(std::span<const visibility::Segment> segments, unsigned camera) {
  double total = 0.0;
  for (const auto& s : segments) {
    if ((s.visibleBy >> camera) & 1u) total += visibility::length(s);
  }
  return total;
}

double invdist(double distance, double d2) {
  if (distance >= d2) return 0.0;
  const double d = std::max(distance, kMinDistance);
  return 1.0 / (d * d);
}

double repulsion(const kinematics::World& world, std::span<const geometry::Pose> cameras,
                 double d2) {
  double total = 0.0;
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    const geometry::Vec2 p = cameras[j].position();
    for (const auto* objects : {&world.targets, &world.obstacles}) {
      for (const auto& object : *objects) {
        total += invdist(geometry::distanceToPolygon(object, p), d2);
      }
    }
    for (std::size_t i = 0; i < j; ++i) {
      total += invdist(geometry::distance(cameras[i].position(), p), d2);
    }
  }
  return total;
}

double combine(const params::RewardParams& p, double coverage, double utilization,
               double repulsion) {
  return p.lambda1 * coverage + p.lambda2 * utilization - p.lambda3 * repulsion;
}

}  // namespace camcov::reward
