#include "kinematics/object_overlaps.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "geometry/ring.h"
#include "kinematics/boost_rings.h"
#include "kinematics/kinematics.h"

namespace camcov::kinematics {
namespace {

using geometry::Vec2;

// A point of the region where the interiors of `a` and `b` meet (the centroid of the largest
// piece), if they meet in more than a sliver: touching, or a crossing thinner than rounding,
// is not overlapping.
std::optional<Vec2> interiorsMeet(const geometry::Ring& a, const geometry::Ring& b) {
  const std::vector<BgPolygon> pieces = intersectionPieces(a, b);
  const double scale =
      std::max(std::abs(geometry::signedArea(a)), std::abs(geometry::signedArea(b)));
  const BgPolygon* largest = nullptr;
  double largestArea = 1e-9 * scale;
  for (const BgPolygon& piece : pieces) {
    const double area = std::abs(bg::area(piece));
    if (area > largestArea) {
      largestArea = area;
      largest = &piece;
    }
  }
  if (largest == nullptr) return std::nullopt;
  BgPoint c(0.0, 0.0);
  bg::centroid(*largest, c);
  return Vec2{c.x(), c.y()};
}

}  // namespace

std::vector<ObjectOverlap> findObjectOverlaps(const scene::Scene& scene, double duration,
                                              double step) {
  const Kinematics kinematics(scene);
  // Capped in floating point first: a long run at a fine step would overflow an int.
  const double wanted = 1.0 + std::floor(std::max(0.0, duration) / step);
  const int instants = wanted < kMaxInstants ? static_cast<int>(wanted) : kMaxInstants;
  std::vector<ObjectOverlap> found;
  std::set<std::pair<std::string, std::string>> seen;
  World world;
  for (int k = 0; k < instants; ++k) {
    const double t = k * step;
    kinematics.worldAt(t, world);
    struct Placed {
      const geometry::Ring* ring;
      geometry::Box box;
      std::string path;
    };
    std::vector<Placed> placed;
    for (std::size_t i = 0; i < world.targets.size(); ++i) {
      placed.push_back({&world.targets[i], geometry::boundingBox(world.targets[i]),
                        fmt::format("targets[{}]", targetId(world, i))});
    }
    for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
      placed.push_back({&world.obstacles[i], geometry::boundingBox(world.obstacles[i]),
                        fmt::format("obstacles[{}]", obstacleId(world, i))});
    }
    // Sweep and prune along x: only pairs whose boxes overlap are tested.
    std::vector<std::size_t> order(placed.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return placed[a].box.min.x < placed[b].box.min.x;
    });
    for (std::size_t i = 0; i < order.size(); ++i) {
      const Placed& a = placed[order[i]];
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        const Placed& b = placed[order[j]];
        if (b.box.min.x > a.box.max.x) break;
        if (!geometry::overlaps(a.box, b.box)) continue;
        auto key = order[i] < order[j] ? std::pair(a.path, b.path) : std::pair(b.path, a.path);
        if (seen.count(key) > 0) continue;
        if (const auto where = interiorsMeet(*a.ring, *b.ring)) {
          seen.insert(key);
          found.push_back({key.first, key.second, t, *where});
        }
      }
    }
  }
  return found;
}

std::string describeOverlap(const ObjectOverlap& o) {
  return fmt::format("{} and {} pass through each other at t = {:g} s near ({:.2f}, {:.2f})",
                     o.first, o.second, o.time, o.near.x, o.near.y);
}

}  // namespace camcov::kinematics
