#pragma once
// A method written in Python: each step the simulator calls a Python callable with the step's
// Observation (as the C++ controllers see it) and takes back the velocities. The simulator
// runs without the GIL; the controller takes it only for the call.
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "control/controller.h"
#include "control/methods.h"
#include "kinematics/world.h"
#include "visibility/segment.h"

namespace camcov::python {

namespace py = pybind11;

// What a Python controller gets each step (camcov.Observation): copies, so a controller may
// keep it beyond the call.
struct PythonObservation {
  double time = 0.0;
  kinematics::World world;
  std::vector<geometry::Pose> cameras;
  std::vector<visibility::Segment> seen;
  reward::RewardTerms terms;
  // Under limited knowledge, what each camera knows on its own (control::Observation::own).
  std::vector<control::OwnKnowledge> own;
};

class PythonController final : public control::Controller {
 public:
  // `callable(observation)` returns velocities (M, 3) — vx, vy (m/s), yaw rate (rad/s) — or
  // (velocities, goals) with goals (M, 3), a row of NaN for a camera without a goal (None: no
  // goals), or (velocities, goals, events) with events a list of dicts: "kind", and optionally
  // "camera" (-1: the team), "detail", "reason" and "path" (n, 3), kept in the results like a
  // C++ method's events (a "plan" event's path is drawn in frames).
  explicit PythonController(py::object callable);
  ~PythonController() override;

  void control(const control::Observation& observation,
               std::span<scene::CameraCommand> commands) override;
  std::optional<geometry::Pose> goal(std::size_t camera) const override { return goals_[camera]; }
  void takeEvents(std::vector<control::ControlEvent>& out) override;

 private:
  void takeEventsFrom(const py::handle& events, double time, std::size_t cameras);

  py::object callable_;
  std::vector<std::optional<geometry::Pose>> goals_;
  std::vector<control::ControlEvent> events_;
};

// A method whose controllers `factory(scene, params, seed)` makes (a camcov.Scene, the run's
// parameters as camcov.parameters() gives them, and its seed; returning a callable as above),
// for camcov.bench. The factory may carry `description` and `color` (for legends and tables,
// like a C++ method's) and `version`; the method's identity is a fingerprint of its code and
// that version (a resume with changed code is refused). InputError for a bad name.
control::Method pythonMethod(const std::string& name, py::object factory);

}  // namespace camcov::python
