// An example method, complete in this one file: each camera turns toward the nearest edge of a
// target that no other camera sees and moves to a point in front of it (so a camera keeps the
// edge it found, and two cameras do not both chase the same one). Greedy, memoryless and
// uncoordinated — a yardstick for what the paper's coordination buys, and a template for a
// method of your own (docs/method.md, "Adding a method").
//
// What a controller gets: the scene (cameras' limits and fields of view), the parameters and
// a seed when it is made; each step an Observation (control/controller.h) with the world at t,
// the cameras' poses and S(t), what the team sees now. What it returns: one velocity command
// per camera (saturated to the limits and made safe by the simulator), and optionally goals
// (drawn in frames) and events (kept in the results).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

#include "control/controller.h"
#include "control/methods.h"
#include "geometry/vec2.h"
#include "params/parameters.h"
#include "scene/scene.h"
#include "visibility/segment.h"

namespace camcov::examples {
namespace {

class NearestUnseenController final : public control::Controller {
 public:
  NearestUnseenController(const scene::Scene& scene, const params::Parameters& params)
      : scene_(scene),
        dt_(params.sim.dt),
        standoff_(params.reward.d2),
        goals_(scene.cameras.size()) {}

  void control(const control::Observation& o, std::span<scene::CameraCommand> commands) override {
    for (std::size_t j = 0; j < o.cameras.size(); ++j) {
      const geometry::Pose& p = o.cameras[j];
      const visibility::Segment* nearest = nearestUnseen(o.seen, j, p.position());
      if (nearest == nullptr) {  // everything is seen: hold still
        commands[j] = {};
        goals_[j].reset();
        continue;
      }
      // Stand d2 in front of the edge's midpoint, on its outer side (rings are CCW, so the
      // outward normal of a → b is b − a turned clockwise), looking at it.
      const geometry::Vec2 mid = 0.5 * (nearest->a + nearest->b);
      const geometry::Vec2 along = nearest->b - nearest->a;
      const geometry::Vec2 outward = geometry::Vec2{along.y, -along.x} / geometry::norm(along);
      const geometry::Vec2 viewpoint = mid + outward * standoff_;
      const geometry::Vec2 toMid = mid - p.position();
      goals_[j] = geometry::Pose{viewpoint.x, viewpoint.y, std::atan2(-outward.y, -outward.x)};
      const scene::CameraSpec& limits = scene_.cameras[j];
      const geometry::Vec2 offset = viewpoint - p.position();
      const double distance = geometry::norm(offset);
      const double speed = std::min(limits.maxVelocity, distance / dt_);
      const double turn = geometry::wrapAngle(std::atan2(toMid.y, toMid.x) - p.yaw) / dt_;
      commands[j] = {distance > 0.0 ? offset * (speed / distance) : geometry::Vec2{}, turn};
    }
  }

  std::optional<geometry::Pose> goal(std::size_t camera) const override { return goals_[camera]; }
  void takeEvents(std::vector<control::ControlEvent>&) override {}

 private:
  // The piece of target boundary that no camera but `camera` sees whose midpoint is nearest to
  // `from`, or nullptr.
  static const visibility::Segment* nearestUnseen(std::span<const visibility::Segment> seen,
                                                  std::size_t camera, geometry::Vec2 from) {
    const visibility::Segment* best = nullptr;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const visibility::Segment& s : seen) {
      scene::CameraSet others = s.visibleBy;
      others.erase(camera);
      if (!others.empty() || s.a == s.b) continue;
      const double d = geometry::distance(from, 0.5 * (s.a + s.b));
      if (d < bestDistance) {
        bestDistance = d;
        best = &s;
      }
    }
    return best;
  }

  const scene::Scene& scene_;
  double dt_;
  double standoff_;  // m in front of the edge: the repulsion radius d2 of eq. (7)
  std::vector<std::optional<geometry::Pose>> goals_;
};

}  // namespace

// The registration line: name, description, colour, role, and how to make the controller.
const bool kRegistered = control::registerMethod(
    {"nearest-unseen", "nearest unseen edge (example)", "#2ca02c", control::Role::example,
     [](const scene::Scene& s, const params::Parameters& p,
        std::uint64_t) -> std::unique_ptr<control::Controller> {
       return std::make_unique<NearestUnseenController>(s, p);
     }});

}  // namespace camcov::examples
