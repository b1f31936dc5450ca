#include "scene/motion_containment.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <tuple>

#include "geometry/ring.h"
#include "scene/deformation.h"

namespace camcov::scene {
namespace {

using geometry::Containment;
using geometry::Vec2;

// The parameters in [0, 1] at which segment [a, b] meets segment [c, d] (both ends of an
// overlap where they are collinear).
void meetings(Vec2 a, Vec2 b, Vec2 c, Vec2 d, std::vector<double>& out) {
  if (!geometry::segmentsIntersect(a, b, c, d)) return;
  const Vec2 ab = b - a, cd = d - c;
  const double denominator = geometry::cross(ab, cd);
  const double length2 = geometry::dot(ab, ab);
  if (denominator == 0.0) {  // collinear: where c and d project onto [a, b]
    if (length2 == 0.0) return;
    for (const Vec2 p : {c, d})
      out.push_back(std::clamp(geometry::dot(p - a, ab) / length2, 0.0, 1.0));
    return;
  }
  out.push_back(std::clamp(geometry::cross(c - a, cd) / denominator, 0.0, 1.0));
}

// The pieces of segment [a, b] (as parameter intervals) that lie `bad` with respect to
// `ring`, judged at the middle of each piece between the places where it meets the ring's
// `edges` (the indices of the edges that can meet it: those near it). A segment that meets
// none lies on one side: `uncutBad` says which when the caller knows, else it is located.
template <class Bad>
std::vector<std::pair<double, double>> badPieces(Vec2 a, Vec2 b, const geometry::Ring& ring,
                                                 std::span<const std::size_t> edges,
                                                 std::optional<bool> uncutBad, const Bad& bad) {
  std::vector<double> cuts{0.0, 1.0};
  const double minX = std::min(a.x, b.x), maxX = std::max(a.x, b.x);
  const double minY = std::min(a.y, b.y), maxY = std::max(a.y, b.y);
  for (const std::size_t i : edges) {
    const Vec2 c = ring[i], d = ring[(i + 1) % ring.size()];
    if (std::max(c.x, d.x) < minX || std::min(c.x, d.x) > maxX || std::max(c.y, d.y) < minY ||
        std::min(c.y, d.y) > maxY)
      continue;
    meetings(a, b, c, d, cuts);
  }
  std::vector<std::pair<double, double>> pieces;
  if (cuts.size() == 2 && uncutBad) {
    if (*uncutBad) pieces.emplace_back(0.0, 1.0);
    return pieces;
  }
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (cuts[k + 1] - cuts[k] <= 0.0) continue;
    if (bad(geometry::locate(ring, a + (b - a) * (0.5 * (cuts[k] + cuts[k + 1])))))
      pieces.emplace_back(cuts[k], cuts[k + 1]);
  }
  return pieces;
}

// How far a piece of segment [a, b] gets from `ring`'s boundary, and where: sampled, for
// the overhang's size (whether it is an error), not for whether there is one.
std::pair<double, double> deepest(Vec2 a, Vec2 b, std::pair<double, double> piece,
                                  const geometry::Ring& ring) {
  std::pair<double, double> best{0.0, piece.first};  // depth, parameter
  constexpr int kSamples = 16;
  for (int k = 0; k <= kSamples; ++k) {
    const double u = piece.first + (piece.second - piece.first) * k / kSamples;
    const double depth = geometry::distanceToBoundary(ring, a + (b - a) * u);
    if (depth > best.first) best = {depth, u};
  }
  return best;
}

// Every shape the object takes, about its reference point: its own, or for a deforming one
// the convex hull of all its keyframes (which holds each interpolated shape).
geometry::Ring envelope(const MovingObject& o) {
  if (!o.deformation) return o.shape;
  std::vector<Vec2> points(o.shape.begin(), o.shape.end());
  for (const auto& frame : o.deformation->keyframes)
    points.insert(points.end(), frame.shape.begin(), frame.shape.end());
  return geometry::convexHull(std::move(points));
}

// The path's segments in travel order (a two-point path goes there and back: one segment),
// with the time the reference point starts each; a one-point path is one segment of length 0.
struct Leg {
  Vec2 from, to;
  double start = 0.0;  // s into the first lap
};
std::vector<Leg> legs(const MovingObject& o) {
  const auto& p = o.path;
  if (p.size() == 1) return {{p[0], p[0], 0.0}};
  std::vector<Leg> out;
  double time = 0.0;
  const std::size_t count = p.size() == 2 ? 1 : p.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % p.size()];
    out.push_back({a, b, time});
    time += geometry::distance(a, b) / o.velocity;
  }
  return out;
}

std::string at(const Leg& leg, double u, double velocity) {
  const Vec2 p = leg.from + (leg.to - leg.from) * u;
  return fmt::format("at t = {:.6g} s (reference point at ({:.6g} {:.6g}))",
                     leg.start + u * geometry::distance(leg.from, leg.to) / velocity, p.x, p.y);
}

// The deepest the object gets outside the boundary over its motion (0: never), and a
// sentence saying when and where.
struct Overhang {
  double depth = 0.0;  // m
  std::string where;
  void take(double d, std::string text) {
    if (d > depth) depth = d, where = std::move(text);
  }
};

// Only what lies near a leg can meet the object on it: the boundary's edges and vertices in
// the box the object sweeps (its shape's box at both ends), found once per leg, so that a
// large room costs a pass per leg, not one per vertex of the object.
Overhang translationOverhang(const geometry::Ring& shape, bool shapeStartsInside,
                             const std::vector<Leg>& path, const geometry::Ring& boundary,
                             double velocity) {
  const auto outside = [](Containment c) { return c == Containment::Outside; };
  const auto inside = [](Containment c) { return c == Containment::Inside; };
  // Whether each vertex of the object is known not to be outside where the leg starts: at
  // t = 0 the loader has placed the object's own shape inside; a hull is located.
  std::vector<char> startsInside(shape.size(), 1);
  for (std::size_t v = 0; v < shape.size() && !shapeStartsInside; ++v)
    startsInside[v] = !outside(geometry::locate(boundary, path.front().from + shape[v]));
  std::vector<std::size_t> shapeEdges(shape.size());
  for (std::size_t i = 0; i < shape.size(); ++i)
    shapeEdges[i] = i;
  const geometry::Box own = geometry::boundingBox(shape);
  Overhang out;
  std::vector<std::size_t> near;
  for (const Leg& leg : path) {
    const Vec2 move = leg.to - leg.from;
    const Vec2 lo{own.min.x + std::min(leg.from.x, leg.to.x),
                  own.min.y + std::min(leg.from.y, leg.to.y)};
    const Vec2 hi{own.max.x + std::max(leg.from.x, leg.to.x),
                  own.max.y + std::max(leg.from.y, leg.to.y)};
    const auto inBox = [&](Vec2 p) {
      return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
    };
    near.clear();
    for (std::size_t i = 0; i < boundary.size(); ++i) {
      const Vec2 c = boundary[i], d = boundary[(i + 1) % boundary.size()];
      if (std::max(c.x, d.x) >= lo.x && std::min(c.x, d.x) <= hi.x && std::max(c.y, d.y) >= lo.y &&
          std::min(c.y, d.y) <= hi.y)
        near.push_back(i);
    }
    for (std::size_t v = 0; v < shape.size(); ++v) {
      const Vec2 a = leg.from + shape[v], b = a + move;
      const auto pieces = badPieces(a, b, boundary, near, !startsInside[v], outside);
      for (const auto& piece : pieces) {
        const auto [depth, u] = deepest(a, b, piece, boundary);
        out.take(std::max(depth, 1e-12),
                 fmt::format("{} its vertex {} lies {:.3g} m outside the boundary",
                             at(leg, u, velocity), v, depth));
      }
      if (!pieces.empty()) startsInside[v] = !outside(geometry::locate(boundary, b));
    }
    for (std::size_t w = 0; w < boundary.size(); ++w) {
      if (!inBox(boundary[w])) continue;  // never within the object's reach on this leg
      const Vec2 a = boundary[w] - leg.from, b = a - move;  // in the object's frame
      for (const auto& piece : badPieces(a, b, shape, shapeEdges, std::nullopt, inside)) {
        const auto [depth, u] = deepest(a, b, piece, shape);
        out.take(std::max(depth, 1e-12),
                 fmt::format("{} the boundary's vertex {} ({:.6g} {:.6g}) lies {:.3g} m inside it",
                             at(leg, u, velocity), w, boundary[w].x, boundary[w].y, depth));
      }
    }
  }
  return out;
}

double radiusOf(const geometry::Ring& shape) {
  double radius = 0.0;
  for (const Vec2 v : shape)
    radius = std::max(radius, geometry::norm(v));
  return radius;
}

Overhang turningOverhang(const geometry::Ring& shape, const std::vector<Leg>& path,
                         const geometry::Ring& boundary, double velocity) {
  const double radius = radiusOf(shape);
  constexpr double kTolerance = 1e-9;  // m: touching the boundary is allowed
  Overhang out;
  for (const Leg& leg : path) {
    for (std::size_t i = 0; i < boundary.size(); ++i) {
      const Vec2 c = boundary[i], d = boundary[(i + 1) % boundary.size()];
      if (geometry::distanceBetweenSegments(leg.from, leg.to, c, d) >= radius - kTolerance)
        continue;
      // Where along the leg it comes nearest the edge: on a fine grid, for the message.
      double best = 0.0, nearest = std::numeric_limits<double>::infinity();
      for (int k = 0; k <= 64; ++k) {
        const double u = k / 64.0;
        const double gap = geometry::distanceToSegment(leg.from + (leg.to - leg.from) * u, c, d);
        if (gap < nearest) nearest = gap, best = u;
      }
      out.take(radius - nearest,
               fmt::format("{} it turns within {:.3g} m of the boundary's edge {} though it "
                           "reaches {:.3g} m from its reference point",
                           at(leg, best, velocity), nearest, i, radius));
    }
  }
  return out;
}

// Where the reference point is at time t (the path's motion: docs/scene-format.md, "Paths").
Vec2 positionAt(const std::vector<Leg>& path, double t, double velocity) {
  const Leg& last = path.back();
  const double lap = path.size() == 1 && last.from.x == last.to.x && last.from.y == last.to.y
                         ? 0.0
                         : last.start + geometry::distance(last.from, last.to) / velocity;
  if (lap <= 0.0) return path.front().from;
  // A two-point path goes there and back: its one leg, then the same leg reversed.
  const bool shuttle = path.size() == 1;
  const double period = shuttle ? 2.0 * lap : lap;
  double s = std::fmod(t, period);
  if (shuttle && s > lap) s = period - s;
  for (const Leg& leg : path) {
    const double duration = geometry::distance(leg.from, leg.to) / velocity;
    if (s <= leg.start + duration)
      return leg.from + (leg.to - leg.from) * ((s - leg.start) / std::max(duration, 1e-300));
  }
  return last.to;
}

// For a deforming object judged by the hull of its keyframes: the first sampled instant at
// which a vertex of its real shape lies outside the boundary, over two of its longest cycles,
// as "at t = … s …", or "" when none does (the hull was too cautious).
std::string sampledExit(const MovingObject& o, const std::vector<Leg>& path,
                        const geometry::Ring& boundary) {
  const Leg& last = path.back();
  const double lap = last.start + geometry::distance(last.from, last.to) / o.velocity;
  const double horizon = 2.0 * std::max({o.deformation->period, 2.0 * lap, 1e-9});
  // 4,000 instants, fewer for a large shape in a large room: each locates every vertex, and
  // the whole search stays within about 1e8 edge tests.
  const double work = static_cast<double>(o.shape.size()) * static_cast<double>(boundary.size());
  const int kSamples = static_cast<int>(std::clamp(1e8 / std::max(work, 1.0), 64.0, 4000.0));
  geometry::Ring shape;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = horizon * k / kSamples;
    localShapeAt(o, t, shape);
    geometry::transformRing(shape, o.angularVelocity * t, positionAt(path, t, o.velocity));
    for (std::size_t v = 0; v < shape.size(); ++v) {
      if (geometry::locate(boundary, shape[v]) == Containment::Outside) {
        return fmt::format(
            "at t = {:.6g} s its vertex {} ({:.6g} {:.6g}) lies {:.3g} m outside "
            "the boundary",
            t, v, shape[v].x, shape[v].y, geometry::distanceToBoundary(boundary, shape[v]));
      }
    }
  }
  return {};
}

}  // namespace

MotionCheck checkMotion(const Scene& scene) {
  MotionCheck check;
  for (const auto& [kind, objects] :
       {std::pair{"targets", &scene.targets}, std::pair{"obstacles", &scene.obstacles}}) {
    for (std::size_t i = 0; i < objects->size(); ++i) {
      const MovingObject& o = (*objects)[i];
      if (o.track || o.isStatic()) continue;  // tracks: their samples; still: at t = 0
      const geometry::Ring shape = envelope(o);
      const std::vector<Leg> path = legs(o);
      const Overhang overhang =
          o.angularVelocity != 0.0
              ? turningOverhang(shape, path, scene.boundary, o.velocity)
              : translationOverhang(shape, !o.deformation, path, scene.boundary, o.velocity);
      if (overhang.depth <= 0.0) continue;
      std::string problem = overhang.where;
      double allowed = kAllowedOverhang * radiusOf(o.shape);
      if (o.deformation) {
        // The hull is cautious: name a real instant, or warn that it may leave.
        problem = sampledExit(o, path, scene.boundary);
        if (problem.empty()) {
          problem = overhang.where +
                    " (judged by the hull of all its keyframes; no sampled "
                    "instant of its real shape is outside)";
          allowed = std::numeric_limits<double>::infinity();
        }
      }
      (overhang.depth <= allowed ? check.warnings : check.errors)
          .push_back({fmt::format("{}[{}]", kind, i),
                      fmt::format("leaves the boundary: {}{}", problem,
                                  overhang.depth <= allowed ? "; the part outside can never be seen"
                                                            : "")});
    }
  }
  return check;
}

}  // namespace camcov::scene
