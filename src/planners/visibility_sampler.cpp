#include "planners/visibility_sampler.h"

#include <algorithm>
#include <cmath>

namespace camcov::planners {

namespace {

template <typename Edges>
std::optional<geometry::Vec2> sampleOnEdges(const Edges& forEachEdge, Random& random) {
  double total = 0.0;
  forEachEdge([&](geometry::Vec2 a, geometry::Vec2 b) { total += geometry::distance(a, b); });
  if (!(total > 0.0)) return std::nullopt;
  double target = random.uniform() * total;
  std::optional<geometry::Vec2> result;
  forEachEdge([&](geometry::Vec2 a, geometry::Vec2 b) {
    if (result) return;
    const double length = geometry::distance(a, b);
    if (target < length) {
      result = geometry::lerp(a, b, target / length);
    } else {
      target -= length;
    }
  });
  return result;
}

}  // namespace

std::optional<geometry::Vec2> samplePointOnSegments(std::span<const visibility::Segment> segments,
                                                    Random& random) {
  return sampleOnEdges(
      [&](auto&& visit) {
        for (const auto& s : segments)
          visit(s.a, s.b);
      },
      random);
}

std::optional<geometry::Vec2> samplePointOnRings(std::span<const geometry::Ring> rings,
                                                 Random& random) {
  return sampleOnEdges(
      [&](auto&& visit) {
        for (const auto& ring : rings) {
          for (std::size_t i = 0; i < ring.size(); ++i)
            visit(ring[i], ring[(i + 1) % ring.size()]);
        }
      },
      random);
}

double sampleYawSeeing(geometry::Vec2 q2, geometry::Vec2 q1, double halfFov, Random& random) {
  const geometry::Vec2 d = q1 - q2;
  return geometry::wrapAngle(std::atan2(d.y, d.x) + random.uniform(-halfFov, halfFov));
}

void PolygonSampler::reset(const geometry::Ring& polygon, geometry::Vec2 viewpoint) {
  triangles_.clear();
  cumulativeArea_.clear();
  double total = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const geometry::Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const double area = 0.5 * std::abs(geometry::orient(viewpoint, a, b));
    if (!(area > 0.0)) continue;  // flat fan triangles at the viewpoint
    total += area;
    triangles_.insert(triangles_.end(), {viewpoint, a, b});
    cumulativeArea_.push_back(total);
  }
}

std::optional<geometry::Vec2> PolygonSampler::sample(Random& random, const StateValidity& validity,
                                                     int attempts) const {
  if (cumulativeArea_.empty()) return std::nullopt;
  for (int i = 0; i < attempts; ++i) {
    const double pick = random.uniform() * cumulativeArea_.back();
    const std::size_t t = static_cast<std::size_t>(
        std::upper_bound(cumulativeArea_.begin(), cumulativeArea_.end(), pick) -
        cumulativeArea_.begin());
    const std::size_t k = 3 * std::min(t, cumulativeArea_.size() - 1);
    // Uniform in a triangle: fold the unit square's upper half back onto the lower.
    double u = random.uniform(), v = random.uniform();
    if (u + v > 1.0) {
      u = 1.0 - u;
      v = 1.0 - v;
    }
    const geometry::Vec2 p = triangles_[k] + (triangles_[k + 1] - triangles_[k]) * u +
                             (triangles_[k + 2] - triangles_[k]) * v;
    if (validity.isValid(p)) return p;
  }
  return std::nullopt;
}

bool VisibilitySampler::focus(reward::RewardModel& model, geometry::Vec2 q1) {
  q1_ = q1;
  model.visibilityPolygon(q1, polygon_);
  area_.reset(polygon_, q1);
  return area_.area() > 0.0;
}

bool VisibilitySampler::focusOnUnseen(reward::RewardModel& model, Random& random) {
  unseen_.clear();
  for (const auto& s : model.segments()) {
    if (s.visibleBy.empty()) unseen_.push_back(s);
  }
  auto q1 = samplePointOnSegments(unseen_, random);
  if (!q1) q1 = samplePointOnSegments(model.segments(), random);
  return q1 && focus(model, *q1);
}

std::optional<geometry::Pose> VisibilitySampler::sample(Random& random,
                                                        const StateValidity& validity,
                                                        const scene::Lens& lens) const {
  // A camera with a sensing range must stand within it of q1: farther places are drawn again
  // (an unlimited lens takes the first, so the draws are the paper's).
  for (int attempt = 0; attempt < kAttemptsPerSample; ++attempt) {
    const auto q2 = area_.sample(random, validity, kAttemptsPerSample);
    if (!q2) return std::nullopt;
    if (lens.withinRange(geometry::distance(*q2, q1_)))
      return geometry::Pose{q2->x, q2->y, sampleYawSeeing(*q2, q1_, lens.halfFov, random)};
  }
  return std::nullopt;
}

}  // namespace camcov::planners
