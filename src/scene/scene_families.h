#pragma once
// Named families of seeded scenes (`camcov generate --family NAME`): many scenes of one kind —
// L rooms, corridors, slow cameras, deforming targets, a look-alike of the published
// benchmark — for deciding a method's defaults on some seeds and reporting it on others.
// Every family is one row of the table in scene_families.cpp: what it draws from (rooms,
// targets and how they move, obstacles, cameras, their speed, field of view and start) and
// which seeds are for tuning and which for testing (docs/families.md). Decisions:
//  - rooms are polygons made of convex pieces (rectangles, a V notch's quadrilaterals, an
//    octagon), centred at 0, sides in whole half metres;
//  - every object gets a region, a convex polygon grown by a radius that holds every place it
//    can ever take: for an object that does not turn, the hull of its path's waypoints plus
//    every vertex of every shape it takes (deformation keyframes included); for one that
//    turns, the hull of its waypoints grown by its largest vertex distance. A region lies in
//    one piece of the room at least 1.5 m from the piece's sides, and 1.5 m from every other
//    region: objects never leave the room or come within 1.5 m of each other, and a camera
//    kept 0.5 m from everything can pass between any two of them or between one and a wall,
//    so no target is ever cut off;
//  - cameras start inside a piece, at least 1 m from its sides, from every region and from
//    each other;
//  - a scene is drawn from its own stream of util/random.h, seeded by the family's name and
//    the seed; an object or camera that finds no place in 300 tries redraws the whole scene
//    from the next stream of the same seed, so the counts asked for are the counts written;
//  - everything is rounded before any decision is made on it (coordinates to the millimetre,
//    objects' speeds to 0.05 m/s, cameras' to 0.01 m/s, yaws to 0.01°): the same family and
//    seed give the same bytes on every machine, whatever its maths library does in the last
//    bit.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace camcov::scene {

enum class RoomKind {
  rectangle,      // a W x H rectangle (a square when the aspect is 1)
  octagon,        // a rectangle with its corners cut at 45°
  hexagon,        // a rectangle whose left and right sides are pointed
  l_shape,        // a rectangle without its upper right part
  u_shape,        // a rectangle with a notch from the top between two arms
  corridor,       // a long thin rectangle; the aspect is its width over its length, at most 1/5
  z_corridor,     // three legs as wide as the corridor: along, across, along
  z_room,         // the same in a wide box: two wide legs joined by a narrower one
  t_shape,        // a bar across the top on a stem
  cross,          // two bars crossing
  v_notch,        // a rectangle with a triangular notch from below (the published static16)
  pillared_hall,  // a rectangle with a grid of pillars (static obstacles)
};
enum class TargetMotion {
  stand,    // static ("static" in texts)
  loop,     // a closed path of 3 to 6 waypoints on an ellipse
  shuttle,  // back and forth between two points
  turn,     // in place, at angularVelocity
  deform,   // the `deformation` extension, in place or on a short shuttle
};
enum class ObstacleMotion { stand, shuttle, loop, spin };
enum class CameraStart {
  spread,       // anywhere free, any yaw
  facing_away,  // every object outside the view cone, with 10° to spare, for all time
  far,          // the free place farthest from every object, any yaw
};
enum class ShapeStyle {
  stars,      // star-shaped polygons of 3 to 8 vertices: convex or not
  published,  // the published benchmark's own target and obstacle shapes
};

struct Range {
  double lo = 0.0;
  double hi = 0.0;
};
struct CountRange {
  int lo = 0;
  int hi = 0;
};
struct SeedRange {
  std::uint64_t first = 0;  // inclusive
  std::uint64_t last = 0;   // inclusive
  bool contains(std::uint64_t seed) const { return first <= seed && seed <= last; }
};
// Defaults of a method are decided on the tune seeds, then reported once on the test seeds.
struct SeedSplit {
  SeedRange tune;
  SeedRange test;
};

// One family: every range it draws from. A kind listed twice is drawn twice as often.
struct SceneFamily {
  std::string_view name;
  std::string_view summary;  // one line
  std::vector<RoomKind> rooms;
  Range roomLength;  // m, the longer side of the room's bounding box (whole half metres)
  Range roomAspect;  // shorter over longer side; corridors: the corridor's width over length
  CountRange targets;
  std::vector<TargetMotion> targetMotions;
  ShapeStyle shapes = ShapeStyle::stars;
  // m, a star target's largest vertex distance from its reference point (with the published
  // shapes: what theirs span, not drawn)
  Range targetRadius;
  Range targetSpeed;     // m/s along its path
  Range pathLength;      // m, a shuttle's length, a loop's longer diameter (also for obstacles)
  CountRange obstacles;  // besides a hall's pillars
  std::vector<ObstacleMotion> obstacleMotions;
  // m, a block's longer side, a spinning bar's length (with the published shapes: what theirs
  // span, not drawn)
  Range obstacleLength;
  Range obstacleSpeed;  // m/s along its path
  CountRange cameras;
  Range crossingSeconds;  // a camera at v_max crosses the room's longer side in this time
  Range cameraTurnRate;   // rad/s
  Range halfFovDeg;       // θ, whole degrees
  std::vector<CameraStart> starts;
  SeedSplit seeds;
};

// The table, in the order `--family list` prints it.
const std::vector<SceneFamily>& sceneFamilies();
// InputError naming every known family when there is none of that name.
const SceneFamily& sceneFamily(std::string_view name);
SeedSplit familySeeds(std::string_view name);
// "published_like, convex_rooms, ...".
std::string familyNames();
// What `camcov generate --family list` prints: every family with its seeds, its summary and
// its ranges.
std::string familyTable();

// Whether `name` is one of the table's families.
bool isSceneFamily(std::string_view name);

// "<family>-<seed>.json".
std::string familySceneFileName(std::string_view family, std::uint64_t seed);
// The scene file's content, with its family, and its description naming the family, the seed
// and what was drawn;
// the same family and seed give the same JSON, to the byte. Any seed is accepted.
nlohmann::json generateFamilyScene(const SceneFamily& family, std::uint64_t seed);

}  // namespace camcov::scene
