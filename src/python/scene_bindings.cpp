// Scenes, the world at time t and parameters, with the CLI's validation and messages.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>

#include "kinematics/world.h"
#include "params/parameter_table.h"
#include "python/bindings.h"
#include "python/numpy_arrays.h"
#include "python/python_scene.h"
#include "scene/scene_loader.h"

namespace camcov::python {

params::Parameters parametersFrom(const py::handle& values) {
  params::Parameters p;
  if (values.is_none()) return p;
  for (const auto& [key, value] : py::cast<py::dict>(values)) {
    const std::string text = py::isinstance<py::bool_>(value)
                                 ? (value.cast<bool>() ? "true" : "false")
                                 : py::str(value).cast<std::string>();
    params::applyAssignment(p, py::str(key).cast<std::string>() + "=" + text);
  }
  params::validate(p);
  return p;
}

py::object parametersToPython(const params::Parameters& p) {
  return jsonToPython(params::toJson(p));
}

namespace {

py::dict cameraDict(const scene::CameraSpec& c) {
  py::dict d;
  d["pose"] = posesToArray(std::span(&c.initial, 1))[py::int_(0)];
  d["max_velocity"] = c.maxVelocity;
  d["max_angular_velocity"] = c.maxAngularVelocity;
  d["half_fov"] = c.halfFov;
  return d;
}

}  // namespace

void bindScene(py::module_& m) {
  py::class_<kinematics::World>(m, "World",
                                "The world at one instant: every polygon in world "
                                "coordinates, rings open and counter-clockwise.")
      .def_readonly("time", &kinematics::World::time)
      .def_property_readonly("boundary",
                             [](const kinematics::World& w) { return ringToArray(w.boundary); })
      .def_property_readonly("targets",
                             [](const kinematics::World& w) { return ringsToList(w.targets); })
      .def_property_readonly("obstacles",
                             [](const kinematics::World& w) { return ringsToList(w.obstacles); })
      // Recorded tracks come and go: which of the scene's objects each ring is.
      .def_property_readonly("target_ids",
                             [](const kinematics::World& w) {
                               std::vector<std::uint32_t> ids;
                               for (std::size_t i = 0; i < w.targets.size(); ++i)
                                 ids.push_back(kinematics::targetId(w, i));
                               return ids;
                             })
      .def_property_readonly("obstacle_ids", [](const kinematics::World& w) {
        std::vector<std::uint32_t> ids;
        for (std::size_t i = 0; i < w.obstacles.size(); ++i)
          ids.push_back(kinematics::obstacleId(w, i));
        return ids;
      });

  py::class_<PythonScene, std::shared_ptr<PythonScene>>(
      m, "Scene", "A validated scene (camcov.load_scene, camcov.parse_scene).")
      .def_property_readonly("name", [](const PythonScene& s) { return s.scene.name; })
      .def_property_readonly("description",
                             [](const PythonScene& s) { return s.scene.description; })
      .def_property_readonly("file", [](const PythonScene& s) { return s.file; })
      .def_property_readonly("hash", [](const PythonScene& s) { return s.hash; })
      .def_property_readonly("boundary",
                             [](const PythonScene& s) { return ringToArray(s.scene.boundary); })
      .def_property_readonly("target_count",
                             [](const PythonScene& s) { return s.scene.targets.size(); })
      .def_property_readonly("obstacle_count",
                             [](const PythonScene& s) { return s.scene.obstacles.size(); })
      .def_property_readonly(
          "cameras",
          [](const PythonScene& s) {
            py::list out;
            for (const auto& c : s.scene.cameras)
              out.append(cameraDict(c));
            return out;
          },
          "Each camera's initial pose (x, y, yaw), limits and half-angle θ_j (radians).")
      .def_property_readonly("initial_poses",
                             [](const PythonScene& s) {
                               std::vector<geometry::Pose> poses;
                               for (const auto& c : s.scene.cameras)
                                 poses.push_back(c.initial);
                               return posesToArray(poses);
                             })
      .def_property_readonly("half_fovs",
                             [](const PythonScene& s) {
                               const auto thetas = scene::halfFovs(s.scene);
                               return Array(static_cast<py::ssize_t>(thetas.size()), thetas.data());
                             })
      .def(
          "world_at",
          [](const PythonScene& s, double t) {
            // Kinematics places objects at times up to 1e9 s (scene/scene_validation.h).
            if (!std::isfinite(t) || std::abs(t) > 1e9)
              throw py::value_error(
                  fmt::format("world_at: t = {}: expected a finite time within ±1e9 s", t));
            return s.kinematics.worldAt(t);
          },
          py::arg("t"), "The world at time t (SPEC section 2's motion).")
      .def("__repr__", [](const PythonScene& s) {
        return fmt::format("<camcov.Scene {}: {} targets, {} obstacles, {} cameras>", s.scene.name,
                           s.scene.targets.size(), s.scene.obstacles.size(),
                           s.scene.cameras.size());
      });

  m.def(
      "load_scene",
      [](const std::string& file) {
        scene::SceneFile loaded = scene::loadSceneFile(file);
        return std::make_shared<PythonScene>(std::move(loaded.scene), loaded.hash, file);
      },
      py::arg("file"),
      "Loads and validates a scene file; camcov.InputError with the CLI's message otherwise.");
  m.def(
      "parse_scene",
      [](const std::string& text, const std::string& name) {
        return std::make_shared<PythonScene>(scene::parseScene(text, name), 0, "");
      },
      py::arg("text"), py::arg("name") = "scene.json",
      "Parses and validates scene JSON text; `name` stands for the file in messages.");
  m.def(
      "parameters",
      [](const py::object& values) { return parametersToPython(parametersFrom(values)); },
      py::arg("values") = py::none(),
      "Every parameter as a nested dict: the defaults (Table I) with `values` applied, "
      "{\"global.K\": 200, ...} as with --set.");
}

}  // namespace camcov::python
