#include "kinematics/world_region.h"

#include <algorithm>
#include <vector>

#include "kinematics/boost_rings.h"

namespace camcov::kinematics {
namespace {

// What an object kept is spared from the clipped room's walls: it must not touch them, and
// anything more would be arbitrary.
constexpr double kObjectSpare = 0.01;  // m

geometry::Box enclosing(const geometry::Box& a, const geometry::Box& b) {
  return {{std::min(a.min.x, b.min.x), std::min(a.min.y, b.min.y)},
          {std::max(a.max.x, b.max.x), std::max(a.max.y, b.max.y)}};
}

// Grows `region` until every object box it meets lies inside it with kObjectSpare around.
geometry::Box grownOverObjects(geometry::Box region, const std::vector<geometry::Box>& objects) {
  for (bool grew = true; grew;) {
    grew = false;
    for (const geometry::Box& object : objects) {
      const geometry::Box spared = geometry::grown(object, kObjectSpare);
      if (geometry::overlaps(region, spared) && !geometry::contains(region, spared)) {
        region = enclosing(region, spared);
        grew = true;
      }
    }
  }
  return region;
}

}  // namespace

std::optional<World> worldInRegion(const World& world, geometry::Box region,
                                   geometry::Vec2 anchor) {
  std::vector<geometry::Box> boxes;
  boxes.reserve(world.targets.size() + world.obstacles.size());
  for (const geometry::Ring& t : world.targets)
    boxes.push_back(geometry::boundingBox(t));
  for (const geometry::Ring& o : world.obstacles)
    boxes.push_back(geometry::boundingBox(o));
  region = grownOverObjects(region, boxes);
  if (geometry::contains(region, geometry::boundingBox(world.boundary))) return std::nullopt;

  // A room that is not convex may fall into several pieces in the box: the anchor's is the
  // part it can reach without leaving the box.
  std::vector<BgPolygon> pieces;
  try {
    pieces = intersectionPieces(world.boundary, geometry::ringOf(region));
  } catch (const bg::exception&) {
    return std::nullopt;  // a room Boost cannot cut (it is stricter than our loader): all of it
  }
  std::optional<geometry::Ring> piece;
  for (const BgPolygon& p : pieces) {
    if (!bg::covered_by(BgPoint(anchor.x, anchor.y), p)) continue;
    geometry::Ring ring;
    for (const BgPoint& v : p.outer())
      ring.push_back({v.x(), v.y()});
    geometry::normalizeRing(ring);
    if (ring.size() >= 3) piece = std::move(ring);
    break;
  }
  if (!piece) return std::nullopt;

  World part;
  part.time = world.time;
  part.boundary = std::move(*piece);
  part.resolution = world.resolution;
  // An object inside the box lies in one piece of the room: the anchor's if its first vertex is.
  const auto inPart = [&](const geometry::Box& box, const geometry::Ring& ring) {
    return geometry::contains(region, box) &&
           geometry::locate(part.boundary, ring.front()) != geometry::Containment::Outside;
  };
  for (std::size_t i = 0; i < world.targets.size(); ++i) {
    if (!inPart(boxes[i], world.targets[i])) continue;
    part.targets.push_back(world.targets[i]);
    part.targetIds.push_back(targetId(world, i));
    if (!world.targetEdgeWeights.empty())
      part.targetEdgeWeights.push_back(world.targetEdgeWeights[i]);
  }
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    if (!inPart(boxes[world.targets.size() + i], world.obstacles[i])) continue;
    part.obstacles.push_back(world.obstacles[i]);
    part.obstacleIds.push_back(obstacleId(world, i));
  }
  return part;
}

}  // namespace camcov::kinematics
