#include "inspection/explanation_json.h"

#include <string>
#include <vector>

#include "inspection/inspection_json.h"
#include "params/parameters.h"
#include "reward/metrics.h"
#include "visibility/sweep.h"
#include "visibility/sweep_trace.h"
#include "visibility/unseen_reason.h"

namespace camcov::inspection {
namespace {

nlohmann::json points(std::span<const geometry::Vec2> ring) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : ring)
    out.push_back({v.x, v.y});
  return out;
}

// An object by its scene index, its ring now and where its shape's frame is (a page that moves
// a vertex edits the shape through it).
nlohmann::json placedJson(std::uint32_t id, const geometry::Ring& ring,
                          const kinematics::ObjectPose& pose) {
  return {{"id", id},
          {"ring", points(ring)},
          {"reference", {pose.reference.x, pose.reference.y}},
          {"angle", pose.angle}};
}

void addObjects(const kinematics::World& world, const kinematics::Kinematics& kinematics,
                double time, nlohmann::json& out) {
  out["boundary"] = points(world.boundary);
  out["targets"] = nlohmann::json::array();
  for (std::size_t i = 0; i < world.targets.size(); ++i) {
    const std::uint32_t id = kinematics::targetId(world, i);
    out["targets"].push_back(placedJson(id, world.targets[i], kinematics.targetPose(id, time)));
    if (!world.targetEdgeWeights.empty())
      out["targets"].back()["weights"] = world.targetEdgeWeights[i];
  }
  out["obstacles"] = nlohmann::json::array();
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    const std::uint32_t id = kinematics::obstacleId(world, i);
    out["obstacles"].push_back(
        placedJson(id, world.obstacles[i], kinematics.obstaclePose(id, time)));
  }
}

// S by columns: target and edge, the ends ax, ay, bx, by in a row, and who sees each.
nlohmann::json segmentColumns(const kinematics::World& world,
                              std::span<const visibility::Segment> segments) {
  nlohmann::json target = nlohmann::json::array(), edge = nlohmann::json::array(),
                 ends = nlohmann::json::array(), visibleBy = nlohmann::json::array();
  for (const visibility::Segment& s : segments) {
    target.push_back(kinematics::targetId(world, s.target));
    edge.push_back(s.edge);
    for (const double v : {s.a.x, s.a.y, s.b.x, s.b.y})
      ends.push_back(v);
    visibleBy.push_back(cameraNumbers(s.visibleBy));
  }
  return {{"target", std::move(target)},
          {"edge", std::move(edge)},
          {"ends", std::move(ends)},
          {"visibleBy", std::move(visibleBy)}};
}

// Why each camera that does not see `s` does not (null for those that do).
nlohmann::json reasonsJson(const kinematics::World& world, const visibility::Segment& s,
                           std::span<const geometry::Pose> cameras,
                           std::span<const scene::Lens> lenses) {
  nlohmann::json why = nlohmann::json::array();
  for (unsigned j = 0; j < cameras.size(); ++j) {
    if (s.visibleBy.contains(j)) {
      why.push_back(nullptr);
    } else {
      why.push_back(visibility::describeUnseen(
          world, visibility::whyUnseen(world, cameras[j], lenses[j], s)));
    }
  }
  return why;
}

nlohmann::json tracedEdge(const kinematics::World& world, const visibility::TracedEdge& e) {
  using Kind = visibility::TracedEdge::Kind;
  if (e.kind == Kind::None) return nullptr;
  if (e.kind == Kind::Wedge) return {{"wedge", true}};
  using visibility::RingKind;
  const std::string ring = e.ring == RingKind::Boundary ? "boundary"
                           : e.ring == RingKind::Target ? "target"
                                                        : "obstacle";
  const std::uint32_t owner = e.ring == RingKind::Target ? kinematics::targetId(world, e.owner)
                              : e.ring == RingKind::Obstacle
                                  ? kinematics::obstacleId(world, e.owner)
                                  : 0;
  return {{"ring", ring},
          {"owner", owner},
          {"edge", e.edge},
          {"a", {e.a.x, e.a.y}},
          {"b", {e.b.x, e.b.y}}};
}

nlohmann::json traceJson(const kinematics::World& world, const visibility::SweepTrace& trace,
                         int camera) {
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : trace.events) {
    events.push_back({{"ray", e.ray},
                      {"point", {e.point.x, e.point.y}},
                      {"angle", e.angle},
                      {"inserted", e.inserted},
                      {"removed", e.removed},
                      {"front", tracedEdge(world, e.frontAfter)},
                      {"inFov", e.inFovAfter},
                      {"hit", {e.hitAfter.x, e.hitAfter.y}}});
  }
  return {{"camera", camera},
          {"blind", trace.blind},
          {"front", tracedEdge(world, trace.frontBefore)},
          {"events", events}};
}

}  // namespace

nlohmann::json explanationJson(const scene::Scene& scene, const kinematics::Kinematics& kinematics,
                               double time, std::span<const geometry::Pose> cameras,
                               reward::RewardModel& model, const ExplanationAsks& asks) {
  const std::vector<scene::Lens> lenses = scene::lenses(scene);
  const params::Parameters p;
  const kinematics::World& world = model.world();
  const reward::RewardTerms terms = model.evaluate(cameras);
  const std::vector<visibility::Segment> segments(model.segments().begin(), model.segments().end());
  nlohmann::json out{{"time", time}, {"terms", termsJson(terms, scene.isWeighted())}};
  addObjects(world, kinematics, time, out);
  // Each camera: its field of view, and its terms alone.
  visibility::Sweep sweep;
  geometry::Ring view;
  out["cameras"] = nlohmann::json::array();
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    sweep.fieldOfViewPolygon(model.occluders(), cameras[j], lenses[j], view);
    const reward::RewardTerms alone =
        reward::termsAlone(world, segments, cameras, lenses, j, p.reward);
    out["cameras"].push_back({{"pose", {cameras[j].x, cameras[j].y, cameras[j].yaw}},
                              {"halfFov", lenses[j].halfFov},
                              {"view", points(view)},
                              {"visibleLength", reward::visibleLengthOf(segments, j)},
                              {"terms", termsJson(alone, scene.isWeighted())}});
  }
  out["segments"] = segmentColumns(world, segments);
  if (asks.reasonsFor >= 0 && static_cast<std::size_t>(asks.reasonsFor) < segments.size()) {
    out["reasons"] = {{"segment", asks.reasonsFor},
                      {"why", reasonsJson(world, segments[asks.reasonsFor], cameras, lenses)}};
  }
  if (asks.traceCamera >= 0 && static_cast<std::size_t>(asks.traceCamera) < cameras.size()) {
    visibility::SweepTrace trace;
    sweep.trace(model.occluders(), cameras[asks.traceCamera], lenses[asks.traceCamera], trace);
    out["trace"] = traceJson(world, trace, asks.traceCamera);
  }
  return out;
}

}  // namespace camcov::inspection
