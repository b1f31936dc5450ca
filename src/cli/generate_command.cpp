// `camcov generate -o scene.json [--targets N --cameras M ...]`: a seeded large scene
// (scene/scene_generator.h). The scene is validated by the loader before it is written,
// atomically: bad options leave no file behind.
// `camcov generate --family NAME --count N --seed S -o DIR`: N scenes of a named family
// (scene/scene_families.h), DIR/<family>-<seed>.json for seeds S to S+N-1, each validated by
// the loader before it is written; `--family list` prints the families.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>

#include "cli/command.h"
#include "cli/number_options.h"
#include "records/atomic_file.h"
#include "scene/scene_families.h"
#include "scene/scene_generator.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace camcov::cli {
namespace {

constexpr int kMaxCount = 100000;

struct GenerateOptions {
  std::string out;
  // Pairs as given; the generator checks the values, so every bad value gets its message.
  std::vector<double> field;
  std::vector<double> targetSize;
  scene::GeneratorOptions scene;
  std::string family;  // a family's name, or "list"
  bool listFamilies = false;
  int count = 1;
  std::vector<const CLI::Option*> sceneOnly;  // options of one large scene, not of a family
  const CLI::Option* countOption = nullptr;
};

int generate(GenerateOptions o) {
  if (o.out.empty()) throw InputError("generate: -o/--out is required: the scene file to write");
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

// Which side of the family's split the seeds first..last are on, for the summary line.
std::string seedRole(const scene::SeedSplit& split, std::uint64_t first, std::uint64_t last) {
  const auto holds = [&](const scene::SeedRange& r) { return r.first <= first && last <= r.last; };
  if (holds(split.tune)) return "tune seeds";
  if (holds(split.test)) return "test seeds";
  return fmt::format("neither all tune seeds ({}-{}) nor all test seeds ({}-{})", split.tune.first,
                     split.tune.last, split.test.first, split.test.last);
}

// Seeds after the first: --count is at least 1 (its check).
std::uint64_t moreSeeds(const GenerateOptions& o) {
  return static_cast<std::uint64_t>(o.count - 1);
}

void checkFamilyOptions(const GenerateOptions& o) {
  for (const CLI::Option* option : o.sceneOnly) {
    if (option->count() > 0) {
      throw InputError(fmt::format(
          "generate: {} does not apply with --family: a family draws it for every scene",
          option->get_name()));
    }
  }
  if (o.out.empty()) {
    throw InputError("generate: -o/--out is required with --family: the folder to write into");
  }
  if (o.scene.seed > std::numeric_limits<std::uint64_t>::max() - moreSeeds(o)) {
    throw InputError(fmt::format("generate: seeds {} and {} more do not fit in 64 bits",
                                 o.scene.seed, moreSeeds(o)));
  }
  if (std::filesystem::exists(o.out) && !std::filesystem::is_directory(o.out)) {
    throw InputError(
        fmt::format("generate: {} is not a folder: with --family, -o names the "
                    "folder the scenes are written into",
                    o.out));
  }
}

// Every scene is validated by the loader before it is written; one that fails would be a bug
// of the generator, not bad input, so it is an internal error (exit 1).
std::string validatedScene(const scene::SceneFamily& family, std::uint64_t seed) {
  const std::string name = scene::familySceneFileName(family.name, seed);
  const std::string text = scene::generateFamilyScene(family, seed).dump(1) + "\n";
  try {
    scene::parseScene(text, name);
  } catch (const InputError& e) {
    throw std::logic_error(fmt::format("generated scene fails validation: {}", e.what()));
  }
  return text;
}

int generateFamily(const GenerateOptions& o) {
  if (o.listFamilies || o.family == "list") {
    std::cout << scene::familyTable();
    return 0;
  }
  const scene::SceneFamily& family = scene::sceneFamily(o.family);
  checkFamilyOptions(o);
  const std::filesystem::path dir = o.out;
  records::NewFolderGuard guard(dir);  // a failure leaves no folder it made
  const std::uint64_t first = o.scene.seed, last = first + moreSeeds(o);
  for (std::uint64_t seed = first;; ++seed) {  // stops at `last`, even the largest seed
    records::writeFileAtomically(dir / scene::familySceneFileName(family.name, seed),
                                 validatedScene(family, seed));
    if (seed == last) break;
  }
  guard.keep();
  std::cout << fmt::format("{}: {} scene(s) of family {}, seeds {} to {} ({})\n", dir.string(),
                           o.count, family.name, first, last, seedRole(family.seeds, first, last));
  return 0;
}

int run(GenerateOptions o) {
  if (!o.family.empty() || o.listFamilies) return generateFamily(o);
  if (o.countOption->count() > 0) {
    throw InputError("generate: --count applies only with --family");
  }
  return generate(std::move(o));
}

}  // namespace

Registration addGenerateCommand(CLI::App& app) {
  auto o = std::make_shared<GenerateOptions>();
  scene::GeneratorOptions& g = o->scene;
  auto* cmd = app.add_subcommand(
      "generate",
      "Make a large seeded scene: N targets on short square loops, M cameras at random places "
      "or N scenes of a named family (--family)");
  cmd->add_option("--out,-o", o->out,
                  "scene file to write (.json); with --family, the folder to write into");
  cmd->add_option("--family", o->family,
                  "write scenes of this family, <family>-<seed>.json; 'list': print the families "
                  "with their ranges and tune/test seeds");
  cmd->add_flag("--list-families", o->listFamilies, "print the families (as --family list)");
  o->countOption =
      cmd->add_option(
             "--count", o->count,
             fmt::format("with --family: number of scenes, seeds S to S+N-1 (1 to {})", kMaxCount))
          ->check(within(1, kMaxCount))
          ->capture_default_str();
  cmd->add_option("--targets", g.targets, "number of targets N (1 to 10000)")
      ->capture_default_str();
  cmd->add_option("--cameras", g.cameras,
                  fmt::format("number of cameras M (1 to {})", scene::kMaxCameras))
      ->capture_default_str();
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
  cmd->add_option("--seed", g.seed,
                  "random seed: the same options and seed, the same file; with --family, the "
                  "first seed")
      ->capture_default_str();
  cmd->add_option("--description", g.description,
                  "the scene's description (default: one saying what was generated)");
  for (const char* name : {"--targets", "--cameras", "--vertices", "--field", "--target-size",
                           "--loop", "--target-speed", "--camera-speed", "--camera-turn", "--fov",
                           "--clearance", "--description"}) {
    o->sceneOnly.push_back(cmd->get_option(name));
  }
  return {cmd, [o] { return run(*o); }};
}

}  // namespace camcov::cli
