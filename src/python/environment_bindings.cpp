// The C++ half of camcov.env (src/python/camcov/env.py): episodes stepped by Python, their
// observations encoded into numpy arrays, a method of the table as a policy, many episodes
// stepped at once on threads without the GIL, frames as RGB arrays, and the scene families.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "environment/episode.h"
#include "environment/episode_batch.h"
#include "environment/method_policy.h"
#include "environment/observation_encoding.h"
#include "python/bindings.h"
#include "python/numpy_arrays.h"
#include "python/python_scene.h"
#include "records/run_files.h"
#include "scene/scene_families.h"
#include "scene/scene_loader.h"
#include "sim/scene_parameters.h"
#include "viz/frame.h"
#include "viz/frame_renderer.h"

namespace camcov::python {
namespace {

using environment::EncodingSizes;
using FloatArray = py::array_t<float, py::array::c_style>;

// An episode as Python holds it: its scene kept alive with it, and what draws its frames.
struct PythonEpisode {
  PythonEpisode(std::shared_ptr<PythonScene> s, const params::Parameters& params)
      : scene(std::move(s)),
        episode(std::shared_ptr<const scene::Scene>(scene, &scene->scene),
                sim::forScene(params, scene->scene,
                              scene->file.empty() ? scene->scene.name : scene->file, false)) {}
  std::shared_ptr<PythonScene> scene;
  environment::Episode episode;
  std::unique_ptr<viz::FrameBuilder> builder;  // made on the first frame
  std::unique_ptr<viz::FrameRenderer> renderer;
  viz::Frame frame;
};

EncodingSizes sizesFrom(const std::vector<std::size_t>& s) {
  if (s.size() != 4)
    throw py::value_error("sizes: expected (cameras, targets, obstacles, vertices)");
  const EncodingSizes sizes{s[0], s[1], s[2], s[3]};
  try {
    sizes.check();
  } catch (const std::invalid_argument& error) {
    throw py::value_error(error.what());
  }
  return sizes;
}

std::vector<std::size_t> sizesTuple(const EncodingSizes& s) {
  return {s.cameras, s.targets, s.obstacles, s.vertices};
}

// Rows [0, count) of an (K, 3) array-like of vx, vy, yaw rate (K ≥ count: rows past the
// scene's cameras, padding, are not read). ValueError naming `what` for another shape or a
// number that is not finite.
void commandsFrom(const py::handle& rows, std::size_t count, const char* what,
                  std::span<scene::CameraCommand> out) {
  const Array a = Array::ensure(rows);
  if (!a || a.ndim() != 2 || a.shape(1) != 3 || static_cast<std::size_t>(a.shape(0)) < count) {
    throw py::value_error(fmt::format(
        "{}: expected an array of shape ({}, 3): vx, vy (m/s) and yaw rate (rad/s) per camera",
        what, count));
  }
  const auto v = a.unchecked<2>();
  for (std::size_t j = 0; j < count; ++j) {
    const scene::CameraCommand u{{v(j, 0), v(j, 1)}, v(j, 2)};
    if (!u.isFinite())
      throw py::value_error(fmt::format("{}: camera {}'s command is not finite", what, j));
    out[j] = u;
  }
}

py::array_t<std::uint8_t> frameArray(PythonEpisode& e, int width, int height,
                                     const std::string& subtitle) {
  const environment::Episode& episode = e.episode;
  if (!e.renderer || e.renderer->width() != width || e.renderer->height() != height) {
    try {
      e.renderer = std::make_unique<viz::FrameRenderer>(width, height);
    } catch (const std::invalid_argument& error) {
      throw py::value_error(std::string("render size: ") + error.what());
    }
  }
  if (!e.builder) e.builder = std::make_unique<viz::FrameBuilder>(episode.scene());
  const control::Observation o = episode.observation();
  e.builder->build(o.time, o.cameras, e.frame);
  e.frame.caption.subtitle = subtitle;
  const viz::RasterImage image = e.renderer->rasterize(e.frame);
  py::array_t<std::uint8_t> rgb({height, width, 3});
  auto out = rgb.mutable_unchecked<3>();
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = image.pixels + static_cast<std::ptrdiff_t>(y) * image.stride;
    for (int x = 0; x < width; ++x) {
      std::uint32_t argb;  // Cairo's ARGB32: one native-endian word per pixel, opaque here
      std::memcpy(&argb, row + 4 * x, 4);
      out(y, x, 0) = static_cast<std::uint8_t>(argb >> 16);
      out(y, x, 1) = static_cast<std::uint8_t>(argb >> 8);
      out(y, x, 2) = static_cast<std::uint8_t>(argb);
    }
  }
  return rgb;
}

}  // namespace

void bindEnvironment(py::module_& m) {
  py::class_<PythonEpisode, std::shared_ptr<PythonEpisode>>(
      m, "Episode",
      "One run of a scene stepped from Python, t = 0 to sim.duration in steps of sim.dt: the "
      "simulator of camcov run (saturation, safety layer, boundary), commands chosen by the "
      "caller. What camcov.env's environments step.")
      .def(py::init([](std::shared_ptr<PythonScene> scene, const py::object& params) {
             return std::make_shared<PythonEpisode>(std::move(scene), parametersFrom(params));
           }),
           py::arg("scene"), py::arg("params") = py::none(),
           "Episode(scene, params=None): a camcov.Scene at t = 0, with the parameters as "
           "camcov.parameters takes them.")
      .def_property_readonly(
          "scene", [](const PythonEpisode& e) { return e.scene; }, "The camcov.Scene it runs.")
      .def_property_readonly(
          "time", [](const PythonEpisode& e) { return e.episode.observation().time; },
          "The present instant t, s.")
      .def_property_readonly(
          "index", [](const PythonEpisode& e) { return e.episode.index(); },
          "The present step k (t = k · dt).")
      .def_property_readonly(
          "steps", [](const PythonEpisode& e) { return e.episode.steps(); },
          "How many steps the episode takes (sim.duration / sim.dt).")
      .def_property_readonly(
          "finished", [](const PythonEpisode& e) { return e.episode.finished(); },
          "True at the last instant, which takes no commands.")
      .def_property_readonly(
          "cameras",
          [](const PythonEpisode& e) { return posesToArray(e.episode.observation().cameras); },
          "The cameras' poses now, (M, 3): x, y (m), yaw (rad).")
      .def_property_readonly(
          "terms", [](const PythonEpisode& e) { return termsToDict(e.episode.scored().terms); },
          "The team's reward terms now: coverage (eq. 3), weightedCoverage (eq. 3 with the "
          "scene's importance weights; coverage where it has none), utilization (5), "
          "repulsion (6), reward (8); as the run is scored, in the true world also under limited "
          "knowledge.")
      .def(
          "own_terms",
          [](const PythonEpisode& e, std::size_t camera) {
            if (camera >= e.episode.scene().cameras.size())
              throw py::value_error(fmt::format("camera: no camera {}", camera));
            return termsToDict(environment::ownTerms(e.episode, camera));
          },
          py::arg("camera"),
          "Camera j's own reward terms, as if it were alone (eq. 3, eq. 5 with M = 1, eq. 6 "
          "against the objects and the other cameras, eq. 8).")
      .def(
          "step",
          [](PythonEpisode& e, const py::handle& actions) {
            std::vector<scene::CameraCommand> commands(e.episode.scene().cameras.size());
            commandsFrom(actions, commands.size(), "action", commands);
            if (e.episode.finished()) throw py::value_error("step: the episode is finished");
            py::gil_scoped_release free;
            e.episode.step(commands);
          },
          py::arg("actions"),
          "Commands for the present instant, (K, 3) with K at least the cameras (rows past them "
          "are not read): vx, vy (m/s), yaw rate (rad/s), saturated to each camera's limits; "
          "then the next instant. ValueError for another shape, a number that is not finite, "
          "or a finished episode.")
      .def(
          "observation",
          [](const PythonEpisode& e, const std::vector<std::size_t>& sizes, const std::string& view,
             std::size_t camera) {
            if (view != "team" && view != "own")
              throw py::value_error("view: expected \"team\" or \"own\", got \"" + view + "\"");
            const EncodingSizes s = sizesFrom(sizes);
            FloatArray out(static_cast<py::ssize_t>(s.size()));
            try {
              environment::encodeObservation(
                  e.episode, s, view == "own" ? environment::View::own : environment::View::team,
                  camera, std::span(out.mutable_data(), s.size()));
            } catch (const std::invalid_argument& error) {
              throw py::value_error(error.what());
            }
            return out;
          },
          py::arg("sizes"), py::arg("view") = "team", py::arg("camera") = 0,
          "The present instant encoded as float32 (the layout of docs/python.md), padded to "
          "sizes = (cameras, targets, obstacles, vertices); view \"own\": what `camera` sees.")
      .def(
          "frame",
          [](PythonEpisode& e, int width, int height, const std::string& subtitle) {
            return frameArray(e, width, height, subtitle);
          },
          py::arg("width") = 640, py::arg("height") = 480, py::arg("subtitle") = "",
          "The present instant drawn as camcov render draws it, with `subtitle` under the "
          "scene's name: an (height, width, 3) uint8 RGB array.")
      .def(
          "close", [](PythonEpisode& e) { e.episode.close(); },
          "Records the last instant, completing the summary's averages (once finished).")
      .def_property_readonly(
          "summary",
          [](const PythonEpisode& e) {
            return jsonToPython(records::summaryJson(e.episode.summary()));
          },
          "The run's summary so far (its averages, eq. 4, once closed).");

  m.def(
      "encoding_sizes", [](const PythonScene& s) { return sizesTuple(EncodingSizes::of(s.scene)); },
      py::arg("scene"),
      "The smallest (cameras, targets, obstacles, vertices) an observation of the scene pads "
      "to.");

  py::class_<environment::MethodPolicy>(
      m, "MethodPolicy",
      "A method of the table choosing an episode's commands, its controller made and asked as "
      "a batch run makes and asks it: driven by it, an episode is that method's run.")
      .def(py::init([](const std::string& method, const PythonEpisode& e, std::uint64_t seed) {
             return std::make_unique<environment::MethodPolicy>(control::requireMethod(method),
                                                                e.episode, seed);
           }),
           py::arg("method"), py::arg("episode"), py::arg("seed"),
           "MethodPolicy(method, episode, seed): made at the episode's start.")
      .def(
          "decide",
          [](environment::MethodPolicy& policy, PythonEpisode& e) {
            std::vector<scene::CameraCommand> commands(e.episode.scene().cameras.size());
            {
              py::gil_scoped_release free;
              policy.decide(e.episode, commands);
            }
            std::vector<geometry::Pose> rows;
            for (const auto& u : commands)
              rows.push_back({u.velocity.x, u.velocity.y, u.angularVelocity});
            return posesToArray(rows);
          },
          py::arg("episode"),
          "The commands for the episode's present instant, (M, 3): vx, vy, yaw rate.");

  py::class_<environment::EpisodeStepper>(
      m, "EpisodeStepper",
      "Steps many episodes at once on threads that wait between calls, without the GIL: what "
      "camcov.env.VectorCoverageEnv steps with.")
      .def(py::init([](unsigned threads) {
             try {
               return std::make_unique<environment::EpisodeStepper>(threads);
             } catch (const std::invalid_argument& error) {
               throw py::value_error(error.what());
             }
           }),
           py::arg("threads"), "EpisodeStepper(threads): the calling thread among them.")
      .def_property_readonly("threads", &environment::EpisodeStepper::threads,
                             "How many threads step.")
      .def(
          "step",
          [](environment::EpisodeStepper& stepper,
             const std::vector<std::shared_ptr<PythonEpisode>>& episodes, const py::handle& actions,
             const std::vector<std::size_t>& sizes) {
            const EncodingSizes s = sizesFrom(sizes);
            const Array a = Array::ensure(actions);
            const std::size_t n = episodes.size();
            if (!a || a.ndim() != 3 || static_cast<std::size_t>(a.shape(0)) != n ||
                static_cast<std::size_t>(a.shape(1)) < s.cameras || a.shape(2) != 3) {
              throw py::value_error(fmt::format(
                  "actions: expected an array of shape ({}, {}, 3): per environment, vx, vy "
                  "and yaw rate per camera",
                  n, s.cameras));
            }
            const std::size_t stride = static_cast<std::size_t>(a.shape(1));
            const auto v = a.unchecked<3>();
            std::vector<scene::CameraCommand> commands(n * stride);
            std::vector<environment::Episode*> stepped;
            for (std::size_t i = 0; i < n; ++i) {
              environment::Episode& episode = episodes[i]->episode;
              if (episode.finished())
                throw py::value_error(fmt::format("episode {} is finished", i));
              for (std::size_t j = 0; j < episode.scene().cameras.size(); ++j) {
                const scene::CameraCommand u{{v(i, j, 0), v(i, j, 1)}, v(i, j, 2)};
                if (!u.isFinite()) {
                  throw py::value_error(
                      fmt::format("actions[{}]: camera {}'s command is not finite", i, j));
                }
                commands[i * stride + j] = u;
              }
              stepped.push_back(&episode);
            }
            FloatArray observations(
                {static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(s.size())});
            std::vector<reward::RewardTerms> terms(n);
            std::string failure;
            {
              py::gil_scoped_release free;
              try {
                stepper.step(stepped, commands, stride, s,
                             std::span(observations.mutable_data(), n * s.size()), terms);
              } catch (const std::invalid_argument& error) {
                failure = error.what();
              }
            }
            if (!failure.empty()) throw py::value_error(failure);
            Array termArray({static_cast<py::ssize_t>(n), py::ssize_t{4}});
            auto t = termArray.mutable_unchecked<2>();
            for (std::size_t i = 0; i < n; ++i) {
              t(i, 0) = reward::coverageTerm(stepped[i]->params().reward, terms[i]);
              t(i, 1) = terms[i].utilization;
              t(i, 2) = terms[i].repulsion;
              t(i, 3) = terms[i].reward;
            }
            return py::make_tuple(observations, termArray);
          },
          py::arg("episodes"), py::arg("actions"), py::arg("sizes"),
          "Steps every episode with its row of actions (N, K, 3); returns their new "
          "observations (N, size) float32 (team view) and terms (N, 4): coverage (as the "
          "reward takes it: weighted where the scene has importance weights), "
          "utilization, repulsion, reward.");

  m.def(
      "family_scene",
      [](const std::string& family, std::uint64_t seed) {
        const scene::SceneFamily& f = scene::sceneFamily(family);
        const std::string name = scene::familySceneFileName(f.name, seed);
        return std::make_shared<PythonScene>(
            scene::parseScene(scene::generateFamilyScene(f, seed).dump(), name), 0, "");
      },
      py::arg("family"), py::arg("seed"),
      "The scene `camcov generate --family FAMILY --seed SEED` writes, in memory.");
  m.def(
      "families",
      []() {
        py::dict out;
        for (const scene::SceneFamily& f : scene::sceneFamilies()) {
          py::dict d;
          d["summary"] = std::string(f.summary);
          d["tune"] = py::make_tuple(f.seeds.tune.first, f.seeds.tune.last);
          d["test"] = py::make_tuple(f.seeds.test.first, f.seeds.test.last);
          out[py::str(std::string(f.name))] = d;
        }
        return out;
      },
      "The scene families (docs/families.md): name -> summary, tune and test seed ranges "
      "(first, last).");
}

}  // namespace camcov::python
