#pragma once
// What Python holds of a scene: the scene as loaded, the FNV-1a hash of its file (as a run's
// metadata records it) and the file name it was loaded from, plus its kinematics.
#include <cstdint>
#include <string>

#include "kinematics/kinematics.h"
#include "params/parameters.h"
#include "scene/scene.h"

namespace camcov::python {

struct PythonScene {
  PythonScene(scene::Scene s, std::uint64_t h, std::string f)
      : scene(std::move(s)), hash(h), file(std::move(f)), kinematics(scene) {}
  scene::Scene scene;
  std::uint64_t hash = 0;
  std::string file;  // as given; empty for a scene parsed from text
  kinematics::Kinematics kinematics;
};

// Parameters from Python: None (the defaults), or a dict of "group.name" keys (as `camcov
// params --describe` lists them, like --set) to numbers or booleans. InputError as the CLI's.
params::Parameters parametersFrom(const pybind11::handle& values);
// Every parameter as a nested dict ({"sim": {"dt": 0.1, ...}, ...}), as `camcov params` prints.
pybind11::object parametersToPython(const params::Parameters& p);

}  // namespace camcov::python
