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
#include "util/counted.h"

namespace camcov::python {

params::Parameters parametersFrom(const py::handle& values) {
  params::Parameters p;
  if (values.is_none()) return p;
  if (!py::isinstance<py::dict>(values)) {
    throw py::type_error(
        fmt::format("params: expected a dict of \"group.name\" keys to values, or None; got {}",
                    typeName(values)));
  }
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(values)) {
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

// For each of a world's `count` targets or obstacles, its index in the scene (`index`:
// kinematics::targetId or obstacleId).
std::vector<std::uint32_t> sceneIndices(const kinematics::World& w, std::size_t count,
                                        std::uint32_t (*index)(const kinematics::World&,
                                                               std::size_t)) {
  std::vector<std::uint32_t> ids(count);
  for (std::size_t i = 0; i < count; ++i)
    ids[i] = index(w, i);
  return ids;
}

}  // namespace

void bindScene(py::module_& m) {
  py::class_<kinematics::World>(m, "World",
                                "The world at one instant (Scene.world_at(t), "
                                "Observation.world): every polygon in world coordinates, metres, "
                                "as an (n, 2) array of its vertices, ring open (the first vertex "
                                "is not repeated) and counter-clockwise. Pass it to "
                                "camcov.Visibility to see what cameras see.")
      .def_readonly("time", &kinematics::World::time, "t, seconds.")
      .def_property_readonly(
          "boundary", [](const kinematics::World& w) { return ringToArray(w.boundary); },
          "The boundary B, (n, 2): fixed, occludes, contains everything.")
      .def_property_readonly(
          "targets", [](const kinematics::World& w) { return ringsToList(w.targets); },
          "The targets present at t, a list of (n, 2) arrays: their boundaries are what the "
          "cameras cover (target i here is the scene's target target_ids[i]).")
      .def_property_readonly(
          "obstacles", [](const kinematics::World& w) { return ringsToList(w.obstacles); },
          "The obstacles present at t, a list of (n, 2) arrays: they occlude and are not "
          "covered (obstacle i here is the scene's obstacle obstacle_ids[i]).")
      // Recorded tracks come and go: which of the scene's objects each ring is.
      .def_property_readonly(
          "target_ids",
          [](const kinematics::World& w) {
            return sceneIndices(w, w.targets.size(), kinematics::targetId);
          },
          "For each ring of `targets`, its index in the scene file's "
          "targets (recorded people come and go; otherwise 0, 1, 2, ...).")
      .def_property_readonly(
          "obstacle_ids",
          [](const kinematics::World& w) {
            return sceneIndices(w, w.obstacles.size(), kinematics::obstacleId);
          },
          "For each ring of `obstacles`, its index in the scene file's obstacles.");

  py::class_<PythonScene, std::shared_ptr<PythonScene>>(
      m, "Scene", "A validated scene (camcov.load_scene, camcov.parse_scene).")
      // Nothing changes a scene once loaded: a copy is the scene itself (gymnasium.make
      // deep-copies its keywords, scenes among them).
      .def(
          "__copy__", [](std::shared_ptr<PythonScene> s) { return s; },
          "The scene itself: scenes do not change.")
      .def(
          "__deepcopy__", [](std::shared_ptr<PythonScene> s, const py::object&) { return s; },
          py::arg("memo"), "The scene itself: scenes do not change.")
      .def_property_readonly(
          "name", [](const PythonScene& s) { return s.scene.name; },
          "The file's stem, e.g. 'dynamic9': how runs and reports name the scene.")
      .def_property_readonly(
          "description", [](const PythonScene& s) { return s.scene.description; },
          "The file's optional one-line description ('' without one).")
      .def_property_readonly(
          "file", [](const PythonScene& s) { return s.file; },
          "The path it was loaded from ('' for camcov.parse_scene).")
      .def_property_readonly(
          "hash", [](const PythonScene& s) { return s.hash; },
          "FNV-1a hash of the file's bytes, as batch.json records it (0 for parse_scene).")
      .def_property_readonly(
          "boundary", [](const PythonScene& s) { return ringToArray(s.scene.boundary); },
          "The boundary B, (n, 2) in metres, open and counter-clockwise.")
      .def_property_readonly(
          "target_count", [](const PythonScene& s) { return s.scene.targets.size(); },
          "How many targets the file has (world_at(t).targets holds those present at t).")
      .def_property_readonly(
          "obstacle_count", [](const PythonScene& s) { return s.scene.obstacles.size(); },
          "How many obstacles the file has.")
      .def_property_readonly(
          "cameras",
          [](const PythonScene& s) {
            py::list out;
            for (const auto& c : s.scene.cameras)
              out.append(jsonToPython(scene::describeCamera(c)));
            return out;
          },
          "One dict per camera, as `camcov state` and the explorer show it, in the scene "
          "file's keys and units (the camera table, docs/scene-format.md): x, y (m), angle "
          "(initial yaw, degrees), maxVelocity (m/s), maxAngularVelocity (rad/s), cameraFoV "
          "(the half-angle θ_j, degrees: the field of view is 2θ_j wide) and, for a camera "
          "that has them, sensingRange (m) and imageWidth (pixels). For radians use "
          "initial_poses and half_fovs.")
      .def_property_readonly(
          "initial_poses",
          [](const PythonScene& s) {
            std::vector<geometry::Pose> poses;
            for (const auto& c : s.scene.cameras)
              poses.push_back(c.initial);
            return posesToArray(poses);
          },
          "The cameras' poses at t = 0, (M, 3): x, y in metres, yaw in radians (the file's "
          "angle is in degrees).")
      .def_property_readonly(
          "half_fovs",
          [](const PythonScene& s) {
            Array thetas(static_cast<py::ssize_t>(s.scene.cameras.size()));
            for (std::size_t j = 0; j < s.scene.cameras.size(); ++j)
              thetas.mutable_at(static_cast<py::ssize_t>(j)) = s.scene.cameras[j].lens.halfFov;
            return thetas;
          },
          "Each camera's half-angle θ_j, radians, (M,). camcov.Visibility takes the scene "
          "itself for its cameras' whole lenses (sensing ranges too).")
      .def(
          "world_at",
          [](const PythonScene& s, double t) {
            // Kinematics places objects at times up to 1e9 s (scene/scene_validation.h).
            if (!std::isfinite(t) || std::abs(t) > 1e9)
              throw py::value_error(
                  fmt::format("world_at: t = {}: expected a finite time within ±1e9 s", t));
            return s.kinematics.worldAt(t);
          },
          py::arg("t"),
          "The world at time t, seconds (a camcov.World: boundary, targets, obstacles as "
          "they stand then).")
      .def("__repr__", [](const PythonScene& s) {
        return fmt::format("<camcov.Scene {}: {}, {}, {}>", s.scene.name,
                           counted(s.scene.targets.size(), "target", "targets"),
                           counted(s.scene.obstacles.size(), "obstacle", "obstacles"),
                           counted(s.scene.cameras.size(), "camera", "cameras"));
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
