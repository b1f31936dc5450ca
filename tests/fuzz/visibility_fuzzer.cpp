// libFuzzer target: a World and camera poses decoded from the bytes -> the polar sweep
// (Sweep::segments), checked against the slow reference of tests/visibility:
//  - no exception, every segment endpoint finite, masks only name cameras that exist;
//  - the segments tile every target's boundary: contiguous along each edge, from its first
//    vertex to its last, lengths adding up to the perimeter;
//  - per camera, the visible length, and the length seen by anyone (coverage), agree with
//    reference::visibleIntervals within the conditioning bound of docs/visibility.md;
//  - the omnidirectional visibility polygon (Algorithm 2's sampler) of one more decoded
//    point is finite and has the reference's area (the tolerance of test_visibility_polygon).
// Four inputs in five sweep culled first (OcclusionCulling) however small the scene, on grids
// of 0.25 to 16 cells per chain (chosen by the input's length, so decoding is unchanged); the
// fifth sweeps whole.
// Coordinates are mostly small integers times a power of two, so that collinear vertices,
// shared edges, cameras on supporting lines and vertices on field-of-view rays come up all
// the time and stay exact at every scale (2^-20 ≈ 1e-6 to 2^20 ≈ 1e6).
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "random_scenes.h"
#include "reference_visibility.h"
#include "scene/scene_validation.h"
#include "visibility/sweep.h"

namespace {

using namespace camcov;
using geometry::Ring;
using geometry::Vec2;

constexpr double kPi = std::numbers::pi;
constexpr int kGrid = 16;  // grid coordinates in [0, kGrid]

class Decoder {
 public:
  Decoder(const std::uint8_t* data, std::size_t size) : in_(data, size) {}

  visibility::testing::Case decode() {
    visibility::testing::Case c;
    unit_ = std::ldexp(1.0, in_.PickValueInArray({0, 0, 0, -2, -20, 20}));
    c.world.boundary = boundary();
    const int objects = in_.ConsumeIntegralInRange(1, 5);
    for (int i = 0; i < objects; ++i) {
      Ring ring = polygon(-2, kGrid + 2);
      if (!scene::describeRingDefect(ring).empty()) continue;  // the loader's rule: simple only
      geometry::normalizeRing(ring);
      (c.world.targets.empty() || in_.ConsumeBool() ? c.world.targets : c.world.obstacles)
          .push_back(std::move(ring));
    }
    if (c.world.targets.empty()) c.world.targets.push_back(rectangle(6, 6, 9, 8));
    c.halfFov = in_.ConsumeBool()
                    ? in_.PickValueInArray({kPi / 4, kPi / 2, 3 * kPi / 4, kPi - 1e-3, 0.3})
                    : 0.01 + (kPi - 0.02) * in_.ConsumeProbability<double>();
    // Up to 64 cameras (every bit of the mask) now and then: the reference is O(n²) each.
    const int cameras = in_.ConsumeIntegralInRange(0, 7) == 0 ? in_.ConsumeIntegralInRange(1, 64)
                                                              : in_.ConsumeIntegralInRange(1, 4);
    for (int j = 0; j < cameras; ++j) {
      const Vec2 p = cameraPosition(c.world);
      c.cameras.push_back({p.x, p.y, cameraYaw(c.world, p, c.halfFov)});
    }
    return c;
  }

  Vec2 viewpoint(const kinematics::World& world) { return cameraPosition(world); }

 private:
  Vec2 gridPoint(int lo, int hi) {
    const double x = in_.ConsumeIntegralInRange(lo, hi), y = in_.ConsumeIntegralInRange(lo, hi);
    return Vec2{x, y} * unit_;
  }

  Ring rectangle(double x0, double y0, double x1, double y1) const {
    return {Vec2{x0, y0} * unit_, Vec2{x1, y0} * unit_, Vec2{x1, y1} * unit_, Vec2{x0, y1} * unit_};
  }

  Ring polygon(int lo, int hi) {
    Ring ring;
    const int n = in_.ConsumeIntegralInRange(3, 9);
    for (int i = 0; i < n; ++i) {
      ring.push_back(gridPoint(lo, hi));
      // Exact midpoints: collinear consecutive vertices.
      if (i > 0 && in_.ConsumeIntegralInRange(0, 7) == 0)
        ring.insert(ring.end() - 1, (ring[ring.size() - 2] + ring.back()) * 0.5);
    }
    return ring;
  }

  Ring boundary() {
    if (in_.ConsumeBool()) return rectangle(0, 0, kGrid, kGrid);
    Ring ring = polygon(0, kGrid);
    if (!scene::describeRingDefect(ring).empty()) return rectangle(0, 0, kGrid, kGrid);
    geometry::normalizeRing(ring);
    return ring;
  }

  const Ring& anyRing(const kinematics::World& world) {
    const std::size_t rings = 1 + world.targets.size() + world.obstacles.size();
    const std::size_t k = in_.ConsumeIntegralInRange<std::size_t>(0, rings - 1);
    if (k == 0) return world.boundary;
    if (k <= world.targets.size()) return world.targets[k - 1];
    return world.obstacles[k - 1 - world.targets.size()];
  }

  Vec2 anyVertex(const kinematics::World& world) {
    const Ring& ring = anyRing(world);
    return ring[in_.ConsumeIntegralInRange<std::size_t>(0, ring.size() - 1)];
  }

  // Anywhere, but mostly on a vertex, an edge, a supporting line or 1e-9 beside an edge.
  Vec2 cameraPosition(const kinematics::World& world) {
    const Ring& ring = anyRing(world);
    const std::size_t i = in_.ConsumeIntegralInRange<std::size_t>(0, ring.size() - 1);
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    switch (in_.ConsumeIntegralInRange(0, 5)) {
      case 0:
        return a;
      case 1:  // on the edge at k/8: exact for grid coordinates
        return lerp(a, b, in_.ConsumeIntegralInRange(1, 7) / 8.0);
      case 2:  // on its supporting line, outside the edge
        return lerp(a, b, in_.PickValueInArray({-1.0, -0.5, 1.5, 2.0}));
      case 3: {  // beside the edge by about 1e-9 of the scene, on either side
        const Vec2 d = b - a, n = Vec2{-d.y, d.x} / geometry::norm(d);
        const double offset = 1e-9 * kGrid * unit_ * (in_.ConsumeBool() ? 1.0 : -1.0);
        return lerp(a, b, in_.ConsumeIntegralInRange(1, 7) / 8.0) + n * offset;
      }
      case 4:
        return gridPoint(-1, kGrid + 1);
      default:
        return Vec2{in_.ConsumeFloatingPointInRange(-1.0, kGrid + 1.0),
                    in_.ConsumeFloatingPointInRange(-1.0, kGrid + 1.0)} *
               unit_;
    }
  }

  double cameraYaw(const kinematics::World& world, Vec2 p, double halfFov) {
    switch (in_.ConsumeIntegralInRange(0, 2)) {
      case 0: {  // a vertex on a field-of-view ray (up to the rounding of atan2)
        const Vec2 v = anyVertex(world);
        if (v == p) return 0.0;
        return std::atan2(v.y - p.y, v.x - p.x) + (in_.ConsumeBool() ? halfFov : -halfFov);
      }
      case 1:
        return in_.ConsumeIntegralInRange(-4, 4) * kPi / 4;
      default:
        return in_.ConsumeFloatingPointInRange(-kPi, kPi);
    }
  }

  FuzzedDataProvider in_;
  double unit_ = 1.0;
};

[[noreturn]] void fail(const visibility::testing::Case& c, const char* what, double got = 0.0,
                       double want = 0.0) {
  std::fprintf(stderr, "visibility fuzzer: %s (sweep %.17g, reference %.17g)\n%s", what, got, want,
               visibility::testing::describe(c).c_str());
  std::abort();
}

bool finite(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}

// Contiguous along each edge from its first vertex to the next; lengths add up to the
// perimeter. Endpoints are interpolated on the edge, so they may differ from the vertices by
// rounding.
void checkTiling(const visibility::testing::Case& c, const std::vector<visibility::Segment>& s,
                 double eps) {
  std::size_t k = 0;
  for (std::uint32_t t = 0; t < c.world.targets.size(); ++t) {
    const Ring& ring = c.world.targets[t];
    double total = 0.0;
    for (std::uint32_t e = 0; e < ring.size(); ++e) {
      Vec2 at = ring[e];
      for (; k < s.size() && s[k].target == t && s[k].edge == e; ++k) {
        if (geometry::distance(s[k].a, at) > eps) fail(c, "gap between segments");
        at = s[k].b;
        total += length(s[k]);
      }
      if (geometry::distance(at, ring[(e + 1) % ring.size()]) > eps)
        fail(c, "segments stop short of the edge's end");
    }
    const double perimeter = geometry::perimeter(ring);
    if (std::abs(total - perimeter) > 1e-12 * perimeter + ring.size() * eps)
      fail(c, "segment lengths do not add up to the perimeter", total, perimeter);
  }
  if (k != s.size()) fail(c, "segments out of order or naming a missing target or edge");
}

double edgeLength(const Ring& ring, std::size_t k) {
  return geometry::distance(ring[k], ring[(k + 1) % ring.size()]);
}

// Length of a set of parameter intervals on an edge of length `edge`, after merging overlaps.
double unionLength(std::vector<visibility::reference::Interval> set, double edge) {
  std::sort(set.begin(), set.end(), [](auto x, auto y) { return x.lo < y.lo; });
  double reach = 0.0, covered = 0.0;
  for (const auto& t : set) {
    if (t.hi > reach) covered += t.hi - std::max(t.lo, reach);
    reach = std::max(reach, t.hi);
  }
  return covered * edge;
}

// docs/visibility.md, "Conditioning": a grazing view of a target edge whose supporting line
// passes at distance g from the camera moves visible endpoints by about u·extent²/g. Lines
// within ε are seen edge-on by both implementations and do not count.
double lengthTolerance(const kinematics::World& world, Vec2 p, double extent, double eps) {
  double g = INFINITY;
  for (const Ring& ring : world.targets) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const double d =
          std::abs(geometry::orient(ring[i], ring[(i + 1) % ring.size()], p)) / edgeLength(ring, i);
      if (d > eps) g = std::min(g, d);
    }
  }
  return 1e-9 * extent + 8.0 * 0x1p-53 * extent * extent / g;
}

void compareWithReference(const visibility::testing::Case& c,
                          const std::vector<visibility::Segment>& s,
                          const visibility::Occluders& occluders) {
  const auto& targets = c.world.targets;
  std::vector<double> sweepLength(c.cameras.size(), 0.0);
  double sweepUnion = 0.0;
  for (const visibility::Segment& segment : s) {
    if (!segment.visibleBy.empty()) sweepUnion += length(segment);
    for (std::size_t j = 0; j < c.cameras.size(); ++j) {
      if (segment.visibleBy.contains(j)) sweepLength[j] += length(segment);
    }
  }
  std::vector<std::vector<std::vector<visibility::reference::Interval>>> seenByAnyone(
      targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i)
    seenByAnyone[i].resize(targets[i].size());
  double unionTolerance = 1e-9 * occluders.extent();
  for (std::size_t j = 0; j < c.cameras.size(); ++j) {
    const geometry::Pose& pose = c.cameras[j];
    const auto seen =
        visibility::reference::visibleIntervals(c.world, pose.position(), pose.yaw, c.halfFov);
    double want = 0.0;
    for (std::size_t i = 0; i < targets.size(); ++i) {
      for (std::size_t k = 0; k < targets[i].size(); ++k) {
        want += unionLength(seen[i][k], edgeLength(targets[i], k));
        seenByAnyone[i][k].insert(seenByAnyone[i][k].end(), seen[i][k].begin(), seen[i][k].end());
      }
    }
    const double tolerance =
        lengthTolerance(c.world, pose.position(), occluders.extent(), occluders.tolerance());
    unionTolerance += tolerance;
    if (std::abs(sweepLength[j] - want) > 1e-6 * std::max(sweepLength[j], want) + tolerance)
      fail(c, "a camera's visible length differs from the reference", sweepLength[j], want);
  }
  double want = 0.0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    for (std::size_t k = 0; k < targets[i].size(); ++k) {
      want += unionLength(seenByAnyone[i][k], edgeLength(targets[i], k));
    }
  }
  if (std::abs(sweepUnion - want) > 1e-6 * std::max(sweepUnion, want) + unionTolerance)
    fail(c, "the length seen by anyone differs from the reference", sweepUnion, want);
}

void checkVisibilityPolygon(const visibility::testing::Case& c,
                            const visibility::Occluders& occluders, visibility::Sweep& sweep,
                            Vec2 point) {
  Ring polygon;
  sweep.visibilityPolygon(occluders, point, polygon);
  if (!std::all_of(polygon.begin(), polygon.end(), finite))
    fail(c, "non-finite visibility polygon vertex");
  const double got = polygon.size() < 3 ? 0.0 : geometry::signedArea(polygon);
  const double want = visibility::reference::visibleArea(c.world, point);
  if (std::abs(got - want) > 1e-6 * want + 1e-9 * occluders.extent() * occluders.extent()) {
    std::fprintf(stderr, "viewpoint %.17g %.17g\n", point.x, point.y);
    fail(c, "the visibility polygon's area differs from the reference", got, want);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Decoder decoder(data, size);
  const visibility::testing::Case c = decoder.decode();
  const Vec2 viewpoint = decoder.viewpoint(c.world);
  const visibility::Occluders occluders(c.world);
  const double cellsPerChain[] = {0.25, 1.0, 4.0, 16.0};
  visibility::Sweep sweep(size % 5 == 0 ? visibility::Culling{UINT32_MAX}
                                        : visibility::Culling{0, cellsPerChain[size % 5 - 1]});
  std::vector<visibility::Segment> segments;
  sweep.segments(occluders, c.cameras, c.halfFov, segments);
  for (const visibility::Segment& segment : segments) {
    if (!finite(segment.a) || !finite(segment.b)) fail(c, "non-finite segment endpoint");
    segment.visibleBy.forEach([&](std::size_t j) {
      if (j >= c.cameras.size()) fail(c, "mask names a camera that does not exist");
    });
  }
  checkTiling(c, segments, 4.0 * occluders.tolerance());
  compareWithReference(c, segments, occluders);
  checkVisibilityPolygon(c, occluders, sweep, viewpoint);
  return 0;
}
