// The engine's JavaScript face (embind): a scene's text in, what `camcov validate` and
// `camcov inspect --json` would say out, computed by the same C++ as the program and written
// by the same writers (src/inspection). Everything crosses as JSON text, so that a page needs
// no types of ours.
#include <emscripten/bind.h>

#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "inspection/explanation_json.h"
#include "inspection/inspection_json.h"
#include "kinematics/kinematics.h"
#include "params/parameters.h"
#include "reward/reward_model.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"

namespace {

namespace cc = camcov;
using cc::geometry::Pose;

nlohmann::json failure(const std::exception& error) {
  return {{"error", error.what()}};
}

// {"ok": true} for a scene `camcov validate` accepts, else {"error": its message}.
std::string validate(const std::string& sceneText, const std::string& name) {
  try {
    cc::scene::parseScene(sceneText, name);
    return nlohmann::json{{"ok", true}}.dump();
  } catch (const std::exception& error) {
    return failure(error).dump();
  }
}

// `camcov inspect SCENE --time T [--cameras POSES] --json`, the same JSON. `posesText` as a
// camera poses file ([{"x":..,"y":..,"yaw_deg":..}]), taken as inspect takes the file; empty:
// the scene's initial poses.
std::string inspect(const std::string& sceneText, const std::string& name, double time,
                    const std::string& posesText) {
  try {
    const cc::scene::Scene scene = cc::scene::parseScene(sceneText, name);
    const std::vector<Pose> cameras =
        posesText.empty() ? cc::scene::initialPoses(scene)
                          : cc::scene::parseCameraPosesFor(posesText, "poses", scene);
    cc::reward::RewardModel model(cc::params::Parameters{}.reward, cc::scene::lenses(scene));
    model.setWorld(cc::kinematics::Kinematics(scene).worldAt(time));
    const cc::reward::RewardTerms terms = model.evaluate(cameras);
    return cc::inspection::inspectionJson(scene, time, cameras, model, terms).dump();
  } catch (const std::exception& error) {
    return failure(error).dump();
  }
}

// The scene and instant the playground asked for last: a drag moves a camera and asks again,
// and must not pay for reading, checking and placing a large scene every time.
struct Instant {
  std::string sceneText, name;
  double time = -1.0;
  std::optional<cc::scene::Scene> scene;
  std::optional<cc::kinematics::Kinematics> kinematics;
  std::optional<cc::reward::RewardModel> model;

  void take(const std::string& text, const std::string& fileName, double t) {
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

// Everything the visibility playground draws at one instant (inspection::explanationJson), with
// the reasons for segment `reasonsFor` of S and camera `traceCamera`'s sweep (each ≥ 0 when
// asked); {"error": the validator's words} for a scene or poses camcov would refuse.
std::string explain(const std::string& sceneText, const std::string& name, double time,
                    const std::string& posesText, int traceCamera, int reasonsFor) {
  try {
    // A page's link may say any time (the playground's #t=): camcov inspect's range.
    if (!(time >= 0.0 && time <= 1e9))
      throw std::invalid_argument("time must lie in [0, 1e9] s, is " + std::to_string(time));
    last.take(sceneText, name, time);
    const std::vector<Pose> cameras = posesText.empty()
                                          ? cc::scene::initialPoses(*last.scene)
                                          : cc::scene::parseCameraPoses(posesText, "poses");
    if (cameras.size() != last.scene->cameras.size())
      throw std::invalid_argument("poses: one pose per camera of the scene");
    return cc::inspection::explanationJson(*last.scene, *last.kinematics, time, cameras,
                                           *last.model, {traceCamera, reasonsFor})
        .dump();
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
