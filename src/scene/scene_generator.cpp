#include "scene/scene_generator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "scene/scene_validation.h"
#include "scene/scene_writer.h"
#include "util/input_error.h"
#include "util/random.h"

namespace camcov::scene {
namespace {

using geometry::Vec2;

constexpr int kMaxTargets = 10000;
constexpr int kMaxVertices = 100000;
constexpr int kPlacementTries = 1000;  // placements tried per target and per camera
constexpr double kMinEdge = 1e-5;      // m: ten times the shapes' rounding, so rounding cannot
                                       // fold an edge over its neighbours
// A rounded loop corner lies at most √2 · 0.5 mm farther from its (rounded) centre than the
// exact one: the regions allow for it.
constexpr double kLoopRounding = 1e-3;

double um(double v) {
  return std::round(v * 1e6) / 1e6;
}

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

bool positiveLength(double v) {
  return std::isfinite(v) && v > 0.0 && v <= kMaxCoordinate;
}
bool positiveSpeed(double v) {
  return std::isfinite(v) && v > 0.0 && v <= kMaxSpeed;
}

void validate(const GeneratorOptions& o) {
  require(o.targets >= 1 && o.targets <= kMaxTargets,
          fmt::format("{} targets: a scene has 1 to {}", o.targets, kMaxTargets));
  require(o.cameras >= 1 && o.cameras <= static_cast<int>(kMaxCameras),
          fmt::format("{} cameras: a scene has 1 to {}", o.cameras, kMaxCameras));
  require(
      o.vertices >= 3 && o.vertices <= kMaxVertices,
      fmt::format("{} vertices per target: a polygon has 3 to {} here", o.vertices, kMaxVertices));
  require(positiveLength(o.fieldWidth) && positiveLength(o.fieldHeight),
          fmt::format("field {} x {} m: both sides must be positive, at most {} m", o.fieldWidth,
                      o.fieldHeight, kMaxCoordinate));
  require(positiveLength(o.targetLength) && positiveLength(o.targetWidth),
          fmt::format("target size {} x {} m: both sides must be positive", o.targetLength,
                      o.targetWidth));
  require(std::isfinite(o.loopSize) && o.loopSize >= 0.0 && o.loopSize <= kMaxCoordinate,
          fmt::format("loop size {} m: must be 0 (static targets) or positive", o.loopSize));
  require(
      positiveSpeed(o.targetSpeed),
      fmt::format("target speed {} m/s: must be positive, at most {}", o.targetSpeed, kMaxSpeed));
  require(positiveSpeed(o.cameraSpeed) && positiveSpeed(o.cameraTurnRate),
          fmt::format("camera speed {} m/s, turn rate {} rad/s: both must be positive, at most {}",
                      o.cameraSpeed, o.cameraTurnRate, kMaxSpeed));
  require(
      std::isfinite(o.cameraHalfFovDeg) && o.cameraHalfFovDeg > 0.0 && o.cameraHalfFovDeg < 180.0,
      fmt::format("field of view θ = {}°: the half-angle must be in (0, 180)", o.cameraHalfFovDeg));
  require(std::isfinite(o.clearance) && o.clearance >= 0.0 && o.clearance <= kMaxCoordinate,
          fmt::format("clearance {} m: must be 0 or positive", o.clearance));
}

// V points on the unit circle from π/V on, mapped so their bounding box is length x width
// about the origin: an affine image of a regular polygon, so inscribed in an ellipse, and for
// V = 4 the axis-aligned rectangle itself.
geometry::Ring targetShape(const GeneratorOptions& o) {
  geometry::Ring unit;
  for (int k = 0; k < o.vertices; ++k)
    unit.push_back(geometry::unitVector(std::numbers::pi * (2 * k + 1) / o.vertices));
  const geometry::Box box = geometry::boundingBox(unit);
  const Vec2 centre = (box.min + box.max) * 0.5;
  geometry::Ring shape;
  for (const Vec2 p : unit) {
    shape.push_back({um((p.x - centre.x) / (box.max.x - box.min.x) * o.targetLength),
                     um((p.y - centre.y) / (box.max.y - box.min.y) * o.targetWidth)});
  }
  for (std::size_t i = 0; i < shape.size(); ++i) {
    require(geometry::distance(shape[i], shape[(i + 1) % shape.size()]) >= kMinEdge,
            fmt::format("{} vertices on a {} x {} m target make edges shorter than {} µm (shapes "
                        "are kept to the µm): use fewer vertices or a larger target",
                        o.vertices, o.targetLength, o.targetWidth, kMinEdge * 1e6));
  }
  return shape;
}

// The target regions' centres binned in square cells at least as wide as any distance asked
// about, so a query looks at 3 x 3 cells instead of every target.
class CentreGrid {
 public:
  CentreGrid(double width, double height, double reach)
      : x0_(-width / 2),
        y0_(-height / 2),
        cell_(std::max({reach, width / kCells, height / kCells})),
        columns_(cellsAlong(width)),
        rows_(cellsAlong(height)),
        cells_(static_cast<std::size_t>(columns_) * rows_) {}

  void add(Vec2 p) { cells_[index(column(p), row(p))].push_back(p); }
  // Is any centre closer to p than `d` (at most the reach the grid was made for)?
  bool anyCloser(Vec2 p, double d) const {
    const int c = column(p), r = row(p);
    for (int i = std::max(0, c - 1); i <= std::min(columns_ - 1, c + 1); ++i) {
      for (int j = std::max(0, r - 1); j <= std::min(rows_ - 1, r + 1); ++j) {
        for (const Vec2 q : cells_[index(i, j)]) {
          if (geometry::distance(p, q) < d) return true;
        }
      }
    }
    return false;
  }

 private:
  static constexpr double kCells = 256.0;  // per side at most: memory stays small
  double x0_, y0_, cell_;
  int columns_, rows_;
  std::vector<std::vector<Vec2>> cells_;

  int cellsAlong(double length) const {
    return std::max(1, static_cast<int>(std::ceil(length / cell_)));
  }
  int column(Vec2 p) const {
    return std::clamp(static_cast<int>((p.x - x0_) / cell_), 0, columns_ - 1);
  }
  int row(Vec2 p) const { return std::clamp(static_cast<int>((p.y - y0_) / cell_), 0, rows_ - 1); }
  std::size_t index(int column, int row) const {
    return static_cast<std::size_t>(row) * columns_ + column;
  }
};

bool within(Vec2 p, double halfWidth, double halfHeight) {
  return std::abs(p.x) <= halfWidth && std::abs(p.y) <= halfHeight;
}

std::string defaultDescription(const GeneratorOptions& o) {
  const std::string motion =
      o.loopSize > 0.0
          ? fmt::format("each on its own {} m square loop at {} m/s", o.loopSize, o.targetSpeed)
          : std::string("static");
  return fmt::format(
      "Generated (seed {}): {} targets of {} x {} m with {} vertices, {}, "
      "and {} cameras in a {} x {} m field.",
      o.seed, o.targets, o.targetLength, o.targetWidth, o.vertices, motion, o.cameras, o.fieldWidth,
      o.fieldHeight);
}

}  // namespace

nlohmann::json generateScene(const GeneratorOptions& o) {
  validate(o);
  const geometry::Ring shape = targetShape(o);
  double shapeReach = 0.0;
  for (const Vec2 p : shape)
    shapeReach = std::max(shapeReach, geometry::norm(p));
  const double half = o.loopSize / 2;
  const double radius =
      (o.loopSize > 0.0 ? half * std::numbers::sqrt2 + kLoopRounding : 0.0) + shapeReach;
  const double hw = o.fieldWidth / 2, hh = o.fieldHeight / 2;
  // Where a region's centre may go: the whole region `clearance` inside the field.
  const double cx = hw - radius - o.clearance, cy = hh - radius - o.clearance;
  require(cx >= 0.0 && cy >= 0.0,
          fmt::format("field {} x {} m: too small for one target's region (radius {:.3f} m: its "
                      "loop and shape) with {} m clearance",
                      o.fieldWidth, o.fieldHeight, radius, o.clearance));

  Random root(o.seed);
  Random targetRandom(root.fork());
  Random cameraRandom(root.fork());

  WrittenScene scene;
  scene.description = o.description.empty() ? defaultDescription(o) : o.description;
  scene.boundary = {{-mm(hw), -mm(hh)}, {mm(hw), -mm(hh)}, {mm(hw), mm(hh)}, {-mm(hw), mm(hh)}};
  scene.halfFovDegrees = o.cameraHalfFovDeg;

  CentreGrid centres(o.fieldWidth, o.fieldHeight, 2 * radius + o.clearance);
  for (int i = 0; i < o.targets; ++i) {
    Vec2 c;
    int tries = 0;
    do {
      require(++tries <= kPlacementTries,
              fmt::format("field {} x {} m too crowded: no room for target {} of {} (its region "
                          "has radius {:.3f} m) after {} tries; use a larger field or fewer, "
                          "smaller targets or loops",
                          o.fieldWidth, o.fieldHeight, i + 1, o.targets, radius, kPlacementTries));
      c = {mm(targetRandom.uniform(-cx, cx)), mm(targetRandom.uniform(-cy, cy))};
    } while (!within(c, cx, cy) || centres.anyCloser(c, 2 * radius));
    centres.add(c);
    MovingObject target;
    target.shape = shape;
    if (o.loopSize > 0.0) {
      const double angle = targetRandom.uniform(0.0, 2 * std::numbers::pi);
      std::vector<Vec2> loop;
      for (const Vec2 corner :
           {Vec2{-half, -half}, Vec2{half, -half}, Vec2{half, half}, Vec2{-half, half}}) {
        const Vec2 p = c + geometry::rotated(corner, angle);
        loop.push_back({mm(p.x), mm(p.y)});
      }
      target.path = std::move(loop);
      target.velocity = o.targetSpeed;
    } else {
      target.path = {c};
    }
    scene.targets.push_back(std::move(target));
  }

  std::vector<Vec2> cameras;
  const double px = hw - o.clearance, py = hh - o.clearance;
  const auto taken = [&](Vec2 q) {
    return !within(q, px, py) || centres.anyCloser(q, radius + o.clearance) ||
           std::any_of(cameras.begin(), cameras.end(),
                       [&](Vec2 other) { return geometry::distance(q, other) < o.clearance; });
  };
  for (int j = 0; j < o.cameras; ++j) {
    Vec2 p;
    int tries = 0;
    do {
      require(
          ++tries <= kPlacementTries,
          fmt::format("field {} x {} m too crowded: no place for camera {} of {} at least {} "
                      "m from every target's region, the boundary and the other cameras "
                      "after {} tries; use a larger field, fewer targets or a smaller "
                      "clearance",
                      o.fieldWidth, o.fieldHeight, j + 1, o.cameras, o.clearance, kPlacementTries));
      p = {mm(cameraRandom.uniform(-px, px)), mm(cameraRandom.uniform(-py, py))};
    } while (taken(p));
    cameras.push_back(p);
    scene.cameras.push_back(cameraEntry(p, std::round(cameraRandom.uniform(0.0, 36000.0)) / 100.0,
                                        o.cameraSpeed, o.cameraTurnRate));
  }
  return sceneJson(scene);
}

}  // namespace camcov::scene
