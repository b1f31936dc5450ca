#pragma once
// What every importer fuzzer asks of a recording its reader accepted: the scene built from it
// (the window a person would most likely ask for, and the busiest 10 s) is either refused with
// an InputError or is a file the scene loader accepts, as `camcov import` validates before it
// writes. Any other exception, a crash, a hang or a sanitizer report is a bug.
#include <cstdio>
#include <cstdlib>

#include "import/recording.h"
#include "import/scene_builder.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace camcov::fuzz {

inline void buildAndLoad(const import::Recording& recording) {
  import::SceneOptions whole, busiest;
  busiest.busiest = 10.0;
  for (const import::SceneOptions* options : {&whole, &busiest}) {
    import::BuiltScene built;
    try {
      built = import::buildScene(recording, *options);
    } catch (const InputError&) {
      continue;  // nothing to make a scene of, said so
    }
    try {
      scene::parseScene(built.scene.dump(1), "imported.json");
    } catch (const InputError& e) {
      std::fprintf(stderr, "import fuzzer: the built scene does not load: %s\n", e.what());
      std::abort();
    }
  }
}

}  // namespace camcov::fuzz
