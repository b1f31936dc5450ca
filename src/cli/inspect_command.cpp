// `camcov inspect SCENE --time T [--cameras FILE] [--json] [--camera J -o debug.svg]`: the
// visibility sweep's answer for one instant — every segment of S with visibleBy, and the
// reward's terms (paper IV-A, IV-B) — and, with -o, the sweep of camera J drawn for debugging.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/parameter_options.h"
#include "inspection/inspection_json.h"
#include "kinematics/kinematics.h"
#include "records/atomic_file.h"
#include "reward/reward_model.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "viz/sweep_debug_svg.h"

namespace camcov::cli {
namespace {

struct InspectOptions {
  std::string scene;
  double time = 0.0;
  std::string camerasFile;
  bool json = false;
  std::string debugSvg;  // the sweep debugger's drawing, if asked for
  unsigned camera = 0;   // the camera it traces
  ParameterOptions parameters;
};

int inspect(const InspectOptions& o) {
  if (!o.debugSvg.empty()) viz::requireSvg(o.debugSvg);  // a wrong extension fails before any work
  const scene::Scene s = scene::loadScene(o.scene);
  const params::Parameters p = o.parameters.resolve();
  const std::vector<geometry::Pose> cameras =
      o.camerasFile.empty() ? scene::initialPoses(s) : scene::loadCameraPosesFor(o.camerasFile, s);
  if (!o.debugSvg.empty()) {
    if (o.camera >= cameras.size()) {
      throw InputError(fmt::format("--camera {}: out of range, the cameras are numbered 0 to {}",
                                   o.camera, cameras.size() - 1));
    }
    records::writeFileAtomically(
        o.debugSvg, viz::sweepDebugSvg(viz::buildSweepDebug(s, o.time, cameras, o.camera)));
  }
  reward::RewardModel model(p.reward, scene::lenses(s));
  model.setWorld(kinematics::Kinematics(s).worldAt(o.time));
  const reward::RewardTerms terms = model.evaluate(cameras);
  const auto segments = model.segments();

  if (o.json) {
    std::cout << inspection::inspectionJson(s, o.time, cameras, model, terms).dump(2) << "\n";
    return 0;
  }
  std::cout << fmt::format(
      "{} at t = {} s: coverage {:.4f}, utilization {:.4f}, repulsion {:.4f}, "
      "reward {:.4f}\n",
      s.name, o.time, terms.coverage, terms.utilization, terms.repulsion, terms.reward);
  if (s.isWeighted())
    std::cout << fmt::format("  weighted coverage {:.4f}\n", terms.weightedCoverage);
  for (unsigned j = 0; j < cameras.size(); ++j) {
    std::cout << fmt::format("  camera {}: ({:.3f}, {:.3f}) yaw {:.1f}°, sees {:.3f} m\n", j,
                             cameras[j].x, cameras[j].y, geometry::radToDeg(cameras[j].yaw),
                             reward::visibleLengthOf(segments, j));
  }
  for (const auto& seg : segments) {
    std::cout << fmt::format(
        "  target {} edge {}: ({:.3f}, {:.3f}) -> ({:.3f}, {:.3f})  {:.3f} m  "
        "seen by {}\n",
        kinematics::targetId(model.world(), seg.target), seg.edge, seg.a.x, seg.a.y, seg.b.x,
        seg.b.y, visibility::length(seg),
        !seg.visibleBy.empty() ? inspection::cameraNumbers(seg.visibleBy).dump() : "nobody");
  }
  if (!o.debugSvg.empty()) std::cout << fmt::format("  -> {}\n", o.debugSvg);
  return 0;
}

}  // namespace

Registration addInspectCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "inspect",
      "Visibility at one instant: the segments S with visibleBy, coverage and reward; with -o, "
      "one camera's sweep drawn for debugging");
  auto o = std::make_shared<InspectOptions>();
  cmd->add_option("scene", o->scene, "scene file (JSON)")->required();
  cmd->add_option("--time,-t", o->time, "time t in seconds")->check(within(0.0, 1e9));
  cmd->add_option("--cameras", o->camerasFile,
                  "JSON list of poses [{\"x\":..,\"y\":..,\"yaw_deg\":..}] (default: the scene's "
                  "initial cameras)");
  cmd->add_flag("--json", o->json, "print JSON instead of a table");
  auto* out = cmd->add_option("--out,-o", o->debugSvg,
                              "also draw the polar sweep of one camera for debugging: its events "
                              "in order, the edge in front after each, S with visibleBy (.svg)");
  cmd->add_option("--camera", o->camera, "the camera whose sweep -o draws (default 0)")->needs(out);
  o->parameters.addTo(*cmd);
  return {cmd, [o] { return inspect(*o); }};
}

}  // namespace camcov::cli
