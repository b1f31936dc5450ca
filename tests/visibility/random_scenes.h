#pragma once
// Seeded random Worlds and cameras for the randomized tests, biased towards the degenerate
// configurations the sweep must survive: integer grids (collinear vertices, cameras on
// supporting lines, vertices on one ray), cameras on edges and vertices or 1e-9 beside them,
// field-of-view rays aimed through vertices, touching and overlapping objects, objects poking
// through the boundary, non-convex boundaries with pockets.
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"

namespace camcov::visibility::testing {

// A small portable generator (splitmix64), so a seed means the same case everywhere.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform(double lo, double hi);  // [lo, hi)
  int integer(int lo, int hi);           // [lo, hi]
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

 private:
  std::uint64_t state_;
};

struct Case {
  kinematics::World world;
  std::vector<geometry::Pose> cameras;
  double halfFov = 0.0;
};

// How many objects a case has: a few (1–4 placements), or many (20–60 placements in a room
// about three times as wide), where most of the scene is hidden from most viewpoints.
enum class Crowd { Few, Many };

// The randomized configuration number `index` of the suite seeded with `seed`.
Case randomCase(std::uint64_t seed, std::uint64_t index, Crowd crowd = Crowd::Few);

// Edges of several rings through one point, so that every pair computes its own crossing
// there and the results differ by ulps: 1–3 such hubs, each with 2–4 triangles (targets and
// obstacles) and now and then the boundary passing through it; cameras at the hubs, near them
// or anywhere.
Case concurrentCase(std::uint64_t seed, std::uint64_t index);

// Long rings, so that the sweep passes their pieces by blocks (piece_blocks.h): finely drawn
// discs, rectangles whose sides are runs of hundreds of collinear pieces, many-pointed stars,
// and two subdivided rectangles sharing part of a side (twins); 1–2 of them with a few small
// objects, cameras placed as randomCase() places them or far off.
Case longRingCase(std::uint64_t seed, std::uint64_t index);

// A point where Algorithm 2 would compute a visibility polygon: anywhere, on a target's
// boundary, at a vertex, or on the boundary.
geometry::Vec2 randomViewpoint(Random& random, const kinematics::World& world);

// The case as text, to reproduce a failure.
std::string describe(const Case& c);

}  // namespace camcov::visibility::testing
