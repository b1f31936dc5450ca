// `camcov generate -o scene.json [--targets N --cameras M ...]`: a seeded large scene (issue
// 23; scene/scene_generator.h). The scene is validated by the loader before it is written,
// atomically: bad options leave no file behind.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cli/command.h"
#include "records/atomic_file.h"
#include "scene/scene_generator.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace camcov::cli {
namespace {

struct GenerateOptions {
  std::string out;
  // Pairs as given; the generator checks the values, so every bad value gets its message.
  std::vector<double> field;
  std::vector<double> targetSize;
  scene::GeneratorOptions scene;
};

int generate(GenerateOptions o) {
  if (!o.field.empty()) {
    o.scene.fieldWidth = o.field[0];
    o.scene.fieldHeight = o.field[1];
  }
  if (!o.targetSize.empty()) {
    o.scene.targetLength = o.targetSize[0];
    o.scene.targetWidth = o.targetSize[1];
  }
  const std::string text = scene::generateScene(o.scene).dump(1) + "\n";
  const scene::Scene s = scene::parseScene(text, o.out);
  records::writeFileAtomically(o.out, text);
  std::cout << fmt::format("{}: {} target(s) of {} vertices, {} camera(s), seed {}\n", o.out,
                           s.targets.size(), s.targets.front().shape.size(), s.cameras.size(),
                           o.scene.seed);
  return 0;
}

}  // namespace

Registration addGenerateCommand(CLI::App& app) {
  auto o = std::make_shared<GenerateOptions>();
  scene::GeneratorOptions& g = o->scene;
  auto* cmd = app.add_subcommand(
      "generate",
      "Make a large seeded scene: N targets on short square loops, M cameras at random places "
      "(issue 23)");
  cmd->add_option("--out,-o", o->out, "scene file to write (.json)")->required();
  cmd->add_option("--targets", g.targets, "number of targets N (1 to 10000)")
      ->capture_default_str();
  cmd->add_option("--cameras", g.cameras, "number of cameras M (1 to 64)")->capture_default_str();
  cmd->add_option("--vertices", g.vertices,
                  "vertices of each target V (3 to 100000): a polygon inscribed in an ellipse, "
                  "4 a rectangle")
      ->capture_default_str();
  cmd->add_option("--field", o->field,
                  fmt::format("field width,height in m, centred at 0 (default {},{})", g.fieldWidth,
                              g.fieldHeight))
      ->delimiter(',')
      ->expected(2);
  cmd->add_option("--target-size", o->targetSize,
                  fmt::format("length,width of every target's bounding box in m (default {},{})",
                              g.targetLength, g.targetWidth))
      ->delimiter(',')
      ->expected(2);
  cmd->add_option("--loop", g.loopSize,
                  "side of each target's square loop, m (random centre and orientation); 0: "
                  "static targets")
      ->capture_default_str();
  cmd->add_option("--target-speed", g.targetSpeed, "speed of every target along its loop, m/s")
      ->capture_default_str();
  cmd->add_option("--camera-speed", g.cameraSpeed, "v_max of every camera, m/s")
      ->capture_default_str();
  cmd->add_option("--camera-turn", g.cameraTurnRate, "angular speed limit of every camera, rad/s")
      ->capture_default_str();
  cmd->add_option("--fov", g.cameraHalfFovDeg, "half-angle field of view θ, degrees")
      ->capture_default_str();
  cmd->add_option("--clearance", g.clearance,
                  "least distance of every camera from every target's loop region, the "
                  "boundary and the other cameras, m (target regions keep it from the boundary "
                  "too)")
      ->capture_default_str();
  cmd->add_option("--seed", g.seed, "random seed: the same options and seed, the same file")
      ->capture_default_str();
  cmd->add_option("--description", g.description,
                  "the scene's description (default: one saying what was generated)");
  return {cmd, [o] { return generate(*o); }};
}

}  // namespace camcov::cli
