// The C++ half of camcov.env (src/python/camcov/env.py): episodes stepped by Python, their
// observations encoded into numpy arrays, a method of the table as a policy, many episodes
// stepped at once on threads without the GIL, frames as RGB arrays, and the scene families.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "control/learned_policy.h"
#include "environment/episode.h"
#include "environment/episode_batch.h"
#include "environment/method_policy.h"
#include "environment/observation_encoding.h"
#include "python/bindings.h"
#include "python/gil_free_lock.h"
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
// Every use takes `mutex` (lockWithoutGil): threads sharing one episode take turns.
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
  bool closed = false;  // close() ends it: no step after
  std::mutex mutex;
};

// With the episode's lock held: RuntimeError unless it can take commands now.
void requireSteppable(const PythonEpisode& e, const std::string& what) {
  if (e.closed) throw std::runtime_error(what + ": the episode is closed");
  if (e.episode.finished()) throw py::value_error(what + ": the episode is finished");
}

// `f(episode)` with the episode's lock held.
template <class Use>
auto locked(PythonEpisode& e, Use&& use) {
  const auto lock = lockWithoutGil(e.mutex);
  return use(e.episode);
}

// A method's policy as Python holds it: the episode it was made for is kept alive, as its
// controller refers to that episode's scene and parameters; calls on one policy take turns.
struct PythonMethodPolicy {
  PythonMethodPolicy(const control::Method& method, std::shared_ptr<PythonEpisode> e,
                     std::uint64_t seed)
      : madeFor(std::move(e)), policy(method, madeFor->episode, seed) {}
  std::shared_ptr<PythonEpisode> madeFor;
  environment::MethodPolicy policy;
  std::mutex mutex;
};

// `item` as an episode: RuntimeError for None (none started yet), TypeError for another type.
std::shared_ptr<PythonEpisode> episodeFrom(const py::handle& item, const std::string& what) {
  if (item.is_none())
    throw std::runtime_error(what + " is None: no episode has started (call reset() first)");
  if (!py::isinstance<PythonEpisode>(item)) {
    throw py::type_error(
        fmt::format("{}: expected a camcov.Episode, got {}", what, typeName(item)));
  }
  return item.cast<std::shared_ptr<PythonEpisode>>();
}

// `targets`: how the target slots are filled, "index" (slot i: the scene's target i) or
// "nearest" (the targets present, nearest first).
EncodingSizes sizesFrom(const std::vector<std::size_t>& s, const std::string& targets) {
  if (s.size() != 4)
    throw py::value_error("sizes: expected (cameras, targets, obstacles, vertices)");
  if (targets != "index" && targets != "nearest")
    throw py::value_error("targets: expected \"index\" or \"nearest\", got \"" + targets + "\"");
  const EncodingSizes sizes{
      s[0], s[1], s[2], s[3],
      targets == "nearest" ? environment::TargetSlots::nearest : environment::TargetSlots::byIndex};
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
      "caller. What camcov.env's environments step. Threads sharing one take turns.")
      .def(py::init([](const py::handle& scene, const py::object& params) {
             // Checked here: pybind11 would hand None on as a null scene.
             if (!py::isinstance<PythonScene>(scene)) {
               throw py::type_error(
                   fmt::format("scene: expected a camcov.Scene, got {}", typeName(scene)));
             }
             return std::make_shared<PythonEpisode>(scene.cast<std::shared_ptr<PythonScene>>(),
                                                    parametersFrom(params));
           }),
           py::arg("scene"), py::arg("params") = py::none(),
           "Episode(scene, params=None): a camcov.Scene at t = 0, with the parameters as "
           "camcov.parameters takes them.")
      .def_property_readonly(
          "scene", [](const PythonEpisode& e) { return e.scene; }, "The camcov.Scene it runs.")
      .def_property_readonly(
          "time",
          [](PythonEpisode& e) {
            return locked(e, [](const auto& episode) { return episode.observation().time; });
          },
          "The present instant t, s.")
      .def_property_readonly(
          "index",
          [](PythonEpisode& e) {
            return locked(e, [](const auto& episode) { return episode.index(); });
          },
          "The present step k (t = k · dt).")
      .def_property_readonly(
          "steps",
          [](PythonEpisode& e) {
            return locked(e, [](const auto& episode) { return episode.steps(); });
          },
          "How many steps the episode takes (sim.duration / sim.dt).")
      .def_property_readonly(
          "finished",
          [](PythonEpisode& e) {
            return locked(e, [](const auto& episode) { return episode.finished(); });
          },
          "True at the last instant, which takes no commands.")
      .def_property_readonly(
          "cameras",
          [](PythonEpisode& e) {
            return locked(
                e, [](const auto& episode) { return posesToArray(episode.observation().cameras); });
          },
          "The cameras' poses now, (M, 3): x, y (m), yaw (rad).")
      .def_property_readonly(
          "terms",
          [](PythonEpisode& e) {
            return locked(e,
                          [](const auto& episode) { return termsToDict(episode.scored().terms); });
          },
          "The team's reward terms now: coverage (eq. 3), weightedCoverage (eq. 3 with the "
          "scene's importance weights; coverage where it has none), utilization (5), "
          "repulsion (6), reward (8); as the run is scored, in the true world also under limited "
          "knowledge.")
      .def(
          "own_terms",
          [](PythonEpisode& e, std::size_t camera) {
            if (camera >= e.episode.scene().cameras.size())
              throw py::value_error(fmt::format("camera: no camera {}", camera));
            return locked(e, [&](const auto& episode) {
              return termsToDict(environment::ownTerms(episode, camera));
            });
          },
          py::arg("camera"),
          "Camera j's own reward terms, as if it were alone (eq. 3, eq. 5 with M = 1, eq. 6 "
          "against the objects and the other cameras, eq. 8).")
      .def(
          "step",
          [](PythonEpisode& e, const py::handle& actions) {
            std::vector<scene::CameraCommand> commands(e.episode.scene().cameras.size());
            commandsFrom(actions, commands.size(), "action", commands);
            const auto lock = lockWithoutGil(e.mutex);
            requireSteppable(e, "step");
            const py::gil_scoped_release free;
            e.episode.step(commands);
          },
          py::arg("actions"),
          "Commands for the present instant, (K, 3) with K at least the cameras (rows past them "
          "are not read): vx, vy (m/s), yaw rate (rad/s), saturated to each camera's limits; "
          "then the next instant. ValueError for another shape, a number that is not finite, "
          "or a finished episode; RuntimeError once closed.")
      .def(
          "observation",
          [](PythonEpisode& e, const std::vector<std::size_t>& sizes, const std::string& view,
             std::size_t camera, const std::string& targets) {
            const environment::View v = [&] {
              try {
                return control::viewNamed(view);
              } catch (const std::invalid_argument& error) {
                throw py::value_error(error.what());
              }
            }();
            const EncodingSizes s = sizesFrom(sizes, targets);
            FloatArray out(static_cast<py::ssize_t>(s.size()));
            const auto lock = lockWithoutGil(e.mutex);
            try {
              environment::encodeObservation(e.episode, s, v, camera,
                                             std::span(out.mutable_data(), s.size()));
            } catch (const std::invalid_argument& error) {
              throw py::value_error(error.what());
            }
            return out;
          },
          py::arg("sizes"), py::arg("view") = "team", py::arg("camera") = 0,
          py::arg("targets") = "index",
          "The present instant encoded as float32 (the layout of docs/python.md), padded to "
          "sizes = (cameras, targets, obstacles, vertices); view \"own\": what `camera` sees, "
          "its teammates after it; view \"known\": what `camera` knows (under limited "
          "knowledge the world as it saw it or was told and its teammates as last heard), laid "
          "out as the team view with its slot first; targets \"nearest\": the target slots "
          "hold the targets present, nearest first, as many as fit.")
      .def(
          "frame",
          [](PythonEpisode& e, int width, int height, const std::string& subtitle) {
            const auto lock = lockWithoutGil(e.mutex);
            return frameArray(e, width, height, subtitle);
          },
          py::arg("width") = 640, py::arg("height") = 480, py::arg("subtitle") = "",
          "The present instant drawn as camcov render draws it, with `subtitle` under the "
          "scene's name: an (height, width, 3) uint8 RGB array.")
      .def(
          "close",
          [](PythonEpisode& e) {
            const auto lock = lockWithoutGil(e.mutex);
            e.closed = true;
            e.episode.close();
          },
          "Ends the episode: it takes no more steps. Once finished, records the last instant, "
          "completing the summary's averages.")
      .def_property_readonly(
          "summary",
          [](PythonEpisode& e) {
            return jsonToPython(records::summaryJson(
                locked(e, [](const auto& episode) { return episode.summary(); })));
          },
          "The run's summary so far (its averages, eq. 4, once closed).");

  m.def(
      "encoding_sizes", [](const PythonScene& s) { return sizesTuple(EncodingSizes::of(s.scene)); },
      py::arg("scene"),
      "The smallest (cameras, targets, obstacles, vertices) an observation of the scene pads "
      "to.");
  m.def(
      "camera_columns", [] { return environment::cameraColumns(); },
      "The names of a camera slot's floats in an observation, in order: present, x, y, cos yaw, "
      "sin yaw, the observed keys of a scene's cameras (maxVelocity, …, sensingRange), "
      "coverage (docs/python.md).");
  m.def(
      "observation_bounds",
      [](const std::vector<std::size_t>& sizes) {
        const EncodingSizes s = sizesFrom(sizes, "index");
        FloatArray low(static_cast<py::ssize_t>(s.size())),
            high(static_cast<py::ssize_t>(s.size()));
        environment::observationBounds(s, std::span(low.mutable_data(), s.size()),
                                       std::span(high.mutable_data(), s.size()));
        return py::make_tuple(low, high);
      },
      py::arg("sizes"),
      "(low, high): the bounds, float32, of every float of an observation padded to sizes = "
      "(cameras, targets, obstacles, vertices); the encoding clamps to them.");

  m.def(
      "learned_action",
      [](const py::array_t<float, py::array::c_style | py::array::forcecast>& observations) {
        const control::LearnedPolicy& policy = control::LearnedPolicy::builtIn();
        const std::size_t size = policy.sizes().size();
        if (observations.ndim() != 2 || static_cast<std::size_t>(observations.shape(1)) != size) {
          throw py::value_error(
              fmt::format("learned_action: expected observations of shape (n, {})", size));
        }
        std::vector<geometry::Pose> rows;
        for (py::ssize_t i = 0; i < observations.shape(0); ++i) {
          const std::span<const float> row(observations.data(i, 0), size);
          if (!std::all_of(row.begin(), row.end(), [](float v) { return std::isfinite(v); }))
            throw py::value_error(fmt::format("learned_action: row {} is not finite", i));
          const auto a = policy.act(row);
          rows.push_back({a[0], a[1], a[2]});
        }
        return posesToArray(rows);
      },
      py::arg("observations"),
      "The learned method's network on each row of observations (n, size), float32: its mean "
      "action (vx, vy, yaw rate over the camera's limits) clipped to [-1, 1], as "
      "`--method learned` proposes it before its reward check.");

  py::class_<PythonMethodPolicy>(
      m, "MethodPolicy",
      "A method of the table choosing an episode's commands, its controller made and asked as "
      "a batch run makes and asks it: driven by it, an episode is that method's run. Threads "
      "sharing one take turns.")
      .def(py::init([](const std::string& method, const py::handle& episode, std::uint64_t seed) {
             return std::make_unique<PythonMethodPolicy>(control::requireMethod(method),
                                                         episodeFrom(episode, "episode"), seed);
           }),
           py::arg("method"), py::arg("episode"), py::arg("seed"),
           "MethodPolicy(method, episode, seed): made at the episode's start.")
      .def(
          "decide",
          [](PythonMethodPolicy& p, const py::handle& episode) {
            const std::shared_ptr<PythonEpisode> e = episodeFrom(episode, "episode");
            // Its controller knows one scene's cameras, targets and obstacles.
            if (e->scene != p.madeFor->scene) {
              throw py::value_error(fmt::format(
                  "decide: an episode of scene '{}', but this policy was made for an episode "
                  "of scene '{}' (another camcov.Scene object); make one per episode",
                  e->scene->scene.name, p.madeFor->scene->scene.name));
            }
            std::vector<scene::CameraCommand> commands(e->episode.scene().cameras.size());
            {
              const auto turn = lockWithoutGil(p.mutex);
              const auto lock = lockWithoutGil(e->mutex);
              if (e->closed) throw std::runtime_error("decide: the episode is closed");
              const py::gil_scoped_release free;
              p.policy.decide(e->episode, commands);
            }
            std::vector<geometry::Pose> rows;
            for (const auto& u : commands)
              rows.push_back({u.velocity.x, u.velocity.y, u.angularVelocity});
            return posesToArray(rows);
          },
          py::arg("episode"),
          "The commands for the episode's present instant, (M, 3): vx, vy, yaw rate. "
          "ValueError for an episode of another scene than the one it was made for; "
          "RuntimeError for a closed one.");

  py::class_<environment::EpisodeStepper>(
      m, "EpisodeStepper",
      "Steps many episodes at once on threads that wait between calls, without the GIL: what "
      "camcov.env.VectorCoverageEnv steps with. Threads sharing one take turns.")
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
          [](environment::EpisodeStepper& stepper, const py::sequence& items,
             const py::handle& actions, const std::vector<std::size_t>& sizes,
             const std::string& targets) {
            const EncodingSizes s = sizesFrom(sizes, targets);
            std::vector<std::shared_ptr<PythonEpisode>> episodes;
            std::vector<std::mutex*> mutexes;
            for (const py::handle item : items) {
              episodes.push_back(episodeFrom(item, fmt::format("episodes[{}]", episodes.size())));
              mutexes.push_back(&episodes.back()->mutex);
            }
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
            FloatArray observations(
                {static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(s.size())});
            std::vector<scene::CameraCommand> commands(n * stride);
            std::vector<environment::Episode*> stepped;
            // An episode given twice is locked once, then refused by the stepper.
            const auto locks = lockAllWithoutGil(mutexes);
            for (std::size_t i = 0; i < n; ++i) {
              requireSteppable(*episodes[i], fmt::format("episodes[{}]", i));
              environment::Episode& episode = episodes[i]->episode;
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
          py::arg("episodes"), py::arg("actions"), py::arg("sizes"), py::arg("targets") = "index",
          "Steps every episode with its row of actions (N, K, 3); returns their new "
          "observations (N, size) float32 (team view; targets as Episode.observation takes "
          "it) and terms (N, 4): coverage (as the "
          "reward takes it: weighted where the scene has importance weights), "
          "utilization, repulsion, reward. The episodes are distinct and started (not "
          "None); calls from several threads take turns.");

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
