#include "reward/metrics.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "reward/fixed_point_sum.h"
#include "reward/resolution_coverage.h"
#include "visibility/sweep.h"

namespace camcov::reward {

namespace {

// Segments next to each other in S on one target edge: S cuts each edge into consecutive
// pieces, with the unseen ones between the seen ones.
bool sameEdge(const visibility::Segment& a, const visibility::Segment& b) {
  return a.target == b.target && a.edge == b.edge;
}

// Calls f(first, last) for each run of consecutive seen segments of one edge.
template <class F>
void forEachSeenRun(std::span<const visibility::Segment> segments, F&& f) {
  const visibility::Segment* first = nullptr;  // of the run of seen segments being walked
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& s = segments[i];
    if (s.visibleBy.empty()) continue;
    if (first == nullptr) first = &s;
    const bool runGoesOn = i + 1 < segments.size() && !segments[i + 1].visibleBy.empty() &&
                           sameEdge(s, segments[i + 1]);
    if (!runGoesOn) {
      f(*first, s);
      first = nullptr;
    }
  }
}

}  // namespace

double visibleLength(std::span<const visibility::Segment> segments) {
  FixedPointSum total;
  forEachSeenRun(segments, [&](const visibility::Segment& first, const visibility::Segment& last) {
    total.add(FixedPointSum::units(geometry::distance(first.a, last.b)));
  });
  return total.value();
}

double weightedVisibleLength(std::span<const visibility::Segment> segments,
                             const std::vector<std::vector<double>>& weights) {
  if (weights.empty()) return visibleLength(segments);
  FixedPointSum total;
  forEachSeenRun(segments, [&](const visibility::Segment& first, const visibility::Segment& last) {
    const double w = weights[first.target][first.edge];
    total.add(FixedPointSum::units(w * geometry::distance(first.a, last.b)));
  });
  return total.value();
}

double targetPerimeter(const kinematics::World& world) {
  double total = 0.0;
  for (const auto& target : world.targets)
    total += geometry::perimeter(target);
  return total;
}

double weightedPerimeter(const kinematics::World& world) {
  if (world.targetEdgeWeights.empty()) return targetPerimeter(world);
  double total = 0.0;
  for (std::size_t i = 0; i < world.targets.size(); ++i) {
    const geometry::Ring& ring = world.targets[i];
    double length = 0.0;  // as geometry::perimeter() adds them
    for (std::size_t e = 0, n = ring.size(); e < n; ++e)
      length += world.targetEdgeWeights[i][e] * geometry::distance(ring[e], ring[(e + 1) % n]);
    total += length;
  }
  return total;
}

double weightedCoverage(std::span<const visibility::Segment> segments,
                        const kinematics::World& world) {
  return coverageOf(weightedVisibleLength(segments, world.targetEdgeWeights),
                    weightedPerimeter(world));
}

RewardTerms termsAlone(const kinematics::World& world,
                       std::span<const visibility::Segment> segments,
                       std::span<const geometry::Pose> cameras, std::span<const scene::Lens> lenses,
                       std::size_t j, const params::RewardParams& params) {
  std::vector<visibility::Segment> own;
  for (visibility::Segment s : segments) {
    if (!s.visibleBy.contains(j)) continue;
    s.visibleBy = scene::CameraSet::only(0);  // camera 0 of a team of one
    own.push_back(s);
  }
  const geometry::Pose& pose = cameras[j];
  RewardTerms t;
  t.coverage = coverage(own, targetPerimeter(world));
  t.weightedCoverage = weightedCoverage(own, world);
  t.utilization = utilization(own, std::span(&pose, 1), lenses.subspan(j, 1));
  t.resolutionCoverage = rewardedResolutionCoverage(params, world, own, std::span(&pose, 1),
                                                    lenses.subspan(j, 1), targetPerimeter(world));
  t.repulsion = repulsion(world, std::span(&pose, 1), params.d2);
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    if (i != j) t.repulsion += pairTerm(pose.position(), cameras[i].position(), params.d2);
  }
  t.reward = combine(params, coverageTerm(params, t), t.utilization, t.repulsion);
  return t;
}

double coverage(std::span<const visibility::Segment> segments, double perimeter) {
  return coverageOf(visibleLength(segments), perimeter);
}

double coverageOf(double visibleLength, double perimeter) {
  return perimeter > 0.0 ? visibleLength / perimeter : 0.0;
}

double subtendedAngle(geometry::Vec2 a, geometry::Vec2 b, geometry::Vec2 p) {
  const geometry::Vec2 u = a - p, v = b - p;
  return std::abs(std::atan2(geometry::cross(u, v), geometry::dot(u, v)));
}

double utilizationOf(std::span<const double> angles, std::span<const scene::Lens> lenses) {
  if (angles.empty()) return 0.0;
  // Σ_j angle_j / 2θ_j, summed as Σ_j (θ_0/θ_j) · angle_j, then over 2θ_0: for a team of
  // like cameras every weight θ_0/θ_0 is exactly 1 (IEEE division), so the sum is eq. (5)
  // as written, to the bit.
  double weighted = 0.0;
  for (std::size_t j = 0; j < angles.size(); ++j)
    weighted += utilizationWeight(lenses[0], lenses[j]) * angles[j];
  return weighted / (2.0 * lenses[0].halfFov) / static_cast<double>(angles.size());
}

double utilization(std::span<const visibility::Segment> segments,
                   std::span<const geometry::Pose> cameras, std::span<const scene::Lens> lenses) {
  // Per camera, the run it is in: its first point and its last segment (an index of S).
  constexpr std::size_t kNone = SIZE_MAX;
  struct Run {
    geometry::Vec2 a;
    std::size_t last = kNone;
  };
  std::array<Run, scene::kMaxCameras> runs;
  std::array<double, scene::kMaxCameras> angles{};
  const auto close = [&](std::size_t j) {
    if (runs[j].last == kNone) return;
    angles[j] += subtendedAngle(runs[j].a, segments[runs[j].last].b, cameras[j].position());
    runs[j].last = kNone;
  };
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& s = segments[i];
    s.visibleBy.forEach([&](std::size_t j) {
      Run& run = runs[j];
      // A run goes on while its camera sees the next piece of the same edge.
      if (run.last != kNone && !(run.last + 1 == i && sameEdge(segments[run.last], s))) close(j);
      if (run.last == kNone) run.a = s.a;
      run.last = i;
    });
  }
  for (std::size_t j = 0; j < cameras.size(); ++j)
    close(j);
  return utilizationOf(std::span(angles.data(), cameras.size()), lenses);
}

double visibleLengthOf(std::span<const visibility::Segment> segments, unsigned camera) {
  double total = 0.0;
  for (const auto& s : segments) {
    if (s.visibleBy.contains(camera)) total += visibility::length(s);
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
  return repulsion(world, objectBoxes(world), cameras, d2);
}

std::vector<geometry::Box> objectBoxes(const kinematics::World& world) {
  std::vector<geometry::Box> boxes;
  boxes.reserve(world.targets.size() + world.obstacles.size());
  for (const auto* objects : {&world.targets, &world.obstacles}) {
    for (const auto& object : *objects)
      boxes.push_back(geometry::boundingBox(object));
  }
  return boxes;
}

namespace {

// Some point of `box` is nearer p than d2, give or take rounding: the box's distance is a
// lower bound of the polygon's, and 1e-9 relative slack keeps an object at d2 to the last bit
// measured, whatever rounding the two distances have.
bool mayBeWithin(const geometry::Box& box, geometry::Vec2 p, double d2) {
  return geometry::squaredDistance(box, p) <= d2 * d2 * (1.0 + 1e-9);
}

}  // namespace

std::vector<double>& objectTerms(const kinematics::World& world,
                                 std::span<const geometry::Box> boxes, geometry::Vec2 p, double d2,
                                 std::vector<double>& out) {
  out.clear();
  std::size_t k = 0;
  for (const auto* objects : {&world.targets, &world.obstacles}) {
    for (const auto& object : *objects) {
      if (!mayBeWithin(boxes[k++], p, d2)) continue;
      const double term = invdist(geometry::distanceToPolygon(object, p), d2);
      if (term != 0.0) out.push_back(term);
    }
  }
  return out;
}

double repulsion(const kinematics::World& world, std::span<const geometry::Box> boxes,
                 std::span<const geometry::Pose> cameras, double d2) {
  FixedPointSum total;
  std::vector<double> terms;
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    const geometry::Vec2 p = cameras[j].position();
    for (const double term : objectTerms(world, boxes, p, d2, terms))
      total.add(FixedPointSum::units(term));
    for (std::size_t i = 0; i < j; ++i)
      total.add(FixedPointSum::units(pairTerm(cameras[i].position(), p, d2)));
  }
  return total.value();
}

double pairTerm(geometry::Vec2 a, geometry::Vec2 b, double d2) {
  // Most pairs are far apart: their term is 0 without a square root (with slack, so that a
  // distance of d2 to the last bit is still measured).
  const geometry::Vec2 d = a - b;
  if (d.x * d.x + d.y * d.y > d2 * d2 * (1.0 + 1e-9)) return 0.0;
  return invdist(geometry::distance(a, b), d2);
}

double combine(const params::RewardParams& p, double coverage, double utilization,
               double repulsion) {
  return p.lambda1 * coverage + p.lambda2 * utilization - p.lambda3 * repulsion;
}

double rewardCeiling(const params::RewardParams& p) {
  if (p.lambda3 < 0.0) return std::numeric_limits<double>::infinity();
  return std::max(p.lambda1, 0.0) + std::max(p.lambda2, 0.0);
}

}  // namespace camcov::reward
