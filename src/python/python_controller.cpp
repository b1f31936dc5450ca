#include "python/python_controller.h"

#include <pybind11/eval.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "python/bindings.h"
#include "python/numpy_arrays.h"
#include "python/python_scene.h"
#include "util/input_error.h"
#include "util/interruption.h"

namespace camcov::python {

PythonController::PythonController(py::object callable) : callable_(std::move(callable)) {}

PythonController::~PythonController() {
  // The reference goes back to Python, which needs the GIL, wherever the run ends.
  py::gil_scoped_acquire gil;
  callable_ = py::object();
}

void PythonController::control(const control::Observation& o,
                               std::span<scene::CameraCommand> commands) {
  py::gil_scoped_acquire gil;
  try {
    auto observation = std::make_unique<PythonObservation>();
    observation->time = o.time;
    observation->world = o.world;
    observation->cameras.assign(o.cameras.begin(), o.cameras.end());
    observation->seen.assign(o.seen.begin(), o.seen.end());
    observation->terms = o.terms;
    observation->own.assign(o.own.begin(), o.own.end());
    const py::object result = callable_(py::cast(std::move(observation)));
    // velocities, or a tuple (velocities, goals) or (velocities, goals, events)
    const std::size_t parts =
        py::isinstance<py::tuple>(result) && py::len(result) >= 2 && py::len(result) <= 3
            ? py::len(result)
            : 1;
    const auto velocities =
        rowsFromArray(parts > 1 ? result[py::int_(0)] : result, "controller's velocities");
    if (velocities.size() != commands.size()) {
      throw py::value_error("the controller returned " + std::to_string(velocities.size()) +
                            " velocities for " + std::to_string(commands.size()) + " cameras");
    }
    for (std::size_t j = 0; j < commands.size(); ++j) {
      // A method's bug shows as its run's error, not as a camera that silently stops.
      if (!std::isfinite(velocities[j].x) || !std::isfinite(velocities[j].y) ||
          !std::isfinite(velocities[j].yaw)) {
        throw py::value_error("the controller returned a velocity that is not finite for camera " +
                              std::to_string(j) + " at t = " + std::to_string(o.time) + " s");
      }
      commands[j] = {{velocities[j].x, velocities[j].y}, velocities[j].yaw};
    }
    goals_.assign(commands.size(), std::nullopt);
    if (parts > 1 && !result[py::int_(1)].is_none()) {
      // A row that is not all finite (NaN) says "no goal"; a goal is a pose a scene could hold.
      const auto goals = rowsFromArray(result[py::int_(1)], "controller's goals");
      if (goals.size() != commands.size()) throw py::value_error("one goal row per camera");
      for (std::size_t j = 0; j < goals.size(); ++j) {
        if (std::isfinite(goals[j].x) && std::isfinite(goals[j].y) && std::isfinite(goals[j].yaw)) {
          requireScenePoses(std::span(&goals[j], 1), "controller's goals");
          goals_[j] = goals[j];
        }
      }
    }
    if (parts > 2) takeEventsFrom(result[py::int_(2)], o.time, commands.size());
  } catch (py::error_already_set& e) {
    // Ctrl-C while the controller ran: the whole call stops, not just this run.
    if (e.matches(PyExc_KeyboardInterrupt)) {
      e.restore();
      keepPythonError();
      throw Interrupted();
    }
    // The Python error as text: the exception object must not outlive the GIL.
    throw std::runtime_error(std::string("Python controller: ") + e.what());
  }
}

void PythonController::takeEventsFrom(const py::handle& events, double time, std::size_t cameras) {
  for (const py::handle item : events) {
    if (!py::isinstance<py::dict>(item))
      throw py::value_error("controller's events: expected dicts with at least a 'kind'");
    const auto e = py::reinterpret_borrow<py::dict>(item);
    if (!e.contains("kind")) throw py::value_error("controller's events: an event without 'kind'");
    for (const char* key : {"kind", "detail", "reason"}) {
      if (e.contains(key) && !py::isinstance<py::str>(e[key]))
        throw py::value_error(std::string("controller's events: '") + key + "' must be a str");
    }
    control::ControlEvent event;
    event.time = time;
    event.kind = py::str(e["kind"]);
    if (e.contains("camera") && !py::isinstance<py::int_>(e["camera"]))
      throw py::value_error("controller's events: 'camera' must be an int");
    // An int too large for C++ reads as out of range, like any other camera it does not have.
    long long camera = e.contains("camera") ? PyLong_AsLongLong(e["camera"].ptr()) : -1;
    if (PyErr_Occurred()) {
      PyErr_Clear();
      camera = std::numeric_limits<long long>::max();
    }
    if (camera < -1 || camera >= static_cast<long long>(cameras))
      throw py::value_error("controller's events: camera " + std::string(py::str(e["camera"])) +
                            " of " + std::to_string(cameras));
    event.camera = static_cast<int>(camera);
    if (e.contains("detail")) event.detail = py::str(e["detail"]);
    if (e.contains("reason")) event.reason = py::str(e["reason"]);
    if (e.contains("path")) event.path = posesFromArray(e["path"], "controller's event path");
    events_.push_back(std::move(event));
  }
}

void PythonController::takeEvents(std::vector<control::ControlEvent>& out) {
  for (auto& e : events_)
    out.push_back(std::move(e));
  events_.clear();
}

namespace {

// What makes a Python method's results, as a batch records it: a hash of the whole source file
// that defines the factory (its helpers and constants change results too), or of the
// factory's own source where it has no file (a notebook cell), or of its bytecode where there
// is no source at all, and the version its author may set as the factory's `version`.
constexpr const char* kFingerprint = R"py(
def fingerprint(factory):
    import functools, hashlib, inspect, marshal, os
    f = inspect.unwrap(factory)
    while isinstance(f, functools.partial):
        f = f.func
    if not (inspect.isfunction(f) or inspect.ismethod(f) or inspect.isclass(f)):
        f = type(f)  # a callable object: its class holds the code
    digest = hashlib.sha256()
    try:
        path = inspect.getsourcefile(f)
    except TypeError:
        path = None
    if path and os.path.isfile(path):
        with open(path, "rb") as source:
            digest.update(source.read())
    else:
        try:
            digest.update(inspect.getsource(f).encode())
        except (OSError, TypeError):
            code = getattr(f, "__code__", None)
            digest.update(marshal.dumps(code) if code is not None else f.__qualname__.encode())
    version = getattr(factory, "version", None)
    return "python " + digest.hexdigest()[:16] + ("" if version is None else f" version {version}")
)py";

std::string fingerprintOf(const py::object& factory) {
  // Made once and never destroyed: a static py::object would be released after Python's
  // interpreter has finalized, at the process's exit.
  static const py::object* const fingerprint = [] {
    py::dict scope;
    py::exec(kFingerprint, scope);
    return new py::object(scope["fingerprint"]);
  }();
  return py::str((*fingerprint)(factory));
}

// The factory's attribute `name` as text, or `otherwise`.
std::string attributeOr(const py::object& factory, const char* name, std::string otherwise) {
  const py::object value = py::getattr(factory, name, py::none());
  return value.is_none() ? otherwise : std::string(py::str(value));
}

}  // namespace

control::Method pythonMethod(const std::string& name, py::object factory) {
  if (!control::isMethodName(name))
    throw InputError("method name '" + name + "': use lowercase letters, digits and '-'");
  if (control::findMethod(name) != nullptr)
    throw InputError("method name '" + name + "' is a built-in method's");
  const std::string description = attributeOr(factory, "description", name + " (Python)");
  const std::string color = attributeOr(factory, "color", "");
  const std::string identity = fingerprintOf(factory);
  // Copies of the method share the factory; the last one lets it go with the GIL.
  const std::shared_ptr<py::object> shared(new py::object(std::move(factory)), [](py::object* f) {
    py::gil_scoped_acquire gil;
    delete f;
  });
  return {
      name,
      description,
      color,
      control::Role::method,
      [shared](const scene::Scene& s, const params::Parameters& p,
               std::uint64_t seed) -> std::unique_ptr<control::Controller> {
        py::gil_scoped_acquire gil;
        try {
          auto scene = std::make_shared<PythonScene>(s, 0, "");
          return std::make_unique<PythonController>((*shared)(scene, parametersToPython(p), seed));
        } catch (const py::error_already_set& e) {
          throw std::runtime_error(std::string("Python controller factory: ") + e.what());
        }
      },
      identity};
}

}  // namespace camcov::python
