#include "planners/state_validity.h"

#include <algorithm>
#include <cmath>

namespace camcov::planners {

void StateValidity::setWorld(const kinematics::World& world) {
  world_ = &world;
  objects_.clear();
  boxes_.clear();
  scale_ = 0.0;
  for (const auto* group : {&world.targets, &world.obstacles}) {
    for (const auto& object : *group) {
      objects_.push_back(&object);
      const geometry::Box& box = boxes_.emplace_back(geometry::boundingBox(object));
      scale_ = std::max({scale_, std::abs(box.min.x), std::abs(box.min.y), std::abs(box.max.x),
                         std::abs(box.max.y)});
    }
  }
}

bool StateValidity::clearOfObjects(geometry::Vec2 p) const {
  // An object whose box lies farther than d1 cannot be nearer: only the objects around p are
  // measured. "Farther" with room for the rounding of both distances, far below a nanometre,
  // so that the answer is the one every object measured would give.
  const double reach = d1_ + 1e-9 * (1.0 + scale_ + std::abs(p.x) + std::abs(p.y));
  const double reach2 = reach * reach;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (geometry::squaredDistance(boxes_[i], p) > reach2) continue;
    if (geometry::distanceToPolygon(*objects_[i], p) < d1_) return false;
  }
  return true;
}

bool StateValidity::insideBoundary(geometry::Vec2 p) const {
  return geometry::locate(world_->boundary, p, 0.0) == geometry::Containment::Inside;
}

bool StateValidity::staysClear(geometry::Vec2 a, geometry::Vec2 b, bool endsClear) const {
  const std::size_t n = world_->boundary.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (geometry::segmentsIntersect(a, b, world_->boundary[i], world_->boundary[(i + 1) % n])) {
      return false;
    }
  }
  // A segment inside an object reaches its boundary or has an end inside; either way the
  // distances below are 0, and only a segment that stays outside can pass.
  const geometry::Box span{{std::min(a.x, b.x), std::min(a.y, b.y)},
                           {std::max(a.x, b.x), std::max(a.y, b.y)}};
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    const geometry::Box& box = boxes_[i];
    const double gap = std::max({box.min.x - span.max.x, span.min.x - box.max.x,
                                 box.min.y - span.max.y, span.min.y - box.max.y});
    if (gap >= d1_) continue;
    const geometry::Ring& object = *objects_[i];
    // Ends clear of every object are at least d1 from this one: what is required is d1.
    double required = d1_;
    if (!endsClear) {
      const double da = geometry::distanceToPolygon(object, a);
      const double db = geometry::distanceToPolygon(object, b);
      if (da < d1_ && db < d1_) return false;  // no motion between two states too close
      required = std::min({d1_, da, db});
    }
    if (required <= 0.0 || geometry::distanceSegmentToBoundary(object, a, b) < required)
      return false;
  }
  return true;
}

}  // namespace camcov::planners
