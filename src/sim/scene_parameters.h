#pragma once
// The parameters a run of a scene uses: its run length (run_length.h), and the scene's settings
// of what a camera knows ("knowledge" and "comms", scene::Scene::knowledgeSettings), each where
// the parameters keep its default, so that --set and a parameter file still say otherwise. One
// rule for `camcov run`, the batch, and Python's runs and environments.
#include <string>

#include "params/parameters.h"
#include "scene/scene.h"

namespace camcov::sim {

// InputError naming `sceneFile` (where the scene was read from) and the key where its settings
// are not the parameter table's names, types or ranges.
params::Parameters forScene(params::Parameters p, const scene::Scene& scene,
                            const std::string& sceneFile, bool durationGiven);

}  // namespace camcov::sim
