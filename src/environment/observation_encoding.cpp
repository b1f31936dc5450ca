#include "environment/observation_encoding.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/ring.h"
#include "kinematics/world.h"
#include "scene/camera.h"

namespace camcov::environment {
namespace {

std::size_t largestRing(const scene::MovingObject& object) {
  std::size_t n = object.shape.size();
  if (object.deformation) {
    for (const auto& keyframe : object.deformation->keyframes)
      n = std::max(n, keyframe.shape.size());
  }
  return n;
}

// The room's frame: (p − c) / L.
struct RoomFrame {
  explicit RoomFrame(const geometry::Ring& boundary) {
    const geometry::Box box = geometry::boundingBox(boundary);
    centre = (box.min + box.max) * 0.5;
    halfSide = 0.5 * std::max(box.max.x - box.min.x, box.max.y - box.min.y);
  }
  geometry::Vec2 centre;
  double halfSide = 1.0;
  float x(geometry::Vec2 p) const { return static_cast<float>((p.x - centre.x) / halfSide); }
  float y(geometry::Vec2 p) const { return static_cast<float>((p.y - centre.y) / halfSide); }
  float length(double metres) const { return static_cast<float>(metres / halfSide); }
};

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

void requireFits(const scene::Scene& scene, const EncodingSizes& sizes) {
  const EncodingSizes needed = EncodingSizes::of(scene);
  if (needed.cameras > sizes.cameras || needed.targets > sizes.targets ||
      needed.obstacles > sizes.obstacles || needed.vertices > sizes.vertices) {
    throw std::invalid_argument("scene " + scene.name + " needs " + std::to_string(needed.cameras) +
                                " cameras, " + std::to_string(needed.targets) + " targets, " +
                                std::to_string(needed.obstacles) + " obstacles and " +
                                std::to_string(needed.vertices) +
                                " vertices a ring: more than the encoding holds");
  }
}

}  // namespace

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
  EncodingSizes s{scene.cameras.size(), scene.targets.size(), scene.obstacles.size(), 0};
  for (const auto& o : scene.targets)
    s.vertices = std::max(s.vertices, largestRing(o));
  for (const auto& o : scene.obstacles)
    s.vertices = std::max(s.vertices, largestRing(o));
  return s;
}

void encodeObservation(const Episode& episode, const EncodingSizes& sizes, View view,
                       std::size_t camera, std::span<float> out) {
  const scene::Scene& scene = episode.scene();
  sizes.check();
  requireFits(scene, sizes);
  if (out.size() != sizes.size())
    throw std::invalid_argument("encodeObservation: the output has the wrong size");
  if (view == View::own && camera >= scene.cameras.size())
    throw std::invalid_argument("encodeObservation: no camera " + std::to_string(camera));
  std::fill(out.begin(), out.end(), 0.0f);
  const control::Observation o = episode.observation();
  const kinematics::World& world = o.world;
  const RoomFrame frame(world.boundary);
  const double perimeter = reward::targetPerimeter(world);
  // Who counts as seeing: the team, or the camera alone.
  const std::uint64_t seers = view == View::own ? std::uint64_t{1} << camera : ~std::uint64_t{0};

  float* at = out.data();
  const double duration = episode.steps() * episode.params().sim.dt;
  *at++ = static_cast<float>(duration > 0.0 ? std::min(1.0, o.time / duration) : 1.0);
  *at++ = static_cast<float>(reward::coverageTerm(episode.params().reward, o.terms));
  *at++ = static_cast<float>(o.terms.utilization);
  *at++ = static_cast<float>(o.terms.reward);

  // Cameras: for the own view only the camera itself, in the first slot.
  for (std::size_t slot = 0; slot < sizes.cameras; ++slot) {
    float* c = at + slot * EncodingSizes::kPerCamera;
    const std::size_t j = view == View::own ? camera : slot;
    if ((view == View::own && slot > 0) || j >= scene.cameras.size()) continue;
    const scene::CameraSpec& spec = scene.cameras[j];
    const geometry::Pose& p = o.cameras[j];
    c[0] = 1.0f;
    c[1] = frame.x(p.position());
    c[2] = frame.y(p.position());
    c[3] = static_cast<float>(std::cos(p.yaw));
    c[4] = static_cast<float>(std::sin(p.yaw));
    c[5] = frame.length(spec.maxVelocity);
    c[6] = static_cast<float>(spec.maxAngularVelocity);
    c[7] = static_cast<float>(spec.lens.halfFov);
    c[8] = spec.lens.limited() ? frame.length(spec.lens.range) : 0.0f;
    c[9] = static_cast<float>(
        reward::coverageOf(reward::visibleLengthOf(o.seen, static_cast<unsigned>(j)), perimeter));
  }
  at += sizes.cameras * EncodingSizes::kPerCamera;

  // Targets, by the scene's index: each one's boundary length and the part seen.
  std::vector<double> boundary(world.targets.size(), 0.0), seen(world.targets.size(), 0.0);
  for (const visibility::Segment& s : o.seen) {
    const double l = visibility::length(s);
    boundary[s.target] += l;
    if ((s.visibleBy & seers) != 0) seen[s.target] += l;
  }
  for (std::size_t i = 0; i < world.targets.size(); ++i) {
    if (view == View::own && seen[i] == 0.0) continue;
    const geometry::Ring& ring = world.targets[i];
    float* t = at + kinematics::targetId(world, i) * sizes.perTarget();
    geometry::Vec2 mean{};
    for (const geometry::Vec2& v : ring)
      mean = mean + v;
    mean = mean * (1.0 / static_cast<double>(ring.size()));
    t[0] = 1.0f;
    t[1] = static_cast<float>(boundary[i] > 0.0 ? seen[i] / boundary[i] : 0.0);
    t[2] = frame.x(mean);
    t[3] = frame.y(mean);
    writeRing(ring, sizes.vertices, frame, t + 4);
  }
  at += sizes.targets * sizes.perTarget();

  if (view == View::own) return;
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    float* b = at + kinematics::obstacleId(world, i) * sizes.perObstacle();
    b[0] = 1.0f;
    writeRing(world.obstacles[i], sizes.vertices, frame, b + 1);
  }
}

reward::RewardTerms ownTerms(const Episode& episode, std::size_t camera) {
  const control::Observation o = episode.scored();  // a reward: the true world's
  const scene::Scene& scene = episode.scene();
  if (camera >= scene.cameras.size())
    throw std::invalid_argument("ownTerms: no camera " + std::to_string(camera));
  return reward::termsAlone(o.world, o.seen, o.cameras, scene::lenses(scene), camera,
                            episode.params().reward);
}

}  // namespace camcov::environment
