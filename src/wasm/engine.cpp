// The engine's JavaScript face (embind): a scene's text in, what `camcov validate` and
// `camcov inspect --json` would say out, computed by the same C++ as the program. Everything
// crosses as JSON text, so that a page needs no types of ours.
#include <emscripten/bind.h>

#include <exception>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "kinematics/kinematics.h"
#include "params/parameters.h"
#include "reward/metrics.h"
#include "reward/reward_model.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"

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
        if ((s.visibleBy >> j & 1u) != 0) seenBy.push_back(j);
      }
      out["segments"].push_back({{"target", camcov::kinematics::targetId(model.world(), s.target)},
                                 {"edge", s.edge},
                                 {"visibleBy", seenBy}});
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
}
