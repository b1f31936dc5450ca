// The engine's JavaScript face (embind): a scene's text in, what `camcov validate` and
// `camcov inspect --json` would say out, computed by the same C++ as the program. Everything
// crosses as JSON text, so that a page needs no types of ours.
#include <emscripten/bind.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "kinematics/kinematics.h"
#include "params/parameters.h"
#include "reward/metrics.h"
#include "reward/reward_model.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"
#include "visibility/sweep.h"
#include "visibility/sweep_trace.h"
#include "visibility/unseen_reason.h"

namespace {

using camcov::geometry::Pose;

nlohmann::json failure(const std::exception& error) {
  return {{"error", error.what()}};
}

// {"ok": true} for a scene `camcov validate` accepts, else {"error": its message}.
std::string validate(const std::string& sceneText, const std::string& name) {
  try {
    camcov::scene::parseScene(sceneText, name);
    return nlohmann::json{{"ok", true}}.dump();
  } catch (const std::exception& error) {
    return failure(error).dump();
  }
}

// `camcov inspect SCENE --time T [--cameras POSES] --json`, its numbers: the reward's terms
// (eq. (3)–(8)), each camera's visible length, and S with visibleBy. `posesText` as a camera
// poses file ([{"x":..,"y":..,"yaw_deg":..}]); empty: the scene's initial poses.
std::string inspect(const std::string& sceneText, const std::string& name, double time,
                    const std::string& posesText) {
  try {
    const camcov::scene::Scene scene = camcov::scene::parseScene(sceneText, name);
    std::vector<Pose> cameras;
    if (posesText.empty()) {
      for (const auto& c : scene.cameras)
        cameras.push_back(c.initial);
    } else {
      cameras = camcov::scene::parseCameraPoses(posesText, "poses");
    }
    const camcov::params::Parameters p;
    camcov::reward::RewardModel model(p.reward, camcov::scene::lenses(scene));
    model.setWorld(camcov::kinematics::Kinematics(scene).worldAt(time));
    const camcov::reward::RewardTerms terms = model.evaluate(cameras);
    const auto segments = model.segments();
    nlohmann::json out{{"coverage", terms.coverage},
                       {"utilization", terms.utilization},
                       {"repulsion", terms.repulsion},
                       {"reward", terms.reward},
                       {"targetPerimeter", camcov::reward::targetPerimeter(model.world())}};
    if (scene.isWeighted()) out["weightedCoverage"] = terms.weightedCoverage;
    out["cameras"] = nlohmann::json::array();
    for (unsigned j = 0; j < cameras.size(); ++j)
      out["cameras"].push_back({{"visibleLength", camcov::reward::visibleLengthOf(segments, j)}});
    out["segments"] = nlohmann::json::array();
    for (const auto& s : segments) {
      nlohmann::json seenBy = nlohmann::json::array();  // camera numbers, as inspect lists them
      for (unsigned j = 0; j < cameras.size(); ++j) {
        if (s.visibleBy.contains(j)) seenBy.push_back(j);
      }
      out["segments"].push_back({{"target", camcov::kinematics::targetId(model.world(), s.target)},
                                 {"edge", s.edge},
                                 {"a", {s.a.x, s.a.y}},
                                 {"b", {s.b.x, s.b.y}},
                                 {"visibleBy", seenBy}});
    }
    return out.dump();
  } catch (const std::exception& error) {
    return failure(error).dump();
  }
}

nlohmann::json points(std::span<const camcov::geometry::Vec2> ring) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : ring)
    out.push_back({v.x, v.y});
  return out;
}

nlohmann::json tracedEdge(const camcov::kinematics::World& world,
                          const camcov::visibility::TracedEdge& e) {
  using Kind = camcov::visibility::TracedEdge::Kind;
  if (e.kind == Kind::None) return nullptr;
  if (e.kind == Kind::Wedge) return {{"wedge", true}};
  using camcov::visibility::RingKind;
  const std::string ring = e.ring == RingKind::Boundary ? "boundary"
                           : e.ring == RingKind::Target ? "target"
                                                        : "obstacle";
  const std::uint32_t owner =
      e.ring == RingKind::Target     ? camcov::kinematics::targetId(world, e.owner)
      : e.ring == RingKind::Obstacle ? camcov::kinematics::obstacleId(world, e.owner)
                                     : 0;
  return {{"ring", ring},
          {"owner", owner},
          {"edge", e.edge},
          {"a", {e.a.x, e.a.y}},
          {"b", {e.b.x, e.b.y}}};
}

// The scene and instant the playground asked for last: a drag moves a camera and asks again,
// and must not pay for reading, checking and placing a large scene every time.
struct Instant {
  std::string sceneText, name;
  double time = -1.0;
  std::optional<camcov::scene::Scene> scene;
  std::optional<camcov::kinematics::Kinematics> kinematics;
  std::optional<camcov::reward::RewardModel> model;

  void take(const std::string& text, const std::string& fileName, double t) {
    namespace cc = camcov;
    if (!scene || text != sceneText || fileName != name) {
      sceneText.clear();  // until the new scene is read whole
      scene.reset();
      scene = cc::scene::parseScene(text, fileName);
      kinematics.emplace(*scene);
      model.emplace(cc::params::Parameters{}.reward, cc::scene::lenses(*scene));
      sceneText = text;
      name = fileName;
      time = -1.0;
    }
    if (t != time) {
      model->setWorld(kinematics->worldAt(t));
      time = t;
    }
  }
};
Instant last;

// Everything the visibility playground draws at one instant: the world, each camera's field
// of view, S with who sees each segment, the terms of the team and of each camera alone; for
// segment `reasonsFor` of S (≥ 0), why each camera that does not see it does not; and
// (traceCamera ≥ 0) that camera's sweep event by event. {"error": the validator's words} for a
// scene or poses camcov would refuse.
std::string explain(const std::string& sceneText, const std::string& name, double time,
                    const std::string& posesText, int traceCamera, int reasonsFor) {
  try {
    namespace cc = camcov;
    // A page's link may say any time (the playground's #t=): camcov inspect's range.
    if (!(time >= 0.0 && time <= 1e9))
      throw std::invalid_argument("time must lie in [0, 1e9] s, is " + std::to_string(time));
    last.take(sceneText, name, time);
    const cc::scene::Scene& scene = *last.scene;
    const cc::kinematics::Kinematics& kinematics = *last.kinematics;
    cc::reward::RewardModel& model = *last.model;
    std::vector<Pose> cameras;
    if (posesText.empty()) {
      for (const auto& c : scene.cameras)
        cameras.push_back(c.initial);
    } else {
      cameras = cc::scene::parseCameraPoses(posesText, "poses");
    }
    if (cameras.size() != scene.cameras.size())
      throw std::invalid_argument("poses: one pose per camera of the scene");
    const std::vector<cc::scene::Lens> lenses = cc::scene::lenses(scene);
    const cc::params::Parameters p;
    const cc::kinematics::World& world = model.world();
    const cc::reward::RewardTerms terms = model.evaluate(cameras);
    const std::vector<cc::visibility::Segment> segments(model.segments().begin(),
                                                        model.segments().end());
    const auto termsJson = [&](const cc::reward::RewardTerms& t) {
      nlohmann::json j{{"coverage", t.coverage},
                       {"utilization", t.utilization},
                       {"repulsion", t.repulsion},
                       {"reward", t.reward}};
      if (scene.isWeighted()) j["weightedCoverage"] = t.weightedCoverage;
      return j;
    };
    nlohmann::json out{{"time", time}, {"terms", termsJson(terms)}};
    out["boundary"] = points(world.boundary);
    // An object by its scene index, its ring now and where its shape's frame is (a page that
    // moves a vertex edits the shape through it).
    const auto placed = [&](std::uint32_t id, const cc::geometry::Ring& ring,
                            const cc::kinematics::ObjectPose& pose) {
      return nlohmann::json{{"id", id},
                            {"ring", points(ring)},
                            {"reference", {pose.reference.x, pose.reference.y}},
                            {"angle", pose.angle}};
    };
    out["targets"] = nlohmann::json::array();
    for (std::size_t i = 0; i < world.targets.size(); ++i) {
      const std::uint32_t id = cc::kinematics::targetId(world, i);
      out["targets"].push_back(placed(id, world.targets[i], kinematics.targetPose(id, time)));
      if (!world.targetEdgeWeights.empty())
        out["targets"].back()["weights"] = world.targetEdgeWeights[i];
    }
    out["obstacles"] = nlohmann::json::array();
    for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
      const std::uint32_t id = cc::kinematics::obstacleId(world, i);
      out["obstacles"].push_back(placed(id, world.obstacles[i], kinematics.obstaclePose(id, time)));
    }
    // Each camera: its field of view, and its terms alone (reward::termsAlone).
    cc::visibility::Sweep sweep;
    cc::geometry::Ring view;
    out["cameras"] = nlohmann::json::array();
    for (std::size_t j = 0; j < cameras.size(); ++j) {
      sweep.fieldOfViewPolygon(model.occluders(), cameras[j], lenses[j], view);
      const cc::reward::RewardTerms t =
          cc::reward::termsAlone(world, segments, cameras, lenses, j, p.reward);
      out["cameras"].push_back({{"pose", {cameras[j].x, cameras[j].y, cameras[j].yaw}},
                                {"halfFov", lenses[j].halfFov},
                                {"view", points(view)},
                                {"visibleLength", cc::reward::visibleLengthOf(segments, j)},
                                {"terms", termsJson(t)}});
    }
    // S by columns (a large target's thousands of segments as objects cost a drag most of
    // its time): target and edge, the ends ax, ay, bx, by in a row, and who sees each.
    nlohmann::json target = nlohmann::json::array(), edge = nlohmann::json::array(),
                   ends = nlohmann::json::array(), visibleBy = nlohmann::json::array();
    for (const cc::visibility::Segment& s : segments) {
      target.push_back(cc::kinematics::targetId(world, s.target));
      edge.push_back(s.edge);
      for (const double v : {s.a.x, s.a.y, s.b.x, s.b.y})
        ends.push_back(v);
      nlohmann::json seenBy = nlohmann::json::array();
      for (unsigned j = 0; j < cameras.size(); ++j) {
        if (s.visibleBy.contains(j)) seenBy.push_back(j);
      }
      visibleBy.push_back(std::move(seenBy));
    }
    out["segments"] = {{"target", std::move(target)},
                       {"edge", std::move(edge)},
                       {"ends", std::move(ends)},
                       {"visibleBy", std::move(visibleBy)}};
    // Why each camera that does not see segment `reasonsFor` does not: O(n) a camera
    // (unseen_reason.h), so for the segment asked about only.
    if (reasonsFor >= 0 && static_cast<std::size_t>(reasonsFor) < segments.size()) {
      const cc::visibility::Segment& s = segments[reasonsFor];
      nlohmann::json why = nlohmann::json::array();
      for (unsigned j = 0; j < cameras.size(); ++j) {
        if (s.visibleBy.contains(j)) {
          why.push_back(nullptr);
        } else {
          why.push_back(cc::visibility::describeUnseen(
              world, cc::visibility::whyUnseen(world, cameras[j], lenses[j], s)));
        }
      }
      out["reasons"] = {{"segment", reasonsFor}, {"why", std::move(why)}};
    }
    if (traceCamera >= 0 && static_cast<std::size_t>(traceCamera) < cameras.size()) {
      cc::visibility::SweepTrace trace;
      sweep.trace(model.occluders(), cameras[traceCamera], lenses[traceCamera], trace);
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
      out["trace"] = {{"camera", traceCamera},
                      {"blind", trace.blind},
                      {"front", tracedEdge(world, trace.frontBefore)},
                      {"events", events}};
    }
    return out.dump();
  } catch (const std::exception& error) {
    return failure(error).dump();
  }
}

}  // namespace

EMSCRIPTEN_BINDINGS(camcov_engine) {
  emscripten::function("validate", &validate);
  emscripten::function("inspect", &inspect);
  emscripten::function("explain", &explain);
}
