// Named scene families (scene/scene_families.h): every family's scenes load, are seeded to the
// byte and say what they are, and keep the promises the loader does not check, looked at from
// outside the generator: the loaded scene moved through kinematics as a run would move it,
// every object inside the boundary with 0.5 m to spare and never meeting another, cameras
// clear of everything, every target reachable by a camera that keeps 0.5 m from everything,
// and cameras that start facing away seeing nothing.
#include "scene/scene_families.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/ring.h"
#include "kinematics/kinematics.h"
#include "scene/scene_error.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace camcov::scene {
namespace {

using geometry::Vec2;

constexpr int kScenesPerFamily = 50;
constexpr int kSampledPerFamily = 8;  // scenes moved through time, per family

std::string text(const SceneFamily& f, std::uint64_t seed) {
  return generateFamilyScene(f, seed).dump(1) + "\n";
}

Scene load(const SceneFamily& f, std::uint64_t seed) {
  return parseScene(text(f, seed), familySceneFileName(f.name, seed));
}

// Every object of the scene, targets then obstacles.
std::vector<const MovingObject*> objectsOf(const Scene& s) {
  std::vector<const MovingObject*> all;
  for (const auto& t : s.targets)
    all.push_back(&t);
  for (const auto& o : s.obstacles)
    all.push_back(&o);
  return all;
}

// The longest time after which some object's motion repeats: a lap of its path, its
// deformation's period, a turn.
double longestPeriod(const Scene& s) {
  double period = 1.0;
  for (const MovingObject* o : objectsOf(s)) {
    if (o->path.size() > 1) period = std::max(period, geometry::perimeter(o->path) / o->velocity);
    if (o->deformation) period = std::max(period, o->deformation->period);
    if (o->angularVelocity != 0.0)
      period = std::max(period, 2 * std::numbers::pi / std::abs(o->angularVelocity));
  }
  return period;
}

// 400 instants over two of the longest periods, none of them a round number.
std::vector<double> sampleTimes(const Scene& s) {
  const double span = 2 * longestPeriod(s);
  std::vector<double> times{0.0};
  for (int i = 0; i < 400; ++i)
    times.push_back(span * (i + 0.618) / 400);
  return times;
}

std::vector<geometry::Ring> polygonsAt(const kinematics::World& w) {
  std::vector<geometry::Ring> all = w.targets;
  all.insert(all.end(), w.obstacles.begin(), w.obstacles.end());
  return all;
}

// Does the polygon meet the view cone of half-angle θ at p facing yaw? A vertex inside the
// cone, an edge across one of its sides, or p inside the polygon.
bool inView(const geometry::Ring& polygon, const geometry::Pose& pose, double halfFov) {
  const Vec2 p = pose.position();
  for (const Vec2 v : polygon) {
    const double off = geometry::wrapAngle(std::atan2(v.y - p.y, v.x - p.x) - pose.yaw);
    if (std::abs(off) <= halfFov) return true;
  }
  for (const double side : {-halfFov, halfFov}) {
    const Vec2 far = p + geometry::unitVector(pose.yaw + side) * 1e4;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      if (geometry::segmentsIntersect(p, far, polygon[i], polygon[(i + 1) % polygon.size()]))
        return true;
    }
  }
  return geometry::locate(polygon, p) != geometry::Containment::Outside;
}

TEST(SceneFamilies, EveryFamilyMakesScenesThatLoadWithinItsRanges) {
  for (const SceneFamily& f : sceneFamilies()) {
    for (std::uint64_t seed = f.seeds.tune.first; seed < f.seeds.tune.first + kScenesPerFamily;
         ++seed) {
      SCOPED_TRACE(familySceneFileName(f.name, seed));
      Scene s;
      ASSERT_NO_THROW(s = load(f, seed));
      EXPECT_GE(static_cast<int>(s.targets.size()), f.targets.lo);
      EXPECT_LE(static_cast<int>(s.targets.size()), f.targets.hi);
      EXPECT_GE(static_cast<int>(s.cameras.size()), f.cameras.lo);
      EXPECT_LE(static_cast<int>(s.cameras.size()), f.cameras.hi);
      EXPECT_GE(static_cast<int>(s.obstacles.size()), f.obstacles.lo);  // pillars come on top
      const geometry::Box room = geometry::boundingBox(s.boundary);
      const double span = std::max(room.max.x - room.min.x, room.max.y - room.min.y);
      EXPECT_GE(span, f.roomLength.lo - 0.25);
      EXPECT_LE(span, f.roomLength.hi + 0.25);
      for (const CameraSpec& c : s.cameras) {
        const double fov = geometry::radToDeg(c.lens.halfFov);
        EXPECT_GE(fov, f.halfFovDeg.lo - 1e-9);
        EXPECT_LE(fov, f.halfFovDeg.hi + 1e-9);
        EXPECT_GE(span / c.maxVelocity, f.crossingSeconds.lo);         // floored: never faster
        EXPECT_LE(span / c.maxVelocity, 1.15 * f.crossingSeconds.hi);  // by 0.01 m/s at most
        EXPECT_EQ(c.maxVelocity, s.cameras[0].maxVelocity);
      }
    }
  }
}

TEST(SceneFamilies, TheSameSeedGivesTheSameBytesAndAnotherSeedAnotherScene) {
  std::set<std::string> seen;
  for (const SceneFamily& f : sceneFamilies()) {
    SCOPED_TRACE(f.name);
    const std::string first = text(f, 7);
    EXPECT_EQ(text(f, 7), first);
    EXPECT_NE(text(f, 8), first);
    EXPECT_TRUE(seen.insert(first).second) << "seed 7 of another family gave the same scene";
    // Far beyond the table's seeds too.
    EXPECT_EQ(text(f, 18446744073709551615ull), text(f, 18446744073709551615ull));
  }
}

TEST(SceneFamilies, TheDescriptionNamesTheFamilyTheSeedAndWhatWasDrawn) {
  for (const SceneFamily& f : sceneFamilies()) {
    for (const std::uint64_t seed : {1ull, 100001ull}) {
      const Scene s = load(f, seed);
      const std::string prefix =
          "family " + std::string(f.name) + " seed " + std::to_string(seed) + ": ";
      EXPECT_EQ(s.description.rfind(prefix, 0), 0u) << s.description;
      EXPECT_NE(s.description.find(std::to_string(s.targets.size()) + " target"), std::string::npos)
          << s.description;
      EXPECT_NE(s.description.find("half FoV"), std::string::npos) << s.description;
    }
  }
}

TEST(SceneFamilies, AGeneratedSceneCarriesItsFamilyAndALoaderRefusesAnUnknownOne) {
  for (const SceneFamily& f : sceneFamilies()) {
    EXPECT_EQ(load(f, 7).family, f.name);
    EXPECT_TRUE(isSceneFamily(f.name));
  }
  nlohmann::json file = generateFamilyScene(sceneFamily("l_rooms"), 1);
  file["family"] = "nosuch";
  try {
    parseScene(file.dump(), "renamed.json");
    ADD_FAILURE() << "an unknown family was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("family"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("l_rooms"), std::string::npos) << "names the known ones";
  }
  // The description is for people: a scene that only says "family l_rooms" in it has none.
  file.erase("family");
  EXPECT_EQ(parseScene(file.dump(), "plain.json").family, "");
  for (const char* other : {"", "family", "L_rooms", "l_rooms "})
    EXPECT_FALSE(isSceneFamily(other)) << '"' << other << '"';
}

TEST(SceneFamilies, TuneAndTestSeedsAreDisjointForEveryFamily) {
  std::set<std::string_view> names;
  for (const SceneFamily& f : sceneFamilies()) {
    SCOPED_TRACE(f.name);
    EXPECT_TRUE(names.insert(f.name).second) << "two families of one name";
    const SeedSplit split = familySeeds(f.name);
    EXPECT_LE(split.tune.first, split.tune.last);
    EXPECT_LE(split.test.first, split.test.last);
    EXPECT_TRUE(split.tune.last < split.test.first || split.test.last < split.tune.first);
    EXPECT_FALSE(split.tune.contains(split.test.first));
    EXPECT_EQ(split.tune.first, f.seeds.tune.first);
    EXPECT_EQ(split.test.last, f.seeds.test.last);
  }
}

// What the families must stress between them: every room shape, motion and start, teams of 1
// to 8, views of 20° to 60°, cameras that need a minute to cross the room.
TEST(SceneFamilies, TheTableCoversEveryKindAndItsRangesAreSane) {
  std::set<RoomKind> rooms;
  std::set<TargetMotion> motions;
  std::set<ObstacleMotion> obstacles;
  std::set<CameraStart> starts;
  int fewestCameras = 64, mostCameras = 0;
  double narrowest = 180, widest = 0, slowest = 0;
  for (const SceneFamily& f : sceneFamilies()) {
    SCOPED_TRACE(f.name);
    for (const Range r :
         {f.roomLength, f.roomAspect, f.targetRadius, f.targetSpeed, f.pathLength, f.obstacleLength,
          f.obstacleSpeed, f.crossingSeconds, f.cameraTurnRate, f.halfFovDeg}) {
      EXPECT_GT(r.lo, 0.0);
      EXPECT_LE(r.lo, r.hi);
    }
    EXPECT_GE(f.targets.lo, 1);
    EXPECT_LE(f.targets.lo, f.targets.hi);
    EXPECT_LE(f.obstacles.lo, f.obstacles.hi);
    EXPECT_GE(f.cameras.lo, 1);
    EXPECT_LE(f.cameras.hi, 64);
    EXPECT_FALSE(f.rooms.empty() || f.targetMotions.empty() || f.obstacleMotions.empty() ||
                 f.starts.empty());
    if (std::count(f.rooms.begin(), f.rooms.end(), RoomKind::pillared_hall) > 0) {
      EXPECT_GE(f.roomLength.lo * f.roomAspect.lo, 12.0) << "a grid of 2 x 2 cells 6 m wide";
    }
    EXPECT_GE(f.halfFovDeg.lo, 20.0);
    EXPECT_LE(f.halfFovDeg.hi, 60.0);
    rooms.insert(f.rooms.begin(), f.rooms.end());
    motions.insert(f.targetMotions.begin(), f.targetMotions.end());
    if (f.obstacles.hi > 0) obstacles.insert(f.obstacleMotions.begin(), f.obstacleMotions.end());
    starts.insert(f.starts.begin(), f.starts.end());
    fewestCameras = std::min(fewestCameras, f.cameras.lo);
    mostCameras = std::max(mostCameras, f.cameras.hi);
    narrowest = std::min(narrowest, f.halfFovDeg.lo);
    widest = std::max(widest, f.halfFovDeg.hi);
    slowest = std::max(slowest, f.crossingSeconds.lo);
  }
  EXPECT_EQ(rooms.size(), 12u);
  EXPECT_EQ(motions.size(), 5u);
  EXPECT_EQ(obstacles.size(), 4u);
  EXPECT_EQ(starts.size(), 3u);
  EXPECT_EQ(fewestCameras, 1);
  EXPECT_EQ(mostCameras, 8);
  EXPECT_EQ(narrowest, 20.0);
  EXPECT_EQ(widest, 60.0);
  EXPECT_GE(slowest, 60.0);
}

TEST(SceneFamilies, AnUnknownFamilyIsAnInputErrorNamingTheKnownOnes) {
  try {
    sceneFamily("l_room");
    FAIL() << "no error";
  } catch (const InputError& e) {
    for (const SceneFamily& f : sceneFamilies())
      EXPECT_NE(std::string(e.what()).find(f.name), std::string::npos) << e.what();
  }
  EXPECT_THROW(familySeeds("nope"), InputError);
}

TEST(SceneFamilies, TheDocsShowTheTableAsTheToolPrintsIt) {
  std::ifstream in(std::filesystem::path(CAMCOV_SOURCE_DIR) / "docs" / "families.md");
  std::stringstream docs;
  docs << in.rdbuf();
  EXPECT_NE(docs.str().find(familyTable()), std::string::npos)
      << "docs/families.md should hold `camcov generate --family list` verbatim:\n"
      << familyTable();
}

// Every object inside the boundary, at least 0.5 m from it (edges included: an edge could
// pass a reflex corner between two vertices that stay clear), objects at least 1 m apart,
// every camera's start 1 m from every object, at 400 instants over two of the longest periods.
TEST(SceneFamilies, ObjectsStayInsideAndApartAndCamerasClearAtEverySampledInstant) {
  for (const SceneFamily& f : sceneFamilies()) {
    for (std::uint64_t seed = 1; seed <= kSampledPerFamily; ++seed) {
      SCOPED_TRACE(familySceneFileName(f.name, seed));
      const Scene s = load(f, seed);
      const kinematics::Kinematics k(s);
      for (const CameraSpec& c : s.cameras) {
        ASSERT_EQ(geometry::locate(s.boundary, c.initial.position()),
                  geometry::Containment::Inside);
        ASSERT_GE(geometry::distanceToBoundary(s.boundary, c.initial.position()), 1.0 - 1e-9);
      }
      kinematics::World w;
      for (const double t : sampleTimes(s)) {
        k.worldAt(t, w);
        const std::vector<geometry::Ring> polygons = polygonsAt(w);
        for (std::size_t i = 0; i < polygons.size(); ++i) {
          const geometry::Ring& poly = polygons[i];
          for (std::size_t v = 0; v < poly.size(); ++v) {
            ASSERT_EQ(geometry::locate(s.boundary, poly[v]), geometry::Containment::Inside)
                << "object " << i << " at t = " << t;
            ASSERT_GE(geometry::distanceSegmentToBoundary(s.boundary, poly[v],
                                                          poly[(v + 1) % poly.size()]),
                      0.5)
                << "object " << i << " at t = " << t;
          }
          for (std::size_t j = i + 1; j < polygons.size(); ++j) {
            ASSERT_GE(geometry::distanceBetweenPolygons(poly, polygons[j]), 1.0)
                << "objects " << i << " and " << j << " at t = " << t;
          }
          for (const CameraSpec& c : s.cameras)
            ASSERT_GE(geometry::distanceToPolygon(poly, c.initial.position()), 1.0 - 1e-9);
        }
      }
    }
  }
}

TEST(SceneFamilies, CamerasThatStartFacingAwaySeeNoObjectAtAnySampledInstant) {
  int scenes = 0;
  for (const SceneFamily& f : sceneFamilies()) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const Scene s = load(f, seed);
      if (s.description.find("facing away") == std::string::npos) continue;
      SCOPED_TRACE(familySceneFileName(f.name, seed));
      ++scenes;
      const kinematics::Kinematics k(s);
      kinematics::World w;
      for (const double t : sampleTimes(s)) {
        k.worldAt(t, w);
        for (const geometry::Ring& poly : polygonsAt(w)) {
          for (const CameraSpec& c : s.cameras)
            ASSERT_FALSE(inView(poly, c.initial, c.lens.halfFov)) << "t = " << t;
        }
      }
    }
  }
  EXPECT_GT(scenes, 10);
}

// A grid of 0.2 m over the room; a cell is free when its centre is 0.5 m inside the boundary
// and 0.5 m from every object that never leaves its place (a turning or deforming one: from
// the disc it sweeps). Moving objects are left out: they pass.
class FreeGrid {
 public:
  explicit FreeGrid(const Scene& s) : box_(geometry::boundingBox(s.boundary)) {
    columns_ = static_cast<int>((box_.max.x - box_.min.x) / kCell) + 1;
    rows_ = static_cast<int>((box_.max.y - box_.min.y) / kCell) + 1;
    free_.assign(static_cast<std::size_t>(columns_) * rows_, false);
    std::vector<std::pair<geometry::Ring, double>> blocks;  // polygon, and a disc radius
    for (const MovingObject* o : objectsOf(s)) {
      if (o->path.size() > 1) continue;
      if (o->isStatic()) {
        blocks.push_back({initialPolygon(*o), 0.0});
      } else {
        double reach = 0.0;
        for (const Vec2 v : o->shape)
          reach = std::max(reach, geometry::norm(v));
        if (o->deformation) {
          for (const auto& key : o->deformation->keyframes) {
            for (const Vec2 v : key.shape)
              reach = std::max(reach, geometry::norm(v));
          }
        }
        blocks.push_back({{o->path[0]}, reach});
      }
    }
    for (int i = 0; i < columns_; ++i) {
      for (int j = 0; j < rows_; ++j) {
        const Vec2 p = centre(i, j);
        bool ok = geometry::locate(s.boundary, p) == geometry::Containment::Inside &&
                  geometry::distanceToBoundary(s.boundary, p) >= kClearance;
        for (const auto& [poly, reach] : blocks) {
          if (ok) ok = geometry::distanceToPolygon(poly, p) - reach >= kClearance;
        }
        free_[index(i, j)] = ok;
      }
    }
  }

  // The free cells reached from the free cell nearest p (8-neighbours).
  std::vector<bool> reachedFrom(Vec2 p) const {
    std::vector<bool> reached(free_.size(), false);
    std::vector<std::pair<int, int>> todo;
    const auto [i0, j0] = cellOf(p);
    if (!free_[index(i0, j0)]) return reached;
    reached[index(i0, j0)] = true;
    todo.push_back({i0, j0});
    while (!todo.empty()) {
      const auto [i, j] = todo.back();
      todo.pop_back();
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const int a = i + di, b = j + dj;
          if (a < 0 || b < 0 || a >= columns_ || b >= rows_) continue;
          if (!free_[index(a, b)] || reached[index(a, b)]) continue;
          reached[index(a, b)] = true;
          todo.push_back({a, b});
        }
      }
    }
    return reached;
  }

  bool free(Vec2 p) const {
    const auto [i, j] = cellOf(p);
    return free_[index(i, j)];
  }
  // Is a reached cell within `d` of the polygon?
  bool reachesNear(const std::vector<bool>& reached, const geometry::Ring& poly, double d) const {
    for (int i = 0; i < columns_; ++i) {
      for (int j = 0; j < rows_; ++j) {
        if (reached[index(i, j)] && geometry::distanceToPolygon(poly, centre(i, j)) <= d)
          return true;
      }
    }
    return false;
  }
  std::pair<int, int> cellOf(Vec2 p) const {
    return {std::clamp(static_cast<int>(std::round((p.x - box_.min.x) / kCell)), 0, columns_ - 1),
            std::clamp(static_cast<int>(std::round((p.y - box_.min.y) / kCell)), 0, rows_ - 1)};
  }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * columns_ + i; }

 private:
  static constexpr double kCell = 0.2;
  static constexpr double kClearance = 0.5;
  Vec2 centre(int i, int j) const { return {box_.min.x + i * kCell, box_.min.y + j * kCell}; }

  geometry::Box box_;
  int columns_ = 0, rows_ = 0;
  std::vector<bool> free_;
};

TEST(SceneFamilies, EveryCameraCanReachEveryOtherCameraAndEveryTarget) {
  for (const SceneFamily& f : sceneFamilies()) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      SCOPED_TRACE(familySceneFileName(f.name, seed));
      const Scene s = load(f, seed);
      const FreeGrid grid(s);
      const Vec2 first = s.cameras[0].initial.position();
      ASSERT_TRUE(grid.free(first));
      const std::vector<bool> reached = grid.reachedFrom(first);
      for (const CameraSpec& c : s.cameras) {
        const auto [i, j] = grid.cellOf(c.initial.position());
        EXPECT_TRUE(reached[grid.index(i, j)]) << "a camera cannot reach another";
      }
      for (const MovingObject& t : s.targets)
        EXPECT_TRUE(grid.reachesNear(reached, initialPolygon(t), 2.0)) << "a target is cut off";
    }
  }
}

}  // namespace
}  // namespace camcov::scene
