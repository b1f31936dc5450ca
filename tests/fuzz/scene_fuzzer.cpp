// libFuzzer target: bytes -> scene::parseScene (JSON with WKT inside). A bad file must end in
// an InputError (SceneError) and nothing else: any other exception, a crash or a sanitizer
// report is a bug. A file the loader accepts must then be usable by the stages that consume
// it, so an accepted scene is also placed in time (kinematics) and swept (visibility) at a
// few instants, and every coordinate must stay finite.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "kinematics/kinematics.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "visibility/sweep.h"

namespace {

using namespace camcov;

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "scene fuzzer: %s\n", what);
  std::abort();
}

bool finite(const geometry::Ring& ring) {
  for (const geometry::Vec2 v : ring) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) return false;
  }
  return true;
}

void checkWorld(const kinematics::World& world) {
  if (!finite(world.boundary)) fail("non-finite boundary");
  for (const auto* rings : {&world.targets, &world.obstacles}) {
    for (const geometry::Ring& ring : *rings) {
      if (!finite(ring)) fail("non-finite object vertex");
    }
  }
}

// An accepted scene, at instants up to the latest `camcov state`/`inspect`/`render` accept.
void exercise(const scene::Scene& s) {
  const kinematics::Kinematics kinematics(s);
  std::vector<geometry::Pose> cameras;
  for (const auto& c : s.cameras)
    cameras.push_back(c.initial);
  visibility::Sweep sweep;
  std::vector<visibility::Segment> segments;
  for (const double t : {0.0, 0.1, 7.3, 1e3, 1e9}) {
    const kinematics::World world = kinematics.worldAt(t);
    checkWorld(world);
    const visibility::Occluders occluders(world);
    sweep.segments(occluders, cameras, scene::lenses(s), segments);
    for (const visibility::Segment& segment : segments) {
      if (!std::isfinite(segment.a.x + segment.a.y + segment.b.x + segment.b.y))
        fail("non-finite segment");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  scene::Scene s;
  try {
    s = scene::parseScene(text, "fuzz.json");
  } catch (const InputError&) {
    return 0;  // rejected with a message: the loader's job done
  }
  exercise(s);
  return 0;
}
