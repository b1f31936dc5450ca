#include "labels/label_placer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace camcov::labels {

bool segmentMeetsBox(Vec2 a, Vec2 b, const Box& box) {
  const Vec2 d = b - a;
  const double p[] = {-d.x, d.x, -d.y, d.y};
  const double q[] = {a.x - box.min.x, box.max.x - a.x, a.y - box.min.y, box.max.y - a.y};
  double t0 = 0.0, t1 = 1.0;
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;  // parallel to this side and outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
  }
  return true;
}

bool polygonMeetsBox(std::span<const Vec2> ring, const Box& box) {
  if (ring.empty()) return false;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    if (segmentMeetsBox(ring[i], ring[(i + 1) % n], box)) return true;
  }
  // No edge meets the box: either is wholly inside the other, or they are apart.
  return geometry::contains(box, ring.front()) ||
         geometry::locate(ring, box.min, 0.0) != geometry::Containment::Outside;
}

std::vector<Box> boxesAround(const Box& around, Vec2 size, Vec2 first,
                             std::span<const double> gaps) {
  const Vec2 centre = (around.min + around.max) * 0.5;
  const Vec2 half = (around.max - around.min) * 0.5;
  constexpr int kDirections = 16;
  const double start = std::atan2(first.y, first.x);
  std::vector<Box> out;
  for (const double gap : gaps) {
    for (int k = 0; k < kDirections; ++k) {
      const int step = (k + 1) / 2 * (k % 2 == 0 ? 1 : -1);  // 0, -1, 1, -2, 2, ...
      const double a = start + step * 2.0 * std::numbers::pi / kDirections;
      const Vec2 u{std::cos(a), std::sin(a)};
      // Where the ray from the centre leaves the box grown by the gap.
      constexpr double kNever = std::numeric_limits<double>::infinity();
      const double reach =
          std::min(std::abs(u.x) > 1e-12 ? (half.x + gap) / std::abs(u.x) : kNever,
                   std::abs(u.y) > 1e-12 ? (half.y + gap) / std::abs(u.y) : kNever);
      const Vec2 at = centre + u * reach;
      const double left = u.x > 0.4 ? at.x : u.x < -0.4 ? at.x - size.x : at.x - size.x / 2;
      const double top = u.y > 0.4 ? at.y : u.y < -0.4 ? at.y - size.y : at.y - size.y / 2;
      out.push_back({{left, top}, {left + size.x, top + size.y}});
    }
  }
  return out;
}

void LabelPlacer::avoidLine(std::span<const Vec2> points, bool closed) {
  if (points.empty()) return;
  obstacles_.push_back(
      {geometry::boundingBox(points), {points.begin(), points.end()}, closed, false});
}

void LabelPlacer::avoidArea(std::span<const Vec2> ring) {
  if (ring.empty()) return;
  obstacles_.push_back({geometry::boundingBox(ring), {ring.begin(), ring.end()}, true, true});
}

void LabelPlacer::avoidBox(const Box& box) {
  avoidArea(geometry::ringOf(box));
}

bool LabelPlacer::clear(const Box& box) const {
  if (!geometry::contains(canvas_, box)) return false;
  const Box around = geometry::grown(box, gap_);
  for (const Box& label : placed_) {
    if (geometry::overlaps(label, around)) return false;
  }
  for (const Obstacle& o : obstacles_) {
    if (!geometry::overlaps(o.bounds, around)) continue;
    if (o.filled) {
      if (polygonMeetsBox(o.points, around)) return false;
      continue;
    }
    const std::size_t n = o.points.size();
    if (n == 1 && geometry::contains(around, o.points.front())) return false;
    const std::size_t edges = o.closed ? n : n - 1;
    for (std::size_t i = 0; i < edges; ++i) {
      if (segmentMeetsBox(o.points[i], o.points[(i + 1) % n], around)) return false;
    }
  }
  return true;
}

std::optional<std::size_t> LabelPlacer::place(std::span<const Box> candidates) {
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (clear(candidates[i])) {
      placed_.push_back(candidates[i]);
      return i;
    }
  }
  return std::nullopt;
}

}  // namespace camcov::labels
