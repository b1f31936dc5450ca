// The `camcov` Python module: scenes, the world at time t, visibility and reward for numpy
// poses, runs of the built-in methods and of Python controllers, batches and reports. Errors
// in the input raise camcov.InputError (a ValueError) with the CLI's message.
#include <pybind11/pybind11.h>

#include "camcov/version.h"
#include "python/bindings.h"
#include "util/input_error.h"

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  m.doc() =
      "camcov: dynamic multi-target coverage with robotic cameras (Hönig & Ayanian).\n\n"
      "load_scene(file) -> Scene; Scene.world_at(t) -> World (targets, obstacles, boundary);\n"
      "Visibility(world, scene) -> what the scene's cameras see at given poses, and the reward;\n"
      "run(scene_file, method) and simulate(scene_file, controller) -> Run; bench(...) is\n"
      "`camcov bench`; report(folder) is `camcov report`. See docs/python.md.";
  m.attr("__version__") = camcov::kVersion;
  py::register_exception<camcov::InputError>(m, "InputError", PyExc_ValueError).attr("__doc__") =
      "Bad input (a scene, parameters, an option): the message the CLI prints with exit code 2, "
      "naming the file and the JSON path. A ValueError.";
  camcov::python::bindScene(m);
  camcov::python::bindVisibility(m);
  camcov::python::bindRuns(m);
  camcov::python::bindInterruption(m);
  camcov::python::bindEnvironment(m);
}
