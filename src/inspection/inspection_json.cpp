#include "inspection/inspection_json.h"

#include <bit>

#include "kinematics/kinematics.h"
#include "reward/metrics.h"

namespace camcov::inspection {

nlohmann::json cameraNumbers(const scene::CameraSet& visibleBy) {
  nlohmann::json list = nlohmann::json::array();
  visibleBy.forEach([&](std::size_t j) { list.push_back(j); });
  return list;
}

nlohmann::json termsJson(const reward::RewardTerms& terms, bool weighted) {
  nlohmann::json out{{"coverage", terms.coverage},
                     {"utilization", terms.utilization},
                     {"repulsion", terms.repulsion},
                     {"reward", terms.reward}};
  if (weighted) out["weightedCoverage"] = terms.weightedCoverage;
  return out;
}

nlohmann::json inspectionJson(const scene::Scene& scene, double time,
                              std::span<const geometry::Pose> cameras,
                              const reward::RewardModel& model, const reward::RewardTerms& terms) {
  const kinematics::World& world = model.world();
  const auto segments = model.segments();
  nlohmann::json out = termsJson(terms, scene.isWeighted());
  out["scene"] = scene.name;
  out["time"] = time;
  out["targetPerimeter"] = reward::targetPerimeter(world);
  out["cameras"] = nlohmann::json::array();
  for (unsigned j = 0; j < cameras.size(); ++j) {
    out["cameras"].push_back({{"x", cameras[j].x},
                              {"y", cameras[j].y},
                              {"yaw_deg", geometry::radToDeg(cameras[j].yaw)},
                              {"visibleLength", reward::visibleLengthOf(segments, j)}});
  }
  out["segments"] = nlohmann::json::array();
  for (const auto& seg : segments) {
    out["segments"].push_back({{"a", {seg.a.x, seg.a.y}},
                               {"b", {seg.b.x, seg.b.y}},
                               {"target", kinematics::targetId(world, seg.target)},
                               {"edge", seg.edge},
                               {"length", visibility::length(seg)},
                               {"visibleBy", cameraNumbers(seg.visibleBy)}});
    // Where weighted, the edge's importance weight (World::targetEdgeWeights, in [0, 1]).
    if (scene.isWeighted())
      out["segments"].back()["weight"] = world.targetEdgeWeights[seg.target][seg.edge];
  }
  return out;
}

}  // namespace camcov::inspection
