#include "random_scenes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "geometry/ring.h"

namespace camcov::visibility::testing {

using geometry::Pose;
using geometry::Ring;
using geometry::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;

Ring rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Star-shaped about `center`, so simple; `grid` rounds the vertices to integers.
Ring starPolygon(Random& random, Vec2 center, int vertices, double rMin, double rMax, bool grid) {
  std::vector<double> angles;
  for (int i = 0; i < vertices; ++i)
    angles.push_back(random.uniform(0.0, 2.0 * kPi));
  std::sort(angles.begin(), angles.end());
  Ring ring;
  for (const double a : angles) {
    Vec2 v = center + geometry::unitVector(a) * random.uniform(rMin, rMax);
    if (grid) v = {std::round(v.x), std::round(v.y)};
    ring.push_back(v);
  }
  geometry::normalizeRing(ring);
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  // Rounding may fold it over itself; a rectangle then stands in.
  if (ring.size() < 3 || geometry::findSelfIntersection(ring).found() ||
      geometry::signedArea(ring) <= 0.0) {
    const double r = grid ? std::max(1.0, std::round(rMin)) : rMin;
    const Vec2 c = grid ? Vec2{std::round(center.x), std::round(center.y)} : center;
    return rectangle(c.x - r, c.y - r, c.x + r, c.y + r);
  }
  return ring;
}

Ring convexPolygon(Random& random, Vec2 center, int vertices, double radius) {
  std::vector<double> angles;
  for (int i = 0; i < vertices; ++i)
    angles.push_back(random.uniform(0.0, 2.0 * kPi));
  std::sort(angles.begin(), angles.end());
  Ring ring;
  for (const double a : angles)
    ring.push_back(center + geometry::unitVector(a) * radius);
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  if (ring.size() < 3)
    return rectangle(center.x - radius, center.y - radius, center.x + radius, center.y + radius);
  return ring;
}

// Inserts exact midpoints into some edges: collinear consecutive vertices.
void addCollinearVertices(Random& random, Ring& ring) {
  Ring out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    out.push_back(ring[i]);
    if (random.chance(0.3)) out.push_back((ring[i] + ring[(i + 1) % ring.size()]) * 0.5);
  }
  ring = out;
}

Ring gridBoundary(Random& random, double w, double h) {
  const double x1 = random.integer(2, static_cast<int>(w) / 2),
               x2 = random.integer(static_cast<int>(w) / 2 + 1, static_cast<int>(w) - 2);
  const double y1 = random.integer(2, static_cast<int>(h) - 3);
  switch (random.integer(0, 2)) {
    case 0:
      return rectangle(0, 0, w, h);
    case 1:  // U: a pocket from the top
      return {{0, 0}, {w, 0}, {w, h}, {x2, h}, {x2, y1}, {x1, y1}, {x1, h}, {0, h}};
    default:  // L
      return {{0, 0}, {w, 0}, {w, y1}, {x1, y1}, {x1, h}, {0, h}};
  }
}

void gridObjects(Random& random, kinematics::World& world, double w, double h, int count) {
  std::vector<Ring> objects;
  for (int i = 0; i < count; ++i) {
    const double x = random.integer(0, static_cast<int>(w) - 2),
                 y = random.integer(0, static_cast<int>(h) - 2);
    const double rw = random.integer(1, 4), rh = random.integer(1, 4);
    switch (random.integer(0, 4)) {
      case 0:
        objects.push_back(rectangle(x, y, x + rw, y + rh));
        break;
      case 1: {  // a rectangle and a neighbour sharing part of its right side
        objects.push_back(rectangle(x, y, x + rw, y + rh));
        const double y2 = y + random.integer(-1, static_cast<int>(rh) - 1);
        objects.push_back(
            rectangle(x + rw, y2, x + rw + random.integer(1, 3), y2 + random.integer(1, 3)));
        break;
      }
      case 2: {  // two overlapping rectangles, one sharing part of the other's bottom side
        objects.push_back(rectangle(x, y, x + rw + 1, y + rh));
        objects.push_back(
            rectangle(x + 1, y, x + 1 + random.integer(1, 3), y + random.integer(1, 3)));
        break;
      }
      case 3:
        objects.push_back(
            starPolygon(random, {x + 1.0, y + 1.0}, random.integer(3, 7), 1.0, 3.0, true));
        break;
      default:  // a triangle touching a rectangle at a vertex
        objects.push_back(rectangle(x, y, x + rw, y + rh));
        objects.push_back({{x + rw, y + rh}, {x + rw + 2, y + rh}, {x + rw, y + rh + 2}});
        break;
    }
  }
  for (Ring& ring : objects) {
    if (random.chance(0.3)) addCollinearVertices(random, ring);
  }
  // At least one target.
  for (std::size_t i = 0; i < objects.size(); ++i) {
    (i == 0 || random.chance(0.6) ? world.targets : world.obstacles).push_back(objects[i]);
  }
}

// `count` objects of radius between `smallest` and `largest` times `size`.
void generalObjects(Random& random, kinematics::World& world, double size, int count,
                    double smallest, double largest) {
  for (int i = 0; i < count; ++i) {
    const Vec2 c{random.uniform(0.1 * size, 0.9 * size), random.uniform(0.1 * size, 0.9 * size)};
    const double r = random.uniform(smallest, largest) * size;
    Ring ring = random.chance(0.5) ? starPolygon(random, c, random.integer(3, 9), 0.4 * r, r, false)
                                   : convexPolygon(random, c, random.integer(3, 8), r);
    (i == 0 || random.chance(0.6) ? world.targets : world.obstacles).push_back(ring);
  }
}

const Ring& randomRing(Random& random, const kinematics::World& world) {
  const std::size_t rings = 1 + world.obstacles.size() + world.targets.size();
  const auto pick = static_cast<std::size_t>(random.integer(0, static_cast<int>(rings) - 1));
  if (pick == 0) return world.boundary;
  if (pick <= world.obstacles.size()) return world.obstacles[pick - 1];
  return world.targets[pick - 1 - world.obstacles.size()];
}

Vec2 cameraPosition(Random& random, const kinematics::World& world, bool grid) {
  const geometry::Box box = geometry::boundingBox(world.boundary);
  const Ring& ring = randomRing(random, world);
  const std::size_t i =
      static_cast<std::size_t>(random.integer(0, static_cast<int>(ring.size()) - 1));
  const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
  switch (random.integer(0, 6)) {
    case 0:  // a vertex
      return a;
    case 1:  // on an edge
      return grid ? (a + b) * 0.5 : lerp(a, b, random.uniform(0.0, 1.0));
    case 2: {  // on an edge's supporting line, outside the edge
      const double s[] = {-1.0, -0.5, 1.5, 2.0, 3.0};
      return a + (b - a) * s[random.integer(0, 4)];
    }
    case 3: {  // 1e-9 beside an edge, on either side
      const Vec2 d = b - a;
      const Vec2 n = Vec2{-d.y, d.x} / geometry::norm(d);
      return lerp(a, b, random.uniform(0.1, 0.9)) + n * (random.chance(0.5) ? 1e-9 : -1e-9);
    }
    case 4:
      if (grid)
        return {std::round(random.uniform(box.min.x, box.max.x)),
                std::round(random.uniform(box.min.y, box.max.y))};
      [[fallthrough]];
    default:
      return {random.uniform(box.min.x, box.max.x), random.uniform(box.min.y, box.max.y)};
  }
}

double cameraYaw(Random& random, const kinematics::World& world, Vec2 p, double halfFov) {
  switch (random.integer(0, 4)) {
    case 0: {  // a vertex exactly (up to rounding of the angle) on a field-of-view ray
      const Ring& ring = randomRing(random, world);
      const Vec2 v =
          ring[static_cast<std::size_t>(random.integer(0, static_cast<int>(ring.size()) - 1))];
      if (v == p) break;
      return std::atan2(v.y - p.y, v.x - p.x) + (random.chance(0.5) ? halfFov : -halfFov);
    }
    case 1:
      return random.integer(-4, 4) * 0.25 * kPi;
    case 2: {  // towards a target, so that most cameras see something
      const Ring& target = world.targets[static_cast<std::size_t>(
          random.integer(0, static_cast<int>(world.targets.size()) - 1))];
      Vec2 centroid;
      for (const Vec2 v : target)
        centroid += v / static_cast<double>(target.size());
      if (centroid == p) break;
      return std::atan2(centroid.y - p.y, centroid.x - p.x) + random.uniform(-halfFov, halfFov);
    }
    default:
      break;
  }
  return random.uniform(-kPi, kPi);
}

}  // namespace

std::uint64_t Random::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double Random::uniform(double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1p-53;
}

int Random::integer(int lo, int hi) {
  return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
}

Case randomCase(std::uint64_t seed, std::uint64_t index, Crowd crowd) {
  Random random(seed ^ (index * 0xd1342543de82ef95ull));
  Case c;
  const bool grid = random.chance(0.5);
  const bool crowded = crowd == Crowd::Many;
  // Drawn where the generators need them, so that a few objects gives the same cases as ever.
  const auto objects = [&] { return crowded ? random.integer(20, 60) : random.integer(1, 4); };
  if (grid) {
    const double w = crowded ? random.integer(24, 40) : random.integer(8, 16);
    const double h = crowded ? random.integer(24, 40) : random.integer(8, 16);
    c.world.boundary = gridBoundary(random, w, h);
    if (random.chance(0.3)) addCollinearVertices(random, c.world.boundary);
    gridObjects(random, c.world, w, h, objects());
  } else {
    const double size = crowded ? 60.0 : 20.0;
    switch (random.integer(0, 2)) {
      case 0:
        c.world.boundary = rectangle(0, 0, size, size);
        break;
      case 1:
        c.world.boundary =
            convexPolygon(random, {0.5 * size, 0.5 * size}, random.integer(3, 10), 0.75 * size);
        break;
      default:
        c.world.boundary = starPolygon(random, {0.5 * size, 0.5 * size}, random.integer(5, 12),
                                       0.35 * size, 0.75 * size, false);
        break;
    }
    if (crowded) {
      generalObjects(random, c.world, size, objects(), 0.01, 0.05);
    } else {
      generalObjects(random, c.world, size, objects(), 0.03, 0.2);
    }
  }
  const double fixedFov[] = {0.25 * kPi, 0.5 * kPi, 0.75 * kPi, kPi - 1e-3, 0.3};
  c.halfFov =
      random.chance(0.5) ? random.uniform(0.05, kPi - 0.05) : fixedFov[random.integer(0, 4)];
  const int cameras = random.integer(1, 4);
  for (int j = 0; j < cameras; ++j) {
    const Vec2 p = cameraPosition(random, c.world, grid);
    c.cameras.push_back({p.x, p.y, cameraYaw(random, c.world, p, c.halfFov)});
  }
  return c;
}

Case longRingCase(std::uint64_t seed, std::uint64_t index) {
  Random random(seed ^ (index * 0xa0761d6478bd642full));
  Case c;
  constexpr double size = 40.0;
  c.world.boundary = rectangle(0, 0, size, size);
  // The rectangle [x0, x1] × [y0, y1] with every side cut into `cuts` equal pieces.
  const auto subdivided = [](double x0, double y0, double x1, double y1, int cuts) {
    const Vec2 corners[] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    Ring ring;
    for (int side = 0; side < 4; ++side) {
      for (int k = 0; k < cuts; ++k)
        ring.push_back(lerp(corners[side], corners[(side + 1) % 4], k / static_cast<double>(cuts)));
    }
    return ring;
  };
  const int longRings = random.integer(1, 2);
  for (int i = 0; i < longRings; ++i) {
    const Vec2 center{random.uniform(10.0, 30.0), random.uniform(10.0, 30.0)};
    const int vertices = random.integer(128, 400);
    Ring ring;
    switch (random.integer(0, 3)) {
      case 0: {  // a disc, its radius jittered by up to a hundredth
        const double r = random.uniform(2.0, 6.0);
        for (int k = 0; k < vertices; ++k) {
          ring.push_back(center + geometry::unitVector(2.0 * kPi * k / vertices) * r *
                                      random.uniform(0.99, 1.0));
        }
        break;
      }
      case 1: {  // integer corners, sides of collinear pieces
        const double x = std::round(center.x), y = std::round(center.y);
        ring = subdivided(x - random.integer(1, 5), y - random.integer(1, 5),
                          x + random.integer(1, 5), y + random.integer(1, 5), vertices / 4);
        break;
      }
      case 2:
        ring = starPolygon(random, center, vertices, 1.0, 6.0, false);
        break;
      default: {  // a neighbour sharing part of the first one's right side: twin pieces
        const double x = std::round(center.x), y = std::round(center.y);
        ring = subdivided(x - 4, y - 3, x, y + 3, vertices / 4);
        c.world.obstacles.push_back(subdivided(x, y - 1, x + 3, y + 5, vertices / 4));
        break;
      }
    }
    (i == 0 || random.chance(0.6) ? c.world.targets : c.world.obstacles).push_back(ring);
  }
  generalObjects(random, c.world, size, random.integer(0, 3), 0.02, 0.06);
  const double fixedFov[] = {0.25 * kPi, 0.5 * kPi, 0.3, 0.05};
  c.halfFov =
      random.chance(0.5) ? random.uniform(0.05, kPi - 0.05) : fixedFov[random.integer(0, 3)];
  const int cameras = random.integer(1, 4);
  for (int j = 0; j < cameras; ++j) {
    const Vec2 p = random.chance(0.3) ? Vec2{random.uniform(0.0, size), random.uniform(0.0, size)}
                                      : cameraPosition(random, c.world, false);
    c.cameras.push_back({p.x, p.y, cameraYaw(random, c.world, p, c.halfFov)});
  }
  return c;
}

Case concurrentCase(std::uint64_t seed, std::uint64_t index) {
  Random random(seed ^ (index * 0x9fb21c651e98df25ull));
  Case c;
  const double size = 20.0;
  c.world.boundary = random.chance(0.5) ? rectangle(0, 0, size, size)
                                        : convexPolygon(random, {0.5 * size, 0.5 * size},
                                                        random.integer(3, 8), 0.75 * size);
  const int hubs = random.integer(1, 3);
  std::vector<Vec2> hubPoints;
  for (int h = 0; h < hubs; ++h) {
    // Anywhere, or on a boundary edge so that the boundary passes through the hub as well.
    const std::size_t i =
        static_cast<std::size_t>(random.integer(0, static_cast<int>(c.world.boundary.size()) - 1));
    const Vec2 x = random.chance(0.3) ? lerp(c.world.boundary[i],
                                             c.world.boundary[(i + 1) % c.world.boundary.size()],
                                             random.uniform(0.2, 0.8))
                                      : Vec2{random.uniform(0.15 * size, 0.85 * size),
                                             random.uniform(0.15 * size, 0.85 * size)};
    hubPoints.push_back(x);
    const int rings = random.integer(2, 4);
    for (int r = 0; r < rings; ++r) {
      // A triangle with its edge a → b through x (as far as rounding a and b allows) and its
      // apex to one side; now and then with x itself as a vertex instead of b, exactly.
      const Vec2 u = geometry::unitVector(random.uniform(0.0, 2.0 * kPi));
      const Vec2 n{-u.y, u.x};
      const Vec2 a = x - u * random.uniform(1.0, 6.0), b = x + u * random.uniform(1.0, 6.0);
      const Vec2 apex = x + n * random.uniform(1.0, 5.0) + u * random.uniform(-3.0, 3.0);
      Ring ring = random.chance(0.2) ? Ring{a, x, apex} : Ring{a, b, apex};
      geometry::normalizeRing(ring);
      (c.world.targets.empty() || random.chance(0.6) ? c.world.targets : c.world.obstacles)
          .push_back(ring);
    }
  }
  // Cameras at a hub (on every ring through it), near one, or anywhere. Cameras a hair beside
  // an edge are randomCase()'s business: their angles are too ill-conditioned to compare where
  // nearly parallel edges cross nearby.
  c.halfFov = random.uniform(0.05, kPi - 0.05);
  const int cameras = random.integer(1, 4);
  const geometry::Box box = geometry::boundingBox(c.world.boundary);
  for (int j = 0; j < cameras; ++j) {
    const Vec2 x = hubPoints[static_cast<std::size_t>(random.integer(0, hubs - 1))];
    Vec2 p;
    switch (random.integer(0, 2)) {
      case 0:
        p = x;
        break;
      case 1:
        p = x + geometry::unitVector(random.uniform(0.0, 2.0 * kPi)) * random.uniform(0.05, 3.0);
        break;
      default:
        p = {random.uniform(box.min.x, box.max.x), random.uniform(box.min.y, box.max.y)};
        break;
    }
    const double yaw = p == x ? random.uniform(-kPi, kPi)
                              : std::atan2(x.y - p.y, x.x - p.x) + random.uniform(-0.5, 0.5);
    c.cameras.push_back({p.x, p.y, yaw});
  }
  return c;
}

Vec2 randomViewpoint(Random& random, const kinematics::World& world) {
  const geometry::Box box = geometry::boundingBox(world.boundary);
  const auto& targets = world.targets;
  const Ring& target =
      targets[static_cast<std::size_t>(random.integer(0, static_cast<int>(targets.size()) - 1))];
  const std::size_t i =
      static_cast<std::size_t>(random.integer(0, static_cast<int>(target.size()) - 1));
  switch (random.integer(0, 3)) {
    case 0:  // q1 of Algorithm 2: on a target's boundary
      return lerp(target[i], target[(i + 1) % target.size()], random.uniform(0.0, 1.0));
    case 1:
      return target[i];
    case 2:
      return lerp(world.boundary[0], world.boundary[1], random.uniform(0.0, 1.0));
    default:
      return {random.uniform(box.min.x, box.max.x), random.uniform(box.min.y, box.max.y)};
  }
}

std::string describe(const Case& c) {
  std::ostringstream out;
  out.precision(17);
  auto ring = [&out](const Ring& r) {
    out << "POLYGON((";
    for (std::size_t i = 0; i <= r.size(); ++i)
      out << (i ? ", " : "") << r[i % r.size()].x << ' ' << r[i % r.size()].y;
    out << "))\n";
  };
  out << "boundary ";
  ring(c.world.boundary);
  for (const Ring& r : c.world.obstacles) {
    out << "obstacle ";
    ring(r);
  }
  for (const Ring& r : c.world.targets) {
    out << "target ";
    ring(r);
  }
  out << "halfFov " << c.halfFov << '\n';
  for (const Pose& p : c.cameras)
    out << "camera " << p.x << ' ' << p.y << ' ' << p.yaw << '\n';
  return out.str();
}

}  // namespace camcov::visibility::testing
