#include "control/observation_encoding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "control/team_belief.h"
#include "geometry/ring.h"
#include "kinematics/world.h"
#include "scene/camera_keys.h"

namespace camcov::control {
namespace {

std::size_t largestRing(const std::vector<scene::MovingObject>& objects) {
  std::size_t n = 0;
  for (const scene::MovingObject& object : objects) {
    n = std::max(n, object.shape.size());
    if (object.deformation) {
      for (const auto& keyframe : object.deformation->keyframes)
        n = std::max(n, keyframe.shape.size());
    }
  }
  return n;
}

float bounded(double value, float low, float high) {
  return std::clamp(static_cast<float>(value), low, high);
}

// The room's frame: (p − c) / L, clamped to the fields' bounds.
struct RoomFrame {
  explicit RoomFrame(const geometry::Ring& boundary) {
    const geometry::Box box = geometry::boundingBox(boundary);
    centre = (box.min + box.max) * 0.5;
    halfSide = 0.5 * std::max(box.max.x - box.min.x, box.max.y - box.min.y);
  }
  geometry::Vec2 centre;
  double halfSide = 1.0;
  float x(geometry::Vec2 p) const { return position((p.x - centre.x) / halfSide); }
  float y(geometry::Vec2 p) const { return position((p.y - centre.y) / halfSide); }
  float length(double metres) const { return bounded(metres / halfSide, 0.0f, kLengthBound); }

 private:
  static float position(double v) { return bounded(v, -kPositionBound, kPositionBound); }
};

// An observed camera table row's bounds: lengths over L, yaw rates bounded, half-angles as
// they are. None for a quantity the encoding has no scale for (pixels).
struct ObservedBounds {
  float low, high;
};
constexpr std::optional<ObservedBounds> observedBounds(scene::CameraQuantity quantity) {
  switch (quantity) {
    case scene::CameraQuantity::length:
      return ObservedBounds{0.0f, kLengthBound};
    case scene::CameraQuantity::rate:
      return ObservedBounds{0.0f, kRateBound};
    case scene::CameraQuantity::angle:
      return ObservedBounds{0.0f, std::numbers::pi_v<float>};
    case scene::CameraQuantity::pixels:
      break;
  }
  return std::nullopt;
}
consteval bool everyObservedKeyHasBounds() {
  for (const scene::CameraKey& row : scene::kCameraKeys)
    if (row.observed && !observedBounds(row.quantity)) return false;
  return true;
}
static_assert(everyObservedKeyHasBounds(), "an observed camera key needs a scale here");

// The value of an observed row for `camera` in the room's frame; 0 for a property the camera
// does not carry (an unlimited range).
float observedValue(const scene::CameraKey& row, const scene::CameraSpec& camera,
                    const RoomFrame& frame) {
  if (!row.carried(camera)) return 0.0f;
  const double v = row.get(camera);
  switch (row.quantity) {
    case scene::CameraQuantity::length:
      return frame.length(v);
    case scene::CameraQuantity::rate:
      return bounded(v, 0.0f, kRateBound);
    case scene::CameraQuantity::angle:
    case scene::CameraQuantity::pixels:
      break;
  }
  return static_cast<float>(v);  // a half-angle, as it is
}

// Writes a ring's vertex count / V and its vertices from `at`; returns where it ended.
float* writeRing(const geometry::Ring& ring, std::size_t vertices, const RoomFrame& frame,
                 float* at) {
  *at++ = static_cast<float>(ring.size()) / static_cast<float>(vertices);
  for (const geometry::Vec2& v : ring) {
    *at++ = frame.x(v);
    *at++ = frame.y(v);
  }
  return at + 2 * (vertices - ring.size());
}

geometry::Vec2 centroid(const geometry::Ring& ring) {
  geometry::Vec2 mean{};
  for (const geometry::Vec2& v : ring)
    mean = mean + v;
  return mean * (1.0 / static_cast<double>(ring.size()));
}

// The world's targets in the order their slots take them: the scene's with
// TargetSlots::byIndex; with TargetSlots::nearest, by the distance from their centroid to
// the nearest of `viewers` (ties: the scene's order).
std::vector<std::size_t> targetOrder(const kinematics::World& world,
                                     const std::vector<geometry::Vec2>& centroids,
                                     std::span<const geometry::Pose> viewers, TargetSlots slots) {
  std::vector<std::size_t> order(world.targets.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  if (slots == TargetSlots::byIndex) return order;
  std::vector<double> distance(order.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (const geometry::Pose& p : viewers)
      distance[i] = std::min(distance[i], geometry::distance(centroids[i], p.position()));
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return distance[a] < distance[b]; });
  return order;
}

}  // namespace

View viewNamed(std::string_view name) {
  if (name == "team") return View::team;
  if (name == "own") return View::own;
  if (name == "known") return View::known;
  throw std::invalid_argument("view: expected \"team\", \"own\" or \"known\", got \"" +
                              std::string(name) + "\"");
}

void requireFits(const scene::Scene& scene, const EncodingSizes& sizes, View view) {
  EncodingSizes needed = EncodingSizes::of(scene);
  if (view == View::own) {
    needed.obstacles = 0;
    needed.vertices = largestRing(scene.targets);
  }
  const bool targetsFit =
      sizes.targetSlots == TargetSlots::nearest || needed.targets <= sizes.targets;
  if (needed.cameras > sizes.cameras || !targetsFit || needed.obstacles > sizes.obstacles ||
      needed.vertices > sizes.vertices) {
    throw std::invalid_argument("scene " + scene.name + " needs " + std::to_string(needed.cameras) +
                                " cameras, " + std::to_string(needed.targets) + " targets, " +
                                std::to_string(needed.obstacles) + " obstacles and " +
                                std::to_string(needed.vertices) +
                                " vertices a ring: more than the encoding holds");
  }
}

void EncodingSizes::check() const {
  const auto require = [](std::size_t value, std::size_t limit, const char* what) {
    if (value > limit) {
      throw std::invalid_argument("sizes: " + std::to_string(value) + " " + what + ", at most " +
                                  std::to_string(limit));
    }
  };
  require(cameras, scene::kMaxCameras, "cameras");
  require(targets, kMaxCount, "targets");
  require(obstacles, kMaxCount, "obstacles");
  require(vertices, kMaxCount, "vertices");
}

EncodingSizes EncodingSizes::of(const scene::Scene& scene) {
  return {scene.cameras.size(), scene.targets.size(), scene.obstacles.size(),
          std::max(largestRing(scene.targets), largestRing(scene.obstacles))};
}

std::vector<std::string> cameraColumns() {
  std::vector<std::string> names{"present", "x", "y", "cos yaw", "sin yaw"};
  for (const scene::CameraKey& row : scene::kCameraKeys)
    if (row.observed) names.emplace_back(row.name);
  names.emplace_back("coverage");
  return names;
}

void observationBounds(const EncodingSizes& sizes, std::span<float> low, std::span<float> high) {
  sizes.check();
  if (low.size() != sizes.size() || high.size() != sizes.size())
    throw std::invalid_argument("observationBounds: the output has the wrong size");
  // Everything not named below is a share, a flag or a count over V: [0, 1].
  std::fill(low.begin(), low.end(), 0.0f);
  std::fill(high.begin(), high.end(), 1.0f);
  const auto set = [&](std::size_t from, std::size_t count, float lo, float hi) {
    std::fill_n(low.begin() + static_cast<std::ptrdiff_t>(from), count, lo);
    std::fill_n(high.begin() + static_cast<std::ptrdiff_t>(from), count, hi);
  };
  set(3, 1, -kRewardBound, kRewardBound);
  std::size_t at = EncodingSizes::kGlobal;
  for (std::size_t slot = 0; slot < sizes.cameras; ++slot, at += EncodingSizes::kPerCamera) {
    set(at + 1, 2, -kPositionBound, kPositionBound);
    set(at + 3, 2, -1.0f, 1.0f);  // cos γ, sin γ
    std::size_t column = EncodingSizes::kCameraPoseColumns;
    for (const scene::CameraKey& row : scene::kCameraKeys) {
      if (!row.observed) continue;
      const ObservedBounds b = *observedBounds(row.quantity);
      set(at + column++, 1, b.low, b.high);
    }
  }
  for (std::size_t slot = 0; slot < sizes.targets; ++slot, at += sizes.perTarget()) {
    set(at + 2, 2, -kPositionBound, kPositionBound);
    set(at + 5, 2 * sizes.vertices, -kPositionBound, kPositionBound);
  }
  for (std::size_t slot = 0; slot < sizes.obstacles; ++slot, at += sizes.perObstacle())
    set(at + 2, 2 * sizes.vertices, -kPositionBound, kPositionBound);
}

namespace {

// The encoding of an instant `o` that the view reads as it is (for View::known under limited
// knowledge, the camera's belief, which encodeObservation builds).
void encodeInstant(const scene::Scene& scene, const params::Parameters& params,
                   const Observation& o, const EncodingSizes& sizes, View view, std::size_t camera,
                   std::span<float> out) {
  std::fill(out.begin(), out.end(), 0.0f);
  const kinematics::World& world = o.world;
  const RoomFrame frame(world.boundary);
  const double perimeter = reward::targetPerimeter(world);
  // Who counts as seeing: the team, or the camera alone.
  const scene::CameraSet seers = view == View::own
                                     ? scene::CameraSet::only(camera)
                                     : scene::CameraSet::firstCameras(o.cameras.size());
  // The own and known views put the camera's own slot first.
  const bool egocentric = view != View::team;

  float* at = out.data();
  // The run's length: its instants after t = 0 (sim::Simulation::steps) times dt.
  const double duration =
      static_cast<double>(std::llround(params.sim.duration / params.sim.dt)) * params.sim.dt;
  *at++ = static_cast<float>(duration > 0.0 ? std::min(1.0, o.time / duration) : 1.0);
  *at++ = static_cast<float>(reward::coverageTerm(params.reward, o.terms));
  *at++ = static_cast<float>(o.terms.utilization);
  *at++ = bounded(o.terms.reward, -kRewardBound, kRewardBound);

  // Cameras: for the own view the camera itself first, then its teammates in their order.
  const std::size_t cameras = scene.cameras.size();
  for (std::size_t slot = 0; slot < std::min(sizes.cameras, cameras); ++slot) {
    float* c = at + slot * EncodingSizes::kPerCamera;
    std::size_t j = slot;
    if (egocentric) j = slot == 0 ? camera : (slot <= camera ? slot - 1 : slot);
    const scene::CameraSpec& spec = scene.cameras[j];
    const geometry::Pose& p = o.cameras[j];
    c[0] = 1.0f;
    c[1] = frame.x(p.position());
    c[2] = frame.y(p.position());
    c[3] = static_cast<float>(std::cos(p.yaw));
    c[4] = static_cast<float>(std::sin(p.yaw));
    float* column = c + EncodingSizes::kCameraPoseColumns;
    for (const scene::CameraKey& row : scene::kCameraKeys)
      if (row.observed) *column++ = observedValue(row, spec, frame);
    *column = static_cast<float>(
        reward::coverageOf(reward::visibleLengthOf(o.seen, static_cast<unsigned>(j)), perimeter));
  }
  at += sizes.cameras * EncodingSizes::kPerCamera;

  // Targets: each one's boundary length and the part seen, in the order of their slots.
  std::vector<double> boundary(world.targets.size(), 0.0), seen(world.targets.size(), 0.0);
  for (const visibility::Segment& s : o.seen) {
    const double l = visibility::length(s);
    boundary[s.target] += l;
    if (s.visibleBy.intersects(seers)) seen[s.target] += l;
  }
  std::vector<geometry::Vec2> centroids;
  centroids.reserve(world.targets.size());
  for (const geometry::Ring& ring : world.targets)
    centroids.push_back(centroid(ring));
  const std::span<const geometry::Pose> viewers =
      egocentric ? std::span(o.cameras).subspan(camera, 1) : std::span(o.cameras);
  std::size_t filled = 0;
  for (const std::size_t i : targetOrder(world, centroids, viewers, sizes.targetSlots)) {
    if (view == View::own && seen[i] == 0.0) continue;
    const std::size_t slot =
        sizes.targetSlots == TargetSlots::nearest ? filled++ : kinematics::targetId(world, i);
    if (slot >= sizes.targets) break;
    float* t = at + slot * sizes.perTarget();
    t[0] = 1.0f;
    t[1] = static_cast<float>(boundary[i] > 0.0 ? seen[i] / boundary[i] : 0.0);
    t[2] = frame.x(centroids[i]);
    t[3] = frame.y(centroids[i]);
    writeRing(world.targets[i], sizes.vertices, frame, t + 4);
  }
  at += sizes.targets * sizes.perTarget();

  if (view == View::own) return;
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    float* b = at + kinematics::obstacleId(world, i) * sizes.perObstacle();
    b[0] = 1.0f;
    writeRing(world.obstacles[i], sizes.vertices, frame, b + 1);
  }
}

}  // namespace

void encodeObservation(const scene::Scene& scene, const params::Parameters& params,
                       const Observation& o, const EncodingSizes& sizes, View view,
                       std::size_t camera, std::span<float> out) {
  sizes.check();
  requireFits(scene, sizes, view);
  if (out.size() != sizes.size())
    throw std::invalid_argument("encodeObservation: the output has the wrong size");
  if (view != View::team && camera >= scene.cameras.size())
    throw std::invalid_argument("encodeObservation: no camera " + std::to_string(camera));
  if (view != View::known || o.own.empty()) {
    // With full knowledge a camera knows the world and its team as they are.
    encodeInstant(scene, params, o, sizes, view, camera, out);
    return;
  }
  // Under limited knowledge the camera's belief: the world it saw or was told, the team where
  // it last heard of each (believedTeam), and S and the terms measured in that world, as its
  // own loop would measure them (the decentralized method's).
  const OwnKnowledge& own = o.own[camera];
  std::vector<geometry::Pose> team;
  believedTeam(scene, own, camera, o.cameras[camera], team);
  reward::RewardModel model(params.reward, scene::lenses(scene));
  model.setWorld(own.world);
  const reward::RewardTerms terms = model.evaluate(team);
  const Observation belief{o.time, own.world, team, model.segments(), terms};
  encodeInstant(scene, params, belief, sizes, view, camera, out);
}

}  // namespace camcov::control
