#include "safety/step_contacts.h"

#include <algorithm>
#include <limits>

#include "geometry/ring.h"
#include "safety/lipschitz_search.h"

namespace camcov::safety {
namespace {

// One distance followed through the step.
struct Pair {
  std::size_t camera = 0;
  std::ptrdiff_t other = -1;  // the other camera; −1: the pair is a camera and an object
  bool target = false;        // for an object: a target (else an obstacle), and which
  std::size_t object = 0;
  Sampled distance;  // f is set only when the pair has to be searched: most never are
  bool withCamera() const { return other >= 0; }
};

}  // namespace

StepAccounting::StepAccounting(const kinematics::Kinematics& kinematics, double delta)
    : kinematics_(kinematics), delta_(delta) {
  const auto& scene = kinematics.scene();
  for (std::size_t i = 0; i < scene.targets.size(); ++i)
    targetBounds_.push_back(kinematics.targetMotionBounds(i));
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
    obstacleBounds_.push_back(kinematics.obstacleMotionBounds(i));
}

Sample StepAccounting::sample(const kinematics::World& world,
                              std::span<const geometry::Pose> cameras) const {
  Sample s;
  s.time = world.time;
  // One distance per object of the scene, in scene order; an object absent at this instant
  // (a recorded track) is infinitely far.
  const std::size_t targets = targetBounds_.size(), objects = targets + obstacleBounds_.size();
  for (const auto& c : cameras) {
    const geometry::Vec2 p = c.position();
    const std::size_t first = s.objectDistances.size();
    s.objectDistances.resize(first + objects, std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < world.targets.size(); ++k) {
      s.objectDistances[first + kinematics::targetId(world, k)] =
          geometry::distanceToPolygon(world.targets[k], p);
    }
    for (std::size_t k = 0; k < world.obstacles.size(); ++k) {
      s.objectDistances[first + targets + kinematics::obstacleId(world, k)] =
          geometry::distanceToPolygon(world.obstacles[k], p);
    }
    for (std::size_t o = first; o < first + objects; ++o)
      s.minObjectDistance = std::min(s.minObjectDistance, s.objectDistances[o]);
    for (const geometry::Vec2 q : s.cameras)
      s.minCameraDistance = std::min(s.minCameraDistance, geometry::distance(p, q));
    s.cameras.push_back(p);
  }
  return s;
}

StepContacts StepAccounting::measure(const Sample& from, const Sample& to) const {
  const double t0 = from.time;
  const double h = to.time - from.time;
  auto cameraAt = [&from, &to, h](std::size_t j, double tau) {
    return h > 0.0 ? geometry::lerp(from.cameras[j], to.cameras[j], tau / h) : from.cameras[j];
  };
  auto cameraSpeed = [&](std::size_t j) {
    return h > 0.0 ? geometry::distance(from.cameras[j], to.cameras[j]) / h : 0.0;
  };

  // Every pair in one order (camera j: the objects, then the cameras before it), made as it is
  // visited: at 100 cameras there are 15,000 of them, of which a handful are ever searched, and
  // keeping them all cost a 2 MB list each step.
  const std::size_t objectCount = targetBounds_.size() + obstacleBounds_.size();
  auto forEachPair = [&](auto&& visit) {
    for (std::size_t j = 0; j < from.cameras.size(); ++j) {
      for (std::size_t o = 0; o < objectCount; ++o) {
        const bool isTarget = o < targetBounds_.size();
        const std::size_t i = isTarget ? o : o - targetBounds_.size();
        const double speed = (isTarget ? targetBounds_[i] : obstacleBounds_[i]).pointSpeed();
        visit(Pair{j,
                   -1,
                   isTarget,
                   i,
                   {{},
                    h,
                    from.objectDistances[j * objectCount + o],
                    to.objectDistances[j * objectCount + o],
                    cameraSpeed(j) + speed,
                    {}}});
      }
      for (std::size_t i = 0; i < j; ++i) {
        // Both move linearly, so their offset r does too: slope ≤ |r1 − r0|/h.
        const geometry::Vec2 r0 = from.cameras[j] - from.cameras[i];
        const geometry::Vec2 r1 = to.cameras[j] - to.cameras[i];
        visit(Pair{j,
                   static_cast<std::ptrdiff_t>(i),
                   false,
                   0,
                   {{},
                    h,
                    geometry::norm(r0),
                    geometry::norm(r1),
                    h > 0.0 ? geometry::distance(r0, r1) / h : 0.0,
                    {}}});
      }
    }
  };
  // The distance between the step's ends, for a pair about to be searched.
  auto follow = [&](Pair& p) -> const Sampled& {
    if (p.distance.f) return p.distance;
    const std::size_t j = p.camera;
    if (p.withCamera()) {
      const auto i = static_cast<std::size_t>(p.other);
      const geometry::Vec2 r0 = from.cameras[j] - from.cameras[i];
      const geometry::Vec2 r1 = to.cameras[j] - to.cameras[i];
      p.distance.f = [r0, r1, h](double tau) {
        return geometry::norm(geometry::lerp(r0, r1, tau / h));
      };
    } else {
      p.distance.f = [this, target = p.target, i = p.object, t0, j, cameraAt,
                      ring = geometry::Ring()](double tau) mutable {
        const double t = t0 + tau;
        if (!(target ? kinematics_.targetPresent(i, t) : kinematics_.obstaclePresent(i, t)))
          return std::numeric_limits<double>::infinity();
        if (target) {
          kinematics_.placeTarget(i, t, ring);
        } else {
          kinematics_.placeObstacle(i, t, ring);
        }
        return geometry::distanceToPolygon(ring, cameraAt(j, tau));
      };
      // Over [a, b] the object's reference point stays within travel·(b − a)/2 of where it is
      // at the middle, and every point of the object within its reach of that point, while
      // the camera stays on its segment: bounds that do not grow with the object's spin.
      p.distance.floor = [this, target = p.target, i = p.object, t0, j, cameraAt](double a,
                                                                                  double b) {
        const double middle = t0 + 0.5 * (a + b);
        if (!(target ? kinematics_.targetPresent(i, middle)
                     : kinematics_.obstaclePresent(i, middle)))
          return -std::numeric_limits<double>::infinity();  // no bound known
        const kinematics::MotionBounds& bounds = target ? targetBounds_[i] : obstacleBounds_[i];
        const geometry::Vec2 reference =
            (target ? kinematics_.targetPose(i, middle) : kinematics_.obstaclePose(i, middle))
                .reference;
        return geometry::distanceToSegment(reference, cameraAt(j, a), cameraAt(j, b)) -
               bounds.travel * 0.5 * (b - a) - bounds.reach;
      };
    }
    return p.distance;
  };

  StepContacts result;
  result.contactStart.assign(from.cameras.size(), -1.0);
  auto lowerBound = [](const Sampled& s) { return 0.5 * (s.f0 + s.f1 - s.lipschitz * s.h); };
  // Minimum distances: start from the samples, then search only pairs that might beat them.
  forEachPair([&](const Pair& p) {
    double& best = p.withCamera() ? result.minCameraDistance : result.minObjectDistance;
    best = std::min({best, p.distance.f0, p.distance.f1});
  });
  forEachPair([&](Pair p) {
    double& best = p.withCamera() ? result.minCameraDistance : result.minObjectDistance;
    if (lowerBound(p.distance) < best - kDistanceTolerance)
      best = std::min(best, std::max(0.0, lipschitzMinimum(follow(p), kDistanceTolerance, best)));
  });

  // Contacts: only pairs that may come below δ take part.
  std::vector<Pair> touching;
  forEachPair([&](Pair p) {
    if (lowerBound(p.distance) >= delta_) return;
    const double first = firstBelow(follow(p), delta_, kContactDepth);
    if (first < 0.0) return;
    for (const std::ptrdiff_t c : {static_cast<std::ptrdiff_t>(p.camera), p.other}) {
      if (c < 0) continue;
      double& start = result.contactStart[static_cast<std::size_t>(c)];
      start = start < 0.0 ? first : std::min(start, first);
    }
    touching.push_back(std::move(p));
  });
  std::vector<const Sampled*> objects, cameras, all;
  for (const Pair& p : touching) {
    (p.withCamera() ? cameras : objects).push_back(&p.distance);
    all.push_back(&p.distance);
  }
  auto below = [&](const std::vector<const Sampled*>& group) {
    if (group.empty()) return 0.0;
    // The nearest of several distances: its slope is bounded by the largest of theirs.
    Sampled nearest{[&group](double tau) {
                      double d = std::numeric_limits<double>::infinity();
                      for (const Sampled* s : group)
                        d = std::min(d, s->f(tau));
                      return d;
                    },
                    h,
                    std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity(),
                    0.0,
                    {}};
    for (const Sampled* s : group) {
      nearest.f0 = std::min(nearest.f0, s->f0);
      nearest.f1 = std::min(nearest.f1, s->f1);
      nearest.lipschitz = std::max(nearest.lipschitz, s->lipschitz);
    }
    return timeBelow(nearest, delta_, kContactDepth);
  };
  result.objectContactTime = below(objects);
  result.cameraContactTime = below(cameras);
  result.contactTime = below(all);
  return result;
}

}  // namespace camcov::safety
