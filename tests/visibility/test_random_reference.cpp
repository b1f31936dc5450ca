// The sweep against the independent O(n²) reference on seeded random configurations
// (random_scenes.h): coverage-relevant quantities must agree to 1e-6 relative.
//
// CAMCOV_VISIBILITY_CASES overrides the number of configurations (default 10000);
// CAMCOV_VISIBILITY_CASE=<index> runs only that one, to debug a failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "random_scenes.h"
#include "reference_visibility.h"
#include "visibility/sweep.h"

namespace camcov::visibility {
namespace {

using geometry::Vec2;

constexpr std::uint64_t kSeed = 20240611;
constexpr double kRelative = 1e-6;

std::uint64_t envNumber(const char* name, std::uint64_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr ? std::stoull(value) : fallback;
}

// The angle ∠ a p b in [0, π].
double angleAt(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 u = a - p, v = b - p;
  return std::abs(std::atan2(cross(u, v), dot(u, v)));
}

struct Quantities {
  double unionLength = 0.0;
  std::vector<double> length, utilization;  // per camera
};

Quantities fromSweep(const testing::Case& c, const std::vector<Segment>& segments) {
  Quantities q;
  q.length.assign(c.cameras.size(), 0.0);
  q.utilization.assign(c.cameras.size(), 0.0);
  for (const Segment& s : segments) {
    if (s.visibleBy != 0) q.unionLength += length(s);
    for (std::size_t j = 0; j < c.cameras.size(); ++j) {
      if ((s.visibleBy >> j & 1) == 0) continue;
      q.length[j] += length(s);
      q.utilization[j] += angleAt(c.cameras[j].position(), s.a, s.b) / (2.0 * c.halfFov);
    }
  }
  return q;
}

Quantities fromReference(const testing::Case& c) {
  Quantities q;
  const auto& targets = c.world.targets;
  // Per target edge, the union over cameras.
  std::vector<std::vector<reference::IntervalSet>> all(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i)
    all[i].resize(targets[i].size());
  for (const geometry::Pose& pose : c.cameras) {
    const auto seen = reference::visibleIntervals(c.world, pose.position(), pose.yaw, c.halfFov);
    double len = 0.0, util = 0.0;
    for (std::size_t i = 0; i < targets.size(); ++i) {
      for (std::size_t k = 0; k < targets[i].size(); ++k) {
        const Vec2 a = targets[i][k], b = targets[i][(k + 1) % targets[i].size()];
        for (const reference::Interval& t : seen[i][k]) {
          len += (t.hi - t.lo) * geometry::distance(a, b);
          util += angleAt(pose.position(), lerp(a, b, t.lo), lerp(a, b, t.hi)) / (2.0 * c.halfFov);
          all[i][k].push_back(t);
        }
      }
    }
    q.length.push_back(len);
    q.utilization.push_back(util);
  }
  for (std::size_t i = 0; i < targets.size(); ++i) {
    for (std::size_t k = 0; k < targets[i].size(); ++k) {
      auto& set = all[i][k];
      std::sort(set.begin(), set.end(), [](auto x, auto y) { return x.lo < y.lo; });
      double reach = 0.0, covered = 0.0;
      for (const reference::Interval& t : set) {
        if (t.hi > reach) covered += t.hi - std::max(t.lo, reach);
        reach = std::max(reach, t.hi);
      }
      q.unionLength +=
          covered * geometry::distance(targets[i][k], targets[i][(k + 1) % targets[i].size()]);
    }
  }
  return q;
}

// Both implementations round points to about u · extent. Seen from a camera at distance h
// from the nearest edge it does not stand on, that turns angles by u · extent / h; along a
// target edge whose supporting line passes at distance g from the camera, it moves visible
// endpoints by u · extent² / g (a grazing view). The comparison allows 8 times these, on top of
// the 1e-6 relative agreement. For cameras in general position both are far below 1e-9.
struct Conditioning {
  double edgeDistance = INFINITY;  // h
  double lineDistance = INFINITY;  // g
};

Conditioning conditioning(const kinematics::World& world, Vec2 p, double eps) {
  Conditioning c;
  auto scan = [&](const geometry::Ring& ring, bool target) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const double d = geometry::distanceToSegment(p, a, b);
      if (d > eps) c.edgeDistance = std::min(c.edgeDistance, d);
      const double g =
          a == b ? INFINITY : std::abs(geometry::orient(a, b, p)) / geometry::distance(a, b);
      if (target && g > eps) c.lineDistance = std::min(c.lineDistance, g);
    }
  };
  scan(world.boundary, false);
  for (const auto& r : world.obstacles)
    scan(r, false);
  for (const auto& r : world.targets)
    scan(r, true);
  return c;
}

bool close(double a, double b, double floor) {
  return std::abs(a - b) <= kRelative * std::max(std::abs(a), std::abs(b)) + floor;
}

TEST(RandomConfigurations, SweepAgreesWithReferenceOnLengthsAndUtilization) {
  const std::uint64_t count = envNumber("CAMCOV_VISIBILITY_CASES", 10000);
  const std::uint64_t only = envNumber("CAMCOV_VISIBILITY_CASE", ~std::uint64_t{0});
  Sweep sweep;
  Occluders occluders;
  std::vector<Segment> segments;
  int failures = 0;
  for (std::uint64_t index = 0; index < count && failures < 10; ++index) {
    if (only != ~std::uint64_t{0} && index != only) continue;
    const testing::Case c = testing::randomCase(kSeed, index);
    occluders.build(c.world);
    sweep.segments(occluders, c.cameras, c.halfFov, segments);
    const Quantities got = fromSweep(c, segments), want = fromReference(c);
    constexpr double u = 0x1p-53;
    const double extent = occluders.extent();
    double unionFloor = 1e-9 * extent;
    bool ok = true;
    for (std::size_t j = 0; j < c.cameras.size(); ++j) {
      const Conditioning k = conditioning(c.world, c.cameras[j].position(), occluders.tolerance());
      const double lengthFloor = 1e-9 * extent + 8.0 * u * extent * extent / k.lineDistance;
      const double angleFloor = 1e-9 + 8.0 * u * extent / (k.edgeDistance * 2.0 * c.halfFov);
      unionFloor += lengthFloor;
      ok = ok && close(got.length[j], want.length[j], lengthFloor) &&
           close(got.utilization[j], want.utilization[j], angleFloor);
    }
    ok = ok && close(got.unionLength, want.unionLength, unionFloor);
    if (!ok) {
      ++failures;
      std::ostringstream detail;
      detail.precision(12);
      detail << "case " << index << ": union " << got.unionLength << " vs " << want.unionLength;
      for (std::size_t j = 0; j < c.cameras.size(); ++j) {
        detail << "\n camera " << j << ": length " << got.length[j] << " vs " << want.length[j]
               << ", utilization " << got.utilization[j] << " vs " << want.utilization[j];
      }
      ADD_FAILURE() << detail.str() << '\n' << testing::describe(c);
    }
  }
}

}  // namespace
}  // namespace camcov::visibility
