// The `camcov` Python module: scenes, the world at time t, visibility and reward for numpy
// poses, runs of the built-in methods and of Python controllers, batches and reports. Errors
// in the input raise camcov.InputError (a ValueError) with the CLI's message.
#include <pybind11/pybind11.h>

#include "camcov/version.h"
#include "python/bindings.h"
#include "util/input_error.h"

PYBIND11_MODULE(camcov, m) {
  namespace py = pybind11;
  m.doc() = "camcov: dynamic multi-target coverage with robotic cameras (Hönig & Ayanian)";
  m.attr("__version__") = camcov::kVersion;
  py::register_exception<camcov::InputError>(m, "InputError", PyExc_ValueError);
  camcov::python::bindScene(m);
  camcov::python::bindVisibility(m);
  camcov::python::bindRuns(m);
  camcov::python::bindInterruption(m);
}
