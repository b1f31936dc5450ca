#include "reward/resolution_coverage.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>
#include <vector>

#include "geometry/ring.h"
#include "reward/metrics.h"

namespace camcov::reward {
namespace {

// One camera that sees a segment from a + t (b − a): ρ(t) = k·h / |f + t·d|², with f = a − c,
// d = b − a (the squared distance as dd·t² + 2·fd·t + ff).
struct Viewer {
  geometry::Vec2 position;
  double k = 0.0;   // k_j, pixels per radian
  double kh = 0.0;  // k_j · h_j, with h_j the distance from the camera to the edge's line, m
  double dd = 0.0, fd = 0.0, ff = 0.0;

  double squaredDistance(double t) const { return (dd * t + 2.0 * fd) * t + ff; }
  double density(double t) const {
    const double d2 = squaredDistance(t);
    return d2 > 0.0 ? kh / d2 : 0.0;
  }
};

Viewer viewer(geometry::Vec2 camera, const scene::Lens& lens, geometry::Vec2 a, geometry::Vec2 b) {
  const geometry::Vec2 d = b - a, f = a - camera;
  const double h = std::abs(geometry::cross(d, f)) / geometry::norm(d);
  const double k = lens.pixelsPerRadian();
  return {camera, k, k * h, geometry::dot(d, d), geometry::dot(f, d), geometry::dot(f, f)};
}

// Adds the roots of A t² + B t + C = 0 inside (0, 1) to `out`.
void rootsInside(double A, double B, double C, std::vector<double>& out) {
  const auto keep = [&](double t) {
    if (t > 0.0 && t < 1.0) out.push_back(t);
  };
  if (A == 0.0) {
    if (B != 0.0) keep(-C / B);
    return;
  }
  const double discriminant = B * B - 4.0 * A * C;
  if (discriminant < 0.0) return;
  // The root of larger magnitude first, then the other from their product: no cancellation.
  const double q = -0.5 * (B + std::copysign(std::sqrt(discriminant), B));
  keep(q / A);
  if (q != 0.0) keep(C / q);
}

// Threshold: the union of the intervals of t where some viewer's density reaches ρ_min, the
// disc of radius √(k·h/ρ_min) about it.
// Where some viewer reaches ρ_min: the union of each one's interval (ρ_j ≥ ρ_min is a disc about
// the camera), as disjoint intervals of t along the segment from a to b, in order.
std::vector<std::pair<double, double>> resolvedIntervals(std::span<const Viewer> viewers,
                                                         geometry::Vec2 a, geometry::Vec2 b,
                                                         double minDensity) {
  std::vector<std::pair<double, double>> intervals;
  for (const Viewer& v : viewers) {
    double t0 = 0.0, t1 = 0.0;
    if (geometry::discOnSegment(v.position, std::sqrt(v.kh / minDensity), a, b, t0, t1))
      intervals.emplace_back(t0, t1);
  }
  std::sort(intervals.begin(), intervals.end());
  std::vector<std::pair<double, double>> merged;
  for (const auto& [lo, hi] : intervals) {
    if (!(hi > lo)) continue;
    if (!merged.empty() && lo <= merged.back().second) {
      merged.back().second = std::max(merged.back().second, hi);
    } else {
      merged.emplace_back(lo, hi);
    }
  }
  return merged;
}

double resolvedFraction(std::span<const Viewer> viewers, geometry::Vec2 a, geometry::Vec2 b,
                        double minDensity) {
  double covered = 0.0;
  for (const auto& [lo, hi] : resolvedIntervals(viewers, a, b, minDensity))
    covered += hi - lo;
  return covered;
}

// Proportional: ∫ max_j min(1, ρ_j/ρ_min) over the segment, in pieces where the best viewer and
// whether it reaches ρ_min stay the same.
double proportionalLength(std::span<const Viewer> viewers, geometry::Vec2 a, geometry::Vec2 b,
                          double minDensity) {
  std::vector<double> cuts{0.0, 1.0};
  for (std::size_t i = 0; i < viewers.size(); ++i) {
    const Viewer& v = viewers[i];
    // ρ_i = ρ_min ⇔ ρ_min·|p − c_i|² − k_i·h_i = 0
    rootsInside(minDensity * v.dd, 2.0 * minDensity * v.fd, minDensity * v.ff - v.kh, cuts);
    for (std::size_t j = i + 1; j < viewers.size(); ++j) {
      // ρ_i = ρ_j ⇔ k_i h_i·|p − c_j|² − k_j h_j·|p − c_i|² = 0
      const Viewer& w = viewers[j];
      rootsInside(v.kh * w.dd - w.kh * v.dd, 2.0 * (v.kh * w.fd - w.kh * v.fd),
                  v.kh * w.ff - w.kh * v.ff, cuts);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  const double length = geometry::distance(a, b);
  double total = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double t0 = cuts[k], t1 = cuts[k + 1];
    if (!(t1 > t0)) continue;
    const double middle = 0.5 * (t0 + t1);
    const Viewer* best = &viewers[0];
    for (const Viewer& v : viewers) {
      if (v.density(middle) > best->density(middle)) best = &v;
    }
    if (best->density(middle) >= minDensity) {
      total += (t1 - t0) * length;
    } else {
      // ∫ ρ ds = ∫ k·h/d² ds = k · (the angle the piece subtends at the camera).
      const geometry::Vec2 p0 = visibility::pointAt(a, b, t0), p1 = visibility::pointAt(a, b, t1);
      total += best->k * subtendedAngle(p0, p1, best->position) / minDensity;
    }
  }
  return total;
}

// The cameras that see `segment` (its visibleBy), as viewers of it.
struct Viewers {
  Viewer viewers[scene::kMaxCameras];
  std::size_t count = 0;
  Viewers(const visibility::Segment& segment, std::span<const geometry::Pose> cameras,
          std::span<const scene::Lens> lenses) {
    segment.visibleBy.forEach([&](std::size_t j) {
      viewers[count++] = viewer(cameras[j].position(), lenses[j], segment.a, segment.b);
    });
  }
  std::span<const Viewer> all() const { return {viewers, count}; }
};

}  // namespace

double pixelDensity(geometry::Vec2 camera, const scene::Lens& lens, geometry::Vec2 a,
                    geometry::Vec2 b, geometry::Vec2 p) {
  const geometry::Vec2 e = (b - a) / geometry::norm(b - a), r = p - camera;
  const double d2 = geometry::dot(r, r);
  return d2 > 0.0 ? lens.pixelsPerRadian() * std::abs(geometry::cross(e, r)) / d2 : 0.0;
}

double resolvedLength(const visibility::Segment& segment, std::span<const geometry::Pose> cameras,
                      std::span<const scene::Lens> lenses,
                      const scene::ResolutionRequirement& requirement) {
  if (segment.visibleBy.empty() || segment.a == segment.b) return 0.0;
  const Viewers seeing(segment, cameras, lenses);
  const std::span<const Viewer> seenBy = seeing.all();
  if (requirement.proportional)
    return std::min(proportionalLength(seenBy, segment.a, segment.b, requirement.minDensity),
                    length(segment));
  return resolvedFraction(seenBy, segment.a, segment.b, requirement.minDensity) * length(segment);
}

double resolutionCoverage(std::span<const visibility::Segment> segments,
                          std::span<const geometry::Pose> cameras,
                          std::span<const scene::Lens> lenses,
                          const scene::ResolutionRequirement& requirement, double perimeter) {
  double resolved = 0.0;
  for (const visibility::Segment& s : segments)
    resolved += resolvedLength(s, cameras, lenses, requirement);
  return coverageOf(resolved, perimeter);
}

void addUnresolvedPieces(const visibility::Segment& segment,
                         std::span<const geometry::Pose> cameras,
                         std::span<const scene::Lens> lenses, double minDensity,
                         std::vector<visibility::Segment>& out) {
  if (segment.visibleBy.empty() || segment.a == segment.b) return;
  const Viewers seeing(segment, cameras, lenses);
  const auto piece = [&](double from, double to) {
    if (!(to > from)) return;
    visibility::Segment s = segment;
    s.a = visibility::pointAt(segment.a, segment.b, from);
    s.b = visibility::pointAt(segment.a, segment.b, to);
    out.push_back(s);
  };
  double from = 0.0;
  for (const auto& [lo, hi] : resolvedIntervals(seeing.all(), segment.a, segment.b, minDensity)) {
    piece(from, lo);
    from = std::max(from, hi);
  }
  piece(from, 1.0);
}

std::optional<double> rewardedResolutionCoverage(const params::RewardParams& params,
                                                 const kinematics::World& world,
                                                 std::span<const visibility::Segment> segments,
                                                 std::span<const geometry::Pose> cameras,
                                                 std::span<const scene::Lens> lenses,
                                                 double perimeter) {
  if (!params.resolution || !world.resolution) return std::nullopt;
  // Each point's credit min(1, ρ/ρ_min), whichever form the scene measures: a camera a little
  // too far still earns most of what it would earn nearer, so the optimizers' steps and samples
  // see where resolution grows instead of a cliff at ρ_min. On recorded pedestrian windows apart
  // from scenes/real (docs/scene-format.md) it resolved more than the threshold itself did.
  scene::ResolutionRequirement credit = *world.resolution;
  credit.proportional = true;
  return resolutionCoverage(segments, cameras, lenses, credit, perimeter);
}

}  // namespace camcov::reward
