#pragma once
// The parts of the `camcov` Python module, each defined in its own file (module.cpp calls
// them in order: later parts use the classes of earlier ones).
#include <pybind11/pybind11.h>

namespace camcov::python {

void bindScene(pybind11::module_& m);         // scene_bindings.cpp: Scene, World, parameters
void bindVisibility(pybind11::module_& m);    // visibility_bindings.cpp: S, visibleBy, reward
void bindRuns(pybind11::module_& m);          // run_bindings.cpp: runs, Python controllers, bench
void bindInterruption(pybind11::module_& m);  // interruption.cpp: Ctrl-C stops long calls
void bindEnvironment(pybind11::module_& m);   // environment_bindings.cpp: episodes, policies
// With the GIL: keeps the Python error being raised (a KeyboardInterrupt in a controller) and
// stops the work; the call then raises it instead of returning (interruption.cpp).
void keepPythonError();

}  // namespace camcov::python
