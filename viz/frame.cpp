#include "viz/frame.h"

#include "scene/pitch_markings.h"

#include <fmt/format.h>

#include "reward/metrics.h"
#include "reward/resolution_coverage.h"

namespace camcov::viz {
namespace {

void addPaths(const std::vector<scene::MovingObject>& objects, std::vector<ObjectPath>& out) {
  for (const auto& object : objects) {
    if (object.path.size() > 1 || object.angularVelocity != 0.0) {
      out.push_back(
          {object.path, object.path.size() > 1 ? object.velocity : 0.0, object.angularVelocity});
    }
  }
}

}  // namespace

std::string ObjectPath::speedLabel() const {
  std::string label;
  if (velocity > 0.0) label = fmt::format("{:g} m/s", velocity);
  if (angularVelocity != 0.0) {
    if (!label.empty()) label += ", ";
    label += fmt::format("{:g} rad/s", angularVelocity);
  }
  return label;
}

FrameBuilder::FrameBuilder(const scene::Scene& scene)
    : kinematics_(scene),
      sceneName_(scene.name),
      weighted_(scene.isWeighted()),
      lenses_(scene::lenses(scene)) {
  addPaths(scene.targets, paths_);
  addPaths(scene.obstacles, paths_);
  for (const auto& t : scene.targets)
    colours_.push_back(rgbFromHex(t.color));
  if (scene.pitch) markings_ = scene::pitchMarkings(*scene.pitch);
}

void FrameBuilder::build(double time, std::span<const geometry::Pose> cameras, Frame& out) {
  kinematics_.worldAt(time, out.world);
  out.targetColours.resize(out.world.targets.size());
  for (std::size_t i = 0; i < out.world.targets.size(); ++i)
    out.targetColours[i] = colours_[kinematics::targetId(out.world, i)];
  occluders_.build(out.world);
  sweep_.segments(occluders_, cameras, lenses_, out.segments);

  out.cameras.resize(cameras.size());
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    CameraView& c = out.cameras[j];
    c.pose = cameras[j];
    sweep_.fieldOfViewPolygon(occluders_, c.pose, lenses_[j], c.view);
    c.goal.reset();
    c.plan.clear();
  }
  out.paths = paths_;
  out.markings = markings_;

  out.caption.title = sceneName_;
  out.caption.subtitle.clear();
  out.caption.time = time;
  const double perimeter = reward::targetPerimeter(out.world);
  out.caption.coverage = reward::coverage(out.segments, perimeter);
  out.caption.weightedCoverage.reset();
  if (weighted_) {
    out.caption.weightedCoverage = reward::weightedCoverage(out.segments, out.world);
  }
  out.caption.utilization = reward::utilization(out.segments, cameras, lenses_);
  out.unresolved.clear();
  out.caption.resolutionCoverage.reset();
  if (const auto& asked = out.world.resolution) {
    out.caption.resolutionCoverage =
        reward::resolutionCoverage(out.segments, cameras, lenses_, *asked, perimeter);
    for (const visibility::Segment& s : out.segments)
      reward::addUnresolvedPieces(s, cameras, lenses_, asked->minDensity, out.unresolved);
  }
}

}  // namespace camcov::viz
