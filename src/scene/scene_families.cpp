#include "scene/scene_families.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "scene/scene_writer.h"
#include "util/fnv1a.h"
#include "util/input_error.h"
#include "util/random.h"

namespace camcov::scene {

// A generated scene's description starts "family NAME seed S: ", for people (a bench reads the
// scene's "family" key).
constexpr std::string_view kFamilyLead = "family ";
constexpr std::string_view kSeedLead = " seed ";

// ---------------------------------------------------------------------------------------------
// The table: every family, in one place. docs/families.md shows it as `--family list` prints
// it (a test checks that the two agree).
// ---------------------------------------------------------------------------------------------

namespace {

using enum RoomKind;
using enum CameraStart;
using TM = TargetMotion;
using OM = ObstacleMotion;

// The same split for every family: the tune seeds are the ones anybody tries first.
constexpr SeedSplit kSeeds{{1, 1000}, {100001, 101000}};

// A function's static, made on first use: safe from the order in which files are initialised.
const std::vector<SceneFamily>& table() {
  static const std::vector<SceneFamily> families{
      {.name = "published_like",
       .summary = "looks like the published benchmark: 30 m squares, its shapes, speeds and counts",
       .rooms = {rectangle, rectangle, rectangle, rectangle, rectangle, rectangle, v_notch},
       .roomLength = {30, 30},
       .roomAspect = {1, 1},
       .targets = {1, 6},
       .targetMotions = {TM::stand, TM::stand, TM::shuttle, TM::loop, TM::turn},
       .shapes = ShapeStyle::published,
       .targetRadius = {1.4, 7.1},
       .targetSpeed = {0.25, 1},
       .pathLength = {5, 16},
       .obstacles = {0, 2},
       .obstacleMotions = {OM::stand, OM::stand, OM::shuttle, OM::loop, OM::spin},
       .obstacleLength = {2.5, 16},
       .obstacleSpeed = {0.5, 2},
       .cameras = {1, 5},
       .crossingSeconds = {3, 60},
       .cameraTurnRate = {0.1, 3},
       .halfFovDeg = {30, 30},
       .starts = {spread},
       .seeds = kSeeds},
      {.name = "convex_rooms",
       .summary = "rectangles, octagons and hexagons: every motion, wide and narrow views",
       .rooms = {rectangle, octagon, hexagon},
       .roomLength = {15, 40},
       .roomAspect = {0.5, 1},
       .targets = {2, 5},
       .targetMotions = {TM::stand, TM::loop, TM::shuttle, TM::turn, TM::deform},
       .targetRadius = {0.5, 2},
       .targetSpeed = {0.3, 1.2},
       .pathLength = {3, 12},
       .obstacles = {0, 2},
       .obstacleMotions = {OM::stand, OM::shuttle},
       .obstacleLength = {1, 4},
       .obstacleSpeed = {0.3, 1},
       .cameras = {1, 4},
       .crossingSeconds = {8, 40},
       .cameraTurnRate = {0.5, 2},
       .halfFovDeg = {20, 60},
       .starts = {spread, facing_away},
       .seeds = kSeeds},
      {.name = "l_rooms",
       .summary = "L rooms: the reflex corner occludes, cameras often start in the other leg",
       .rooms = {l_shape},
       .roomLength = {20, 40},
       .roomAspect = {0.6, 1},
       .targets = {2, 4},
       .targetMotions = {TM::stand, TM::loop, TM::shuttle, TM::turn},
       .targetRadius = {0.5, 1.5},
       .targetSpeed = {0.3, 1},
       .pathLength = {3, 10},
       .obstacles = {0, 2},
       .obstacleMotions = {OM::stand},
       .obstacleLength = {1, 4},
       .obstacleSpeed = {0.3, 1},
       .cameras = {1, 3},
       .crossingSeconds = {10, 45},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {20, 45},
       .starts = {far, spread, facing_away},
       .seeds = kSeeds},
      {.name = "u_rooms",
       .summary = "U rooms: two arms seen from nowhere at once, targets around two corners",
       .rooms = {u_shape},
       .roomLength = {24, 44},
       .roomAspect = {0.6, 1},
       .targets = {2, 4},
       .targetMotions = {TM::stand, TM::loop, TM::shuttle, TM::turn},
       .targetRadius = {0.5, 1.5},
       .targetSpeed = {0.3, 1},
       .pathLength = {3, 10},
       .obstacles = {0, 2},
       .obstacleMotions = {OM::stand, OM::shuttle},
       .obstacleLength = {1, 4},
       .obstacleSpeed = {0.3, 1},
       .cameras = {1, 3},
       .crossingSeconds = {10, 45},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {20, 45},
       .starts = {far, far, spread},
       .seeds = kSeeds},
      {.name = "corridors",
       .summary = "long straight and Z corridors 4-10 m wide: long shuttles, long ways round",
       .rooms = {corridor, z_corridor},
       .roomLength = {32, 56},
       .roomAspect = {0.125, 0.18},
       .targets = {1, 4},
       .targetMotions = {TM::stand, TM::shuttle, TM::shuttle, TM::loop, TM::turn},
       .targetRadius = {0.4, 1},
       .targetSpeed = {0.4, 1.2},
       .pathLength = {4, 20},
       .obstacles = {0, 2},
       .obstacleMotions = {OM::stand, OM::shuttle},
       .obstacleLength = {0.8, 2},
       .obstacleSpeed = {0.3, 1},
       .cameras = {1, 3},
       .crossingSeconds = {15, 60},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {20, 40},
       .starts = {spread, far},
       .seeds = kSeeds},
      {.name = "pillared_halls",
       .summary = "halls with a grid of pillars that occlude: small targets between them",
       .rooms = {pillared_hall},
       .roomLength = {20, 36},
       .roomAspect = {0.6, 1},
       .targets = {2, 6},
       .targetMotions = {TM::stand, TM::loop, TM::shuttle, TM::turn},
       .targetRadius = {0.4, 1},
       .targetSpeed = {0.3, 1},
       .pathLength = {2, 6},
       .obstacles = {0, 1},
       .obstacleMotions = {OM::shuttle},
       .obstacleLength = {0.8, 2},
       .obstacleSpeed = {0.3, 0.8},
       .cameras = {2, 5},
       .crossingSeconds = {10, 40},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {25, 50},
       .starts = {spread, facing_away},
       .seeds = kSeeds},
      {.name = "nonconvex_rooms",
       .summary = "T, cross, Z, V-notch, L and U rooms: every motion, every start",
       .rooms = {t_shape, cross, z_room, v_notch, l_shape, u_shape},
       .roomLength = {24, 44},
       .roomAspect = {0.6, 1},
       .targets = {2, 5},
       .targetMotions = {TM::stand, TM::loop, TM::shuttle, TM::turn, TM::deform},
       .targetRadius = {0.5, 1.5},
       .targetSpeed = {0.3, 1},
       .pathLength = {3, 10},
       .obstacles = {0, 2},
       .obstacleMotions = {OM::stand, OM::shuttle, OM::spin},
       .obstacleLength = {1, 4},
       .obstacleSpeed = {0.3, 1},
       .cameras = {1, 4},
       .crossingSeconds = {10, 45},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {20, 60},
       .starts = {spread, far, facing_away},
       .seeds = kSeeds},
      {.name = "slow_cameras",
       .summary = "cameras that need 60-150 s to cross the room and turn slowly: moving targets",
       .rooms = {rectangle, octagon, l_shape},
       .roomLength = {15, 35},
       .roomAspect = {0.5, 1},
       .targets = {1, 4},
       .targetMotions = {TM::loop, TM::shuttle, TM::turn, TM::stand},
       .targetRadius = {0.5, 1.5},
       .targetSpeed = {0.3, 1},
       .pathLength = {3, 10},
       .obstacles = {0, 1},
       .obstacleMotions = {OM::stand},
       .obstacleLength = {1, 3},
       .obstacleSpeed = {0.3, 1},
       .cameras = {1, 3},
       .crossingSeconds = {60, 150},
       .cameraTurnRate = {0.2, 0.6},
       .halfFovDeg = {20, 60},
       .starts = {spread, facing_away},
       .seeds = kSeeds},
      {.name = "big_teams",
       .summary = "5-8 cameras over 6-12 targets in large rooms and halls",
       .rooms = {rectangle, octagon, pillared_hall},
       .roomLength = {30, 50},
       .roomAspect = {0.6, 1},
       .targets = {6, 12},
       .targetMotions = {TM::stand, TM::loop, TM::shuttle, TM::turn, TM::deform},
       .targetRadius = {0.5, 1.5},
       .targetSpeed = {0.3, 1.2},
       .pathLength = {3, 10},
       .obstacles = {0, 4},
       .obstacleMotions = {OM::stand, OM::shuttle, OM::loop},
       .obstacleLength = {1, 4},
       .obstacleSpeed = {0.3, 1},
       .cameras = {5, 8},
       .crossingSeconds = {8, 30},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {20, 40},
       .starts = {spread},
       .seeds = kSeeds},
      {.name = "far_starts",
       .summary = "cameras start as far from every object as the room allows, or facing away",
       .rooms = {rectangle, l_shape, u_shape, z_corridor, v_notch},
       .roomLength = {20, 40},
       .roomAspect = {0.15, 0.8},
       .targets = {1, 4},
       .targetMotions = {TM::stand, TM::loop, TM::shuttle, TM::turn, TM::deform},
       .targetRadius = {0.5, 1.5},
       .targetSpeed = {0.3, 1},
       .pathLength = {3, 10},
       .obstacles = {0, 2},
       .obstacleMotions = {OM::stand},
       .obstacleLength = {1, 4},
       .obstacleSpeed = {0.3, 1},
       .cameras = {1, 3},
       .crossingSeconds = {8, 40},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {20, 60},
       .starts = {far, facing_away},
       .seeds = kSeeds},
      {.name = "moving_obstacles",
       .summary = "2-4 obstacles that shuttle, loop or spin across the views",
       .rooms = {rectangle, octagon, hexagon},
       .roomLength = {20, 36},
       .roomAspect = {0.6, 1},
       .targets = {1, 4},
       .targetMotions = {TM::stand, TM::loop, TM::shuttle},
       .targetRadius = {0.5, 1.5},
       .targetSpeed = {0.3, 1},
       .pathLength = {4, 12},
       .obstacles = {2, 4},
       .obstacleMotions = {OM::shuttle, OM::loop, OM::spin},
       .obstacleLength = {1, 5},
       .obstacleSpeed = {0.3, 1.5},
       .cameras = {1, 4},
       .crossingSeconds = {8, 30},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {25, 45},
       .starts = {spread},
       .seeds = kSeeds},
      {.name = "deforming_targets",
       .summary = "targets that breathe and wobble (the deformation key), some turning",
       .rooms = {rectangle, hexagon, l_shape},
       .roomLength = {16, 32},
       .roomAspect = {0.6, 1},
       .targets = {1, 4},
       .targetMotions = {TM::deform, TM::deform, TM::turn, TM::stand, TM::loop},
       .targetRadius = {0.6, 2},
       .targetSpeed = {0.3, 1},
       .pathLength = {3, 8},
       .obstacles = {0, 2},
       .obstacleMotions = {OM::stand, OM::spin},
       .obstacleLength = {1, 4},
       .obstacleSpeed = {0.3, 1},
       .cameras = {1, 3},
       .crossingSeconds = {8, 30},
       .cameraTurnRate = {0.5, 1.5},
       .halfFovDeg = {20, 60},
       .starts = {spread, facing_away},
       .seeds = kSeeds},
  };
  return families;
}

// ---------------------------------------------------------------------------------------------
// Names and the printed table.
// ---------------------------------------------------------------------------------------------

std::string_view nameOf(RoomKind kind) {
  static constexpr std::array kNames{"rectangle", "octagon",  "hexagon",    "l_shape",
                                     "u_shape",   "corridor", "z_corridor", "z_room",
                                     "t_shape",   "cross",    "v_notch",    "pillared_hall"};
  return kNames.at(static_cast<std::size_t>(kind));
}
std::string_view nameOf(TargetMotion motion) {
  static constexpr std::array kNames{"static", "loop", "shuttle", "turn", "deform"};
  return kNames.at(static_cast<std::size_t>(motion));
}
std::string_view nameOf(ObstacleMotion motion) {
  static constexpr std::array kNames{"static", "shuttle", "loop", "spin"};
  return kNames.at(static_cast<std::size_t>(motion));
}
std::string_view nameOf(CameraStart start) {
  static constexpr std::array kNames{"spread", "facing_away", "far"};
  return kNames.at(static_cast<std::size_t>(start));
}

// Is kinds[i] the first of its kind in the list?
template <class Kind>
bool firstOfItsKind(const std::vector<Kind>& kinds, std::size_t i) {
  return std::find(kinds.begin(), kinds.end(), kinds[i]) ==
         kinds.begin() + static_cast<std::ptrdiff_t>(i);
}

// "a, b x2, c": kinds in the table's order, a repeated kind once with its weight.
template <class Kind>
std::string kindsText(const std::vector<Kind>& kinds) {
  std::string text;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    if (!firstOfItsKind(kinds, i)) continue;
    const auto n = std::count(kinds.begin(), kinds.end(), kinds[i]);
    text += fmt::format("{}{}{}", text.empty() ? "" : ", ", nameOf(kinds[i]),
                        n > 1 ? fmt::format(" x{}", n) : "");
  }
  return text;
}

// "0.3-1", or "30" when both ends are one.
template <class R>
std::string rangeText(R r) {
  return r.lo == r.hi ? fmt::format("{}", r.lo) : fmt::format("{}-{}", r.lo, r.hi);
}
std::string rangeText(SeedRange r) {
  return fmt::format("{}-{}", r.first, r.last);
}

std::string familyRanges(const SceneFamily& f) {
  const bool published = f.shapes == ShapeStyle::published;
  const std::string targetShapes =
      published ? std::string("the published shapes")
                : fmt::format("stars of radius {} m", rangeText(f.targetRadius));
  const std::string obstacleShapes =
      published ? std::string("the published shapes")
                : fmt::format("blocks {} m long", rangeText(f.obstacleLength));
  return fmt::format(
      "    rooms      {}; {} m long, aspect {}\n"
      "    targets    {} ({}); {}; {} m/s; paths {} m\n"
      "    obstacles  {} ({}); {}; {} m/s\n"
      "    cameras    {}; {} s to cross the room; {} rad/s; half FoV {} deg; start {}\n",
      kindsText(f.rooms), rangeText(f.roomLength), rangeText(f.roomAspect), rangeText(f.targets),
      kindsText(f.targetMotions), targetShapes, rangeText(f.targetSpeed), rangeText(f.pathLength),
      rangeText(f.obstacles), kindsText(f.obstacleMotions), obstacleShapes,
      rangeText(f.obstacleSpeed), rangeText(f.cameras), rangeText(f.crossingSeconds),
      rangeText(f.cameraTurnRate), rangeText(f.halfFovDeg), kindsText(f.starts));
}

}  // namespace

const std::vector<SceneFamily>& sceneFamilies() {
  return table();
}

std::string familyNames() {
  std::string names;
  for (const SceneFamily& f : table())
    names += fmt::format("{}{}", names.empty() ? "" : ", ", f.name);
  return names;
}

const SceneFamily& sceneFamily(std::string_view name) {
  for (const SceneFamily& f : table()) {
    if (f.name == name) return f;
  }
  throw InputError(
      fmt::format("unknown scene family '{}': the families are {}", name, familyNames()));
}

SeedSplit familySeeds(std::string_view name) {
  return sceneFamily(name).seeds;
}

std::string familyTable() {
  std::string text = fmt::format("{:<18} {:<12} {:<14} {}\n", "family", "tune seeds", "test seeds",
                                 "what it stresses");
  for (const SceneFamily& f : table()) {
    text += fmt::format("{:<18} {:<12} {:<14} {}\n", f.name, rangeText(f.seeds.tune),
                        rangeText(f.seeds.test), f.summary);
    text += familyRanges(f);
  }
  return text;
}

bool isSceneFamily(std::string_view name) {
  const auto& all = sceneFamilies();
  return std::any_of(all.begin(), all.end(), [&](const SceneFamily& f) { return f.name == name; });
}

std::string familySceneFileName(std::string_view family, std::uint64_t seed) {
  return fmt::format("{}-{}.json", family, seed);
}

// ---------------------------------------------------------------------------------------------
// Drawing a scene.
// ---------------------------------------------------------------------------------------------

namespace {

using geometry::Ring;
using geometry::Vec2;

// Every region keeps this from the sides of its piece of the room and from every other
// region: more than the 0.5 m margin promised, and a way 0.5 m wide for a camera kept
// δ = 0.5 m from both sides, so no part of the room is ever closed off.
constexpr double kGap = 1.5;
constexpr double kCameraGap = 1.0;    // m, cameras from the sides, every region, each other
constexpr double kAwayMargin = 10.0;  // degrees of free view beyond each edge of a camera's view
constexpr int kTries = 300;           // places tried per object and per camera
constexpr int kAttempts = 200;        // whole scenes drawn from one seed before giving up
constexpr int kFarCandidates = 64;    // free places compared for a "far" start

double halfMetres(double v) {
  return roundTo(v, 2.0);
}

double draw(Random& r, Range range) {
  return r.uniform(range.lo, range.hi);
}
int draw(Random& r, CountRange range) {
  return range.lo + static_cast<int>(r.index(static_cast<std::uint64_t>(range.hi - range.lo + 1)));
}
template <class T>
T pick(Random& r, const std::vector<T>& kinds) {
  return kinds[r.index(kinds.size())];
}
double drawSign(Random& r) {
  return r.uniform() < 0.5 ? -1.0 : 1.0;
}

// --- rooms -----------------------------------------------------------------------------------

struct Room {
  RoomKind kind = rectangle;
  double width = 0.0, height = 0.0;  // bounding box, m
  Ring boundary;                     // CCW, centred at 0
  std::vector<Ring> pieces;          // convex, CCW, inside the boundary, covering it
  std::vector<double> pieceAreas;
  std::vector<Vec2> pillars;  // centres (pillared halls)
  double pillarRadius = 0.0;
};

Ring box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A Z of three legs: along the bottom from the left, `middle` wide up the middle, along the
// top to the right; the outer legs are `leg` wide.
void zShape(Room& room, double leg, double middle) {
  const double w = room.width, h = room.height, s = halfMetres(w / 2);
  const double x0 = s - middle / 2, x1 = s + middle / 2;
  room.boundary = {{0, 0}, {x1, 0}, {x1, h - leg}, {w, h - leg},
                   {w, h}, {x0, h}, {x0, leg},     {0, leg}};
  room.pieces = {box(0, 0, x1, leg), box(x0, 0, x1, h), box(x0, h - leg, w, h)};
}

void lShape(Room& room, Random& r) {
  const double w = room.width, h = room.height;
  const double a = halfMetres(r.uniform(0.35, 0.55) * w), b = halfMetres(r.uniform(0.35, 0.55) * h);
  room.boundary = {{0, 0}, {w, 0}, {w, b}, {a, b}, {a, h}, {0, h}};
  room.pieces = {box(0, 0, w, b), box(0, 0, a, h)};
}

void uShape(Room& room, Random& r) {
  const double w = room.width, h = room.height;
  const double a = halfMetres(r.uniform(0.25, 0.35) * w), b = halfMetres(r.uniform(0.3, 0.45) * h);
  room.boundary = {{0, 0}, {w, 0}, {w, h}, {w - a, h}, {w - a, b}, {a, b}, {a, h}, {0, h}};
  room.pieces = {box(0, 0, w, b), box(0, 0, a, h), box(w - a, 0, w, h)};
}

void tShape(Room& room, Random& r) {
  const double w = room.width, h = room.height, s = halfMetres(w / 2);
  const double bar = halfMetres(r.uniform(0.35, 0.5) * h);
  const double stem = halfMetres(r.uniform(0.3, 0.45) * w);
  const double x0 = s - stem / 2, x1 = s + stem / 2;
  room.boundary = {{x0, 0}, {x1, 0}, {x1, h - bar}, {w, h - bar},
                   {w, h},  {0, h},  {0, h - bar},  {x0, h - bar}};
  room.pieces = {box(0, h - bar, w, h), box(x0, 0, x1, h)};
}

void crossShape(Room& room, Random& r) {
  const double w = room.width, h = room.height;
  const double sx = halfMetres(w / 2), sy = halfMetres(h / 2);
  const double a = halfMetres(r.uniform(0.3, 0.45) * w), b = halfMetres(r.uniform(0.3, 0.45) * h);
  const double x0 = sx - a / 2, x1 = sx + a / 2, y0 = sy - b / 2, y1 = sy + b / 2;
  room.boundary = {{x0, 0}, {x1, 0}, {x1, y0}, {w, y0}, {w, y1}, {x1, y1},
                   {x1, h}, {x0, h}, {x0, y1}, {0, y1}, {0, y0}, {x0, y0}};
  room.pieces = {box(0, y0, w, y1), box(x0, 0, x1, h)};
}

// A triangular notch from below, its apex at height d: the part above the apex and the two
// quadrilaterals beside the notch are convex.
void vNotch(Room& room, Random& r) {
  const double w = room.width, h = room.height;
  const double x1 = halfMetres(r.uniform(0.2, 0.35) * w), x2 = halfMetres(r.uniform(0.65, 0.8) * w);
  const double xm = halfMetres((x1 + x2) / 2), d = halfMetres(r.uniform(0.4, 0.6) * h);
  room.boundary = {{0, 0}, {x1, 0}, {xm, d}, {x2, 0}, {w, 0}, {w, h}, {0, h}};
  room.pieces = {box(0, d, w, h), Ring{{0, 0}, {x1, 0}, {xm, d}, {0, d}},
                 Ring{{x2, 0}, {w, 0}, {w, d}, {xm, d}}};
}

void cutCorners(Room& room, Random& r) {
  const double w = room.width, h = room.height;
  const double c = halfMetres(r.uniform(0.15, 0.3) * std::min(w, h));
  room.boundary = {{c, 0}, {w - c, 0}, {w, c}, {w, h - c}, {w - c, h}, {c, h}, {0, h - c}, {0, c}};
  room.pieces = {room.boundary};
}

void pointSides(Room& room, Random& r) {
  const double w = room.width, h = room.height;
  const double c = halfMetres(r.uniform(0.15, 0.3) * w);
  room.boundary = {{c, 0}, {w - c, 0}, {w, h / 2}, {w - c, h}, {c, h}, {0, h / 2}};
  room.pieces = {room.boundary};
}

// Pillars in the middle of the cells of a grid of 2 to 5 cells each way, at least 6 m wide
// (rooms are at least 12 m each way): every pillar at least 2.3 m from the walls and 4.6 m
// from the next, so targets fit between them.
void pillars(Room& room, Random& r) {
  const double spacing = r.uniform(6.0, 9.0);
  const int nx = std::clamp(static_cast<int>(room.width / spacing), 2, 5);
  const int ny = std::clamp(static_cast<int>(room.height / spacing), 2, 5);
  room.pillarRadius = roundTo(r.uniform(0.3, 0.7), 20.0);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j)
      room.pillars.push_back(mm(Vec2{(i + 0.5) * room.width / nx, (j + 0.5) * room.height / ny}));
  }
}

void centre(Room& room) {
  const Vec2 shift{-room.width / 2, -room.height / 2};  // multiples of 0.25 m: exact
  for (Vec2& p : room.boundary)
    p += shift;
  for (Ring& piece : room.pieces) {
    for (Vec2& p : piece)
      p += shift;
    room.pieceAreas.push_back(geometry::signedArea(piece));
  }
  for (Vec2& p : room.pillars)
    p = mm(p + shift);
}

Room makeRoom(const SceneFamily& f, Random& r) {
  Room room;
  room.kind = pick(r, f.rooms);
  const double length = halfMetres(draw(r, f.roomLength));
  const double aspect = draw(r, f.roomAspect);
  room.width = length;
  room.height = std::max(halfMetres(aspect * length), 4.0);
  if (room.kind == corridor || room.kind == z_corridor) {
    // A corridor is at most a fifth of its length wide, whatever the family's aspect.
    room.height = std::max(std::min(room.height, halfMetres(length / 5)), 4.0);
  }
  switch (room.kind) {
    case rectangle:
    case corridor:
    case pillared_hall:
      room.boundary = box(0, 0, room.width, room.height);
      room.pieces = {room.boundary};
      if (room.kind == pillared_hall) pillars(room, r);
      break;
    case z_corridor: {
      // The aspect is the corridor's width; the middle leg goes up half the length, at
      // least far enough for two corridor widths and 4 m between them.
      const double leg = room.height;
      room.height = std::max(halfMetres(length / 2), 2 * leg + 4.0);
      zShape(room, leg, leg);
      break;
    }
    case z_room:
      zShape(room, halfMetres(r.uniform(0.3, 0.38) * room.height),
             halfMetres(r.uniform(0.25, 0.35) * room.width));
      break;
    case octagon:
      cutCorners(room, r);
      break;
    case hexagon:
      pointSides(room, r);
      break;
    case l_shape:
      lShape(room, r);
      break;
    case u_shape:
      uShape(room, r);
      break;
    case t_shape:
      tShape(room, r);
      break;
    case cross:
      crossShape(room, r);
      break;
    case v_notch:
      vNotch(room, r);
      break;
  }
  centre(room);
  return room;
}

std::string roomText(const Room& room) {
  static constexpr std::array kWords{"rectangular room", "octagonal room", "hexagonal room",
                                     "L room",           "U room",         "corridor",
                                     "Z corridor",       "Z room",         "T room",
                                     "cross room",       "V-notch room",   "pillared hall"};
  const bool square = room.kind == rectangle && room.width == room.height;
  std::string text = fmt::format(
      "{} {}x{} m", square ? "square room" : kWords.at(static_cast<std::size_t>(room.kind)),
      room.width, room.height);
  if (!room.pillars.empty()) text += fmt::format(" with {} pillars", room.pillars.size());
  return text;
}

// Inward distance of p from the side a -> b of a CCW convex piece (negative outside).
double inward(Vec2 a, Vec2 b, Vec2 p) {
  return geometry::cross(b - a, p - a) / geometry::distance(a, b);
}

// Does the disc of `radius` about every point lie in the convex piece, `gap` from its sides?
// Then so does the hull of the points grown by `radius`.
bool fitsPiece(const Ring& piece, const std::vector<Vec2>& points, double radius, double gap) {
  for (std::size_t i = 0; i < piece.size(); ++i) {
    const Vec2 a = piece[i], b = piece[(i + 1) % piece.size()];
    for (const Vec2 p : points) {
      if (inward(a, b, p) < radius + gap) return false;
    }
  }
  return true;
}

bool fitsRoom(const Room& room, const std::vector<Vec2>& points, double radius, double gap) {
  return std::any_of(room.pieces.begin(), room.pieces.end(),
                     [&](const Ring& piece) { return fitsPiece(piece, points, radius, gap); });
}

// A point drawn uniformly in the bounding box of a piece chosen by its area; it may fall
// outside the piece, which the fit tests then refuse.
Vec2 drawPoint(const Room& room, Random& r) {
  double total = 0.0;
  for (const double a : room.pieceAreas)
    total += a;
  double u = r.uniform(0.0, total);
  std::size_t i = 0;
  while (i + 1 < room.pieces.size() && u >= room.pieceAreas[i])
    u -= room.pieceAreas[i++];
  const geometry::Box b = geometry::boundingBox(room.pieces[i]);
  return mm(Vec2{r.uniform(b.min.x, b.max.x), r.uniform(b.min.y, b.max.y)});
}

// --- objects ---------------------------------------------------------------------------------

// All the room an object can ever take: the convex hull grown by the radius.
struct Region {
  std::vector<Vec2> hull;  // CCW; one point, two, or a polygon
  double radius = 0.0;
  geometry::Box box;  // of the hull grown by the radius
};

Region makeRegion(std::vector<Vec2> points, double radius) {
  Region region{geometry::convexHull(std::move(points)), radius, {}};
  region.box = geometry::grown(geometry::boundingBox(region.hull), radius);
  return region;
}

double gapBetween(const Region& a, const Region& b) {
  return geometry::distanceBetweenPolygons(a.hull, b.hull) - a.radius - b.radius;
}

bool clearOf(const std::vector<Region>& taken, const Region& region, double gap) {
  return std::none_of(taken.begin(), taken.end(), [&](const Region& other) {
    return geometry::overlaps(geometry::grown(other.box, gap), region.box) &&
           gapBetween(other, region) < gap;
  });
}

double distanceTo(const Region& region, Vec2 p) {
  return geometry::distanceToPolygon(region.hull, p) - region.radius;
}

struct Object {
  Ring shape;                        // local, about the reference point
  std::vector<Ring> keyframeShapes;  // the deformation's, vertex for vertex like `shape`
  std::vector<double> keyframeTimes;
  double period = 0.0;
  std::vector<Vec2> path;  // offsets from the centre until placed, then world coordinates
  double velocity = 0.0;   // m/s, written when the path moves
  double angularVelocity = 0.0;
};

// Every place the object can take. Without turning, its reference point stays in the hull of
// the waypoints and its local shape in the hull of the vertices of every shape it takes
// (a deformation moves each vertex along segments between them), so the object stays in the
// hull of their sums; turning, it stays within its largest vertex distance of the reference.
Region regionOf(const Object& o) {
  std::vector<const Ring*> shapes{&o.shape};
  for (const Ring& k : o.keyframeShapes)
    shapes.push_back(&k);
  if (o.angularVelocity == 0.0) {
    std::vector<Vec2> sums;
    for (const Vec2 w : o.path) {
      for (const Ring* s : shapes) {
        for (const Vec2 v : *s)
          sums.push_back(w + v);
      }
    }
    return makeRegion(std::move(sums), 0.0);
  }
  double reach = 0.0;
  for (const Ring* s : shapes) {
    for (const Vec2 v : *s)
      reach = std::max(reach, geometry::norm(v));
  }
  return makeRegion(o.path, reach);
}

Ring rounded(Ring ring) {
  for (Vec2& p : ring)
    p = mm(p);
  return ring;
}

Ring rotatedRing(Ring ring, double angle) {
  for (Vec2& p : ring)
    p = mm(geometry::rotated(p, angle));
  return ring;
}

// The published benchmark's shapes, as its files write them.
const std::vector<Ring>& publishedTargetShapes() {
  static const std::vector<Ring> shapes{
      {{-2, -1}, {2, 1}, {2, -1}},
      {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}},
      {{-1, -1}, {2, 1}, {2, -2}},
      {{-1, -1}, {-1, 1}, {1, 1}, {2, 0}, {1, -1}},
      {{-1, 0}, {0, 4}, {2, 2}, {5, 5}, {6, -1}},
  };
  return shapes;
}
const std::vector<Ring>& publishedObstacleShapes() {
  static const std::vector<Ring> shapes{
      {{2.5, 2.5}, {2.5, 0}, {0, 0}, {0, 2.5}}, {{-1, -3}, {-1, 3}, {1, 3}, {1, -3}},
      {{-5, 1}, {5, 1}, {5, -1}, {-5, -1}},     {{-3, 3}, {3, 3}, {3, -3}, {-3, -3}},
      {{-1, -6}, {-1, 6}, {1, 8}, {1, -8}},
  };
  return shapes;
}
const Ring& publishedSpinningBar() {
  static const Ring bar{{-1, -5}, {-1, 5}, {1, 7}, {1, -7}};
  return bar;
}

// Vertex directions of a star: evenly spaced and jittered by at most a fifth of the spacing,
// so every gap stays under 180°: the origin is inside and the ring counter-clockwise.
std::vector<double> starAngles(int n, Random& r) {
  const double step = 2 * std::numbers::pi / n, start = r.uniform(0.0, step);
  std::vector<double> angles;
  for (int k = 0; k < n; ++k)
    angles.push_back(start + k * step + r.uniform(-0.2, 0.2) * step);
  return angles;
}

Ring starRing(const std::vector<double>& angles, const std::vector<double>& radii) {
  Ring ring;
  for (std::size_t k = 0; k < angles.size(); ++k)
    ring.push_back(mm(geometry::unitVector(angles[k]) * radii[k]));
  return ring;
}

std::vector<double> starRadii(int n, double radius, Random& r) {
  std::vector<double> radii;
  for (int k = 0; k < n; ++k)
    radii.push_back(radius * r.uniform(0.5, 1.0));
  return radii;
}

// A star that breathes (every vertex scaled alike) or wobbles (each its own way) through one
// or two keyframes. Its vertices only move along their own rays, so every shape in between
// is a star about the same directions: simple, as the loader requires.
void deformingStar(Object& o, double radius, Random& r) {
  const int n = 5 + static_cast<int>(r.index(4));
  const std::vector<double> angles = starAngles(n, r), radii = starRadii(n, radius, r);
  o.shape = starRing(angles, radii);
  const bool breathe = r.uniform() < 0.5;
  const int keyframes = 1 + static_cast<int>(r.index(2));
  o.period = roundTo(r.uniform(2.0, 8.0), 10.0);
  for (int k = 1; k <= keyframes; ++k) {
    const double common = r.uniform(0.6, 1.4);
    std::vector<double> scaled = radii;
    for (double& v : scaled)
      v *= breathe ? common : r.uniform(0.6, 1.4);
    o.keyframeShapes.push_back(starRing(angles, scaled));
    o.keyframeTimes.push_back(roundTo(o.period * k / (keyframes + 1), 100.0));
  }
}

std::vector<Vec2> shuttleOffsets(double length, Random& r) {
  const Vec2 half = geometry::unitVector(r.uniform(0.0, std::numbers::pi)) * (length / 2);
  return {half, -half};
}

// 3 to 6 waypoints in order on an ellipse of the given longer diameter, turned at random.
std::vector<Vec2> loopOffsets(double length, Random& r) {
  const int n = 3 + static_cast<int>(r.index(4));
  const double a = length / 2, b = a * r.uniform(0.4, 1.0);
  const double turn = r.uniform(0.0, std::numbers::pi);
  const double step = 2 * std::numbers::pi / n, start = r.uniform(0.0, step);
  std::vector<Vec2> points;
  for (int k = 0; k < n; ++k) {
    const double t = start + k * step + r.uniform(-0.2, 0.2) * step;
    points.push_back(geometry::rotated({a * std::cos(t), b * std::sin(t)}, turn));
  }
  return points;
}

double drawSpeed(Range range, Random& r) {
  return std::max(0.05, roundTo(draw(r, range), 20.0));
}

double drawTurnRate(double lo, double hi, Random& r) {
  return drawSign(r) * roundTo(r.uniform(lo, hi), 20.0);
}

Ring targetShape(const SceneFamily& f, Random& r) {
  if (f.shapes == ShapeStyle::published) return pick(r, publishedTargetShapes());
  const int n = 3 + static_cast<int>(r.index(6));
  return starRing(starAngles(n, r), starRadii(n, draw(r, f.targetRadius), r));
}

Object drawTarget(const SceneFamily& f, TargetMotion motion, Random& r) {
  Object o;
  o.path = {{0, 0}};
  if (motion == TargetMotion::deform) {
    deformingStar(o, draw(r, f.targetRadius), r);
    if (r.uniform() < 0.5) o.path = shuttleOffsets(draw(r, f.pathLength) / 2, r);
  } else {
    o.shape = targetShape(f, r);
  }
  if (motion == TargetMotion::shuttle) o.path = shuttleOffsets(draw(r, f.pathLength), r);
  if (motion == TargetMotion::loop) o.path = loopOffsets(draw(r, f.pathLength), r);
  if (motion == TargetMotion::turn) o.angularVelocity = drawTurnRate(0.1, 0.6, r);
  o.velocity = drawSpeed(f.targetSpeed, r);
  return o;
}

// A block `length` long and a fifth to a half as wide, at any angle.
Ring block(double length, Random& r) {
  const double l = length / 2, w = std::max(0.15, l * r.uniform(0.2, 0.5));
  return rotatedRing({{-l, -w}, {l, -w}, {l, w}, {-l, w}}, r.uniform(0.0, std::numbers::pi));
}

Object drawObstacle(const SceneFamily& f, ObstacleMotion motion, Random& r) {
  const bool published = f.shapes == ShapeStyle::published;
  Object o;
  o.path = {{0, 0}};
  if (motion == ObstacleMotion::spin) {
    const double l = draw(r, f.obstacleLength) / 2;
    o.shape = published ? publishedSpinningBar()
                        : rounded({{-l, -0.25}, {l, -0.25}, {l, 0.25}, {-l, 0.25}});
    o.angularVelocity = drawTurnRate(0.1, 0.4, r);
  } else {
    o.shape = published ? pick(r, publishedObstacleShapes()) : block(draw(r, f.obstacleLength), r);
  }
  if (motion == ObstacleMotion::shuttle) o.path = shuttleOffsets(draw(r, f.pathLength), r);
  if (motion == ObstacleMotion::loop) o.path = loopOffsets(draw(r, f.pathLength), r);
  o.velocity = drawSpeed(f.obstacleSpeed, r);
  return o;
}

// A place for an object drawn afresh at every try, its region in the room and clear of every
// region taken; nothing after kTries tries.
std::optional<Object> place(const Room& room, std::vector<Region>& taken,
                            const std::function<Object(Random&)>& drawObject, Random& r) {
  for (int i = 0; i < kTries; ++i) {
    Object o = drawObject(r);
    const Vec2 c = drawPoint(room, r);
    for (Vec2& p : o.path)
      p = mm(c + p);
    Region region = regionOf(o);
    if (fitsRoom(room, region.hull, region.radius, kGap) && clearOf(taken, region, kGap)) {
      taken.push_back(std::move(region));
      return o;
    }
  }
  return std::nullopt;
}

Ring pillarShape(double radius, bool round) {
  Ring ring;
  const int n = round ? 8 : 4;
  for (int k = 0; k < n; ++k)
    ring.push_back(mm(geometry::unitVector(std::numbers::pi * (2 * k + 1) / n) * radius));
  return ring;
}

// --- cameras ---------------------------------------------------------------------------------

struct Camera {
  Vec2 position;
  double yawDeg = 0.0;
};

bool freeForCamera(const Room& room, const std::vector<Region>& regions,
                   const std::vector<Camera>& cameras, Vec2 p) {
  return fitsRoom(room, {p}, 0.0, kCameraGap) &&
         std::all_of(regions.begin(), regions.end(),
                     [&](const Region& g) { return distanceTo(g, p) >= kCameraGap; }) &&
         std::all_of(cameras.begin(), cameras.end(), [&](const Camera& c) {
           return geometry::distance(c.position, p) >= kCameraGap;
         });
}

// Directions (radians) from p that a region fills: the smallest arc holding the discs about
// its hull's points. p is outside the region, so the arc is under 180° and measured from any
// of its points without wrapping.
std::pair<double, double> arcOf(const Region& region, Vec2 p) {
  const double reference = std::atan2(region.hull[0].y - p.y, region.hull[0].x - p.x);
  double lo = 0.0, hi = 0.0;
  for (const Vec2 q : region.hull) {
    const double d = geometry::distance(p, q);
    const double offset = geometry::wrapAngle(std::atan2(q.y - p.y, q.x - p.x) - reference);
    const double half = std::asin(std::min(1.0, region.radius / d));
    lo = std::min(lo, offset - half);
    hi = std::max(hi, offset + half);
  }
  return {reference + lo, reference + hi};
}

// The widest arc of directions from p that meets no region: its middle and width, radians.
std::pair<double, double> widestFreeArc(const std::vector<Region>& regions, Vec2 p) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  std::vector<std::pair<double, double>> arcs;  // start in [0, 2π), length
  for (const Region& g : regions) {
    const auto [lo, hi] = arcOf(g, p);
    arcs.push_back({lo - kTwoPi * std::floor(lo / kTwoPi), hi - lo});
  }
  std::sort(arcs.begin(), arcs.end());
  double end = -kTwoPi;  // where the arcs end, wrapped back before the first one starts
  for (const auto& [start, length] : arcs)
    end = std::max(end, start + length - kTwoPi);
  double best = 0.0, middle = 0.0;
  for (const auto& [start, length] : arcs) {
    if (start - end > best) {
      best = start - end;
      middle = (start + end) / 2;
    }
    end = std::max(end, start + length);
  }
  return {middle, best};
}

double yawDegrees(double radians) {
  const double deg = geometry::radToDeg(radians);
  return roundTo(deg - 360.0 * std::floor(deg / 360.0), 100.0);
}

double randomYaw(Random& r) {
  return std::round(r.uniform(0.0, 36000.0)) / 100.0;
}

std::optional<Camera> spreadCamera(const Room& room, const std::vector<Region>& regions,
                                   const std::vector<Camera>& cameras, Random& r) {
  for (int i = 0; i < kTries; ++i) {
    const Vec2 p = drawPoint(room, r);
    if (freeForCamera(room, regions, cameras, p)) return Camera{p, randomYaw(r)};
  }
  return std::nullopt;
}

// A free place whose widest free arc holds the view and kAwayMargin on both sides, facing its
// middle: every region is outside the view, so nothing is in view at any time.
std::optional<Camera> awayCamera(const Room& room, const std::vector<Region>& regions,
                                 const std::vector<Camera>& cameras, double halfFovDeg, Random& r) {
  const double needed = geometry::degToRad(2 * (halfFovDeg + kAwayMargin));
  for (int i = 0; i < kTries; ++i) {
    const Vec2 p = drawPoint(room, r);
    if (!freeForCamera(room, regions, cameras, p)) continue;
    const auto [middle, width] = widestFreeArc(regions, p);
    if (width >= needed) return Camera{p, yawDegrees(middle)};
  }
  return std::nullopt;
}

// Of kFarCandidates free places, the one farthest from every object.
std::optional<Camera> farCamera(const Room& room, const std::vector<Region>& regions,
                                const std::vector<Camera>& cameras, Random& r) {
  std::optional<Camera> best;
  double bestDistance = -1.0;
  int found = 0;
  for (int i = 0; i < kTries && found < kFarCandidates; ++i) {
    const Vec2 p = drawPoint(room, r);
    if (!freeForCamera(room, regions, cameras, p)) continue;
    ++found;
    double nearest = std::numeric_limits<double>::infinity();
    for (const Region& g : regions)
      nearest = std::min(nearest, distanceTo(g, p));
    if (nearest > bestDistance) {
      bestDistance = nearest;
      best = Camera{p, 0.0};
    }
  }
  if (best) best->yawDeg = randomYaw(r);
  return best;
}

// --- the scene -------------------------------------------------------------------------------

struct Draw {
  Room room;
  std::vector<Object> pillars, targets, obstacles;
  std::vector<TargetMotion> targetMotions;
  std::vector<ObstacleMotion> obstacleMotions;
  std::vector<Camera> cameras;
  CameraStart start = spread;
  double cameraSpeed = 0.0, turnRate = 0.0, halfFovDeg = 0.0;
};

// v_max such that crossing the room's longer side takes at least the drawn time (drawn
// uniformly in its logarithm: as many fast teams as slow ones), floored to 0.01 m/s.
double cameraSpeed(const Room& room, Range crossingSeconds, Random& r) {
  const double seconds =
      std::exp(r.uniform(std::log(crossingSeconds.lo), std::log(crossingSeconds.hi)));
  return std::max(1.0, std::floor(room.width / seconds * 100.0)) / 100.0;
}

bool placePillars(Draw& d, std::vector<Region>& taken) {
  const bool round = d.room.pillarRadius > 0.5;
  for (const Vec2 c : d.room.pillars) {
    Object o;
    o.shape = pillarShape(d.room.pillarRadius, round);
    o.path = {c};
    Region region = regionOf(o);
    if (!fitsRoom(d.room, region.hull, 0.0, kGap) || !clearOf(taken, region, kGap)) return false;
    taken.push_back(std::move(region));
    d.pillars.push_back(std::move(o));
  }
  return true;
}

bool placeObjects(const SceneFamily& f, Draw& d, std::vector<Region>& taken, Random& r) {
  if (!placePillars(d, taken)) return false;
  const int targets = draw(r, f.targets), obstacles = draw(r, f.obstacles);
  for (int i = 0; i < targets; ++i) {
    const TargetMotion motion = pick(r, f.targetMotions);
    auto o = place(
        d.room, taken, [&](Random& rr) { return drawTarget(f, motion, rr); }, r);
    if (!o) return false;
    d.targets.push_back(std::move(*o));
    d.targetMotions.push_back(motion);
  }
  for (int i = 0; i < obstacles; ++i) {
    const ObstacleMotion motion = pick(r, f.obstacleMotions);
    auto o = place(
        d.room, taken, [&](Random& rr) { return drawObstacle(f, motion, rr); }, r);
    if (!o) return false;
    d.obstacles.push_back(std::move(*o));
    d.obstacleMotions.push_back(motion);
  }
  return true;
}

bool placeCameras(const SceneFamily& f, Draw& d, const std::vector<Region>& taken, Random& r) {
  const int cameras = draw(r, f.cameras);
  for (int j = 0; j < cameras; ++j) {
    std::optional<Camera> c;
    switch (d.start) {
      case spread:
        c = spreadCamera(d.room, taken, d.cameras, r);
        break;
      case facing_away:
        c = awayCamera(d.room, taken, d.cameras, d.halfFovDeg, r);
        break;
      case far:
        c = farCamera(d.room, taken, d.cameras, r);
        break;
    }
    if (!c) return false;
    d.cameras.push_back(*c);
  }
  return true;
}

std::optional<Draw> tryDraw(const SceneFamily& f, Random& r) {
  Draw d;
  d.room = makeRoom(f, r);
  d.start = pick(r, f.starts);
  d.cameraSpeed = cameraSpeed(d.room, f.crossingSeconds, r);
  d.turnRate = std::max(0.1, roundTo(draw(r, f.cameraTurnRate), 10.0));
  d.halfFovDeg = std::round(draw(r, f.halfFovDeg));
  std::vector<Region> taken;
  if (!placeObjects(f, d, taken, r) || !placeCameras(f, d, taken, r)) return std::nullopt;
  return d;
}

// "3 targets (1 static, 2 loop)": the kinds drawn, in the family's order, with their counts.
template <class Kind>
std::string countsText(const std::vector<Kind>& drawn, const std::vector<Kind>& kinds,
                       std::string_view noun) {
  if (drawn.empty()) return fmt::format("no {}s", noun);
  std::string counts;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    const auto n = std::count(drawn.begin(), drawn.end(), kinds[i]);
    if (n > 0 && firstOfItsKind(kinds, i))
      counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", n, nameOf(kinds[i]));
  }
  return fmt::format("{} {}{} ({})", drawn.size(), noun, drawn.size() == 1 ? "" : "s", counts);
}

std::string describe(const SceneFamily& f, std::uint64_t seed, const Draw& d) {
  static constexpr std::array kStarts{"spread out", "facing away from every object",
                                      "far from every object"};
  return fmt::format(
      "{}{}{}{}: {}, {}, {}, {} camera{} at {} m/s ({:.0f} s to cross) turning {} "
      "rad/s, half FoV {}°, starting {}",
      kFamilyLead, f.name, kSeedLead, seed, roomText(d.room),
      countsText(d.targetMotions, f.targetMotions, "target"),
      countsText(d.obstacleMotions, f.obstacleMotions, "obstacle"), d.cameras.size(),
      d.cameras.size() == 1 ? "" : "s", d.cameraSpeed, d.room.width / d.cameraSpeed, d.turnRate,
      d.halfFovDeg, kStarts.at(static_cast<std::size_t>(d.start)));
}

MovingObject movingObject(const Object& o) {
  MovingObject m;
  m.shape = o.shape;
  m.path = o.path;
  m.velocity = o.velocity;
  m.angularVelocity = o.angularVelocity;
  if (!o.keyframeShapes.empty()) {
    Deformation d{o.period, {}};
    for (std::size_t k = 0; k < o.keyframeShapes.size(); ++k)
      d.keyframes.push_back({o.keyframeTimes[k], o.keyframeShapes[k]});
    m.deformation = std::move(d);
  }
  return m;
}

nlohmann::json familySceneJson(const SceneFamily& f, std::uint64_t seed, const Draw& d) {
  WrittenScene scene;
  scene.description = describe(f, seed, d);
  scene.family = f.name;
  scene.boundary = d.room.boundary;
  scene.halfFovDegrees = d.halfFovDeg;
  for (const Object& o : d.targets)
    scene.targets.push_back(movingObject(o));
  for (const std::vector<Object>* group : {&d.pillars, &d.obstacles}) {
    for (const Object& o : *group)
      scene.obstacles.push_back(movingObject(o));
  }
  for (const Camera& c : d.cameras)
    scene.cameras.push_back(cameraEntry(c.position, c.yawDeg, d.cameraSpeed, d.turnRate));
  return sceneJson(scene);
}

}  // namespace

nlohmann::json generateFamilyScene(const SceneFamily& f, std::uint64_t seed) {
  // The family's name in the seed: seed 7 of two families are unrelated scenes.
  Random root(fnv1a(f.name) ^ (seed * 0x9e3779b97f4a7c15ull));
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    Random r(root.fork());
    if (const std::optional<Draw> d = tryDraw(f, r)) return familySceneJson(f, seed, *d);
  }
  throw std::runtime_error(
      fmt::format("family {} seed {}: no scene after {} attempts", f.name, seed, kAttempts));
}

}  // namespace camcov::scene
