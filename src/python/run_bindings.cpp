// Runs: the built-in methods (camcov.run), a Python controller (camcov.simulate), batches
// with both (camcov.bench) and reports, all through the same stages as the CLI, so their
// files are the CLI's to the byte. The GIL is let go while C++ works.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "batch/run_job.h"
#include "bench/progress_count.h"
#include "bench/run_bench.h"
#include "python/bindings.h"
#include "python/numpy_arrays.h"
#include "python/python_controller.h"
#include "python/python_scene.h"
#include "records/batch_folder.h"
#include "records/batch_summary_file.h"
#include "records/run_files.h"
#include "reports/report_builder.h"
#include "sim/scene_parameters.h"
#include "util/interruption.h"
#include "util/person_numbers.h"

namespace camcov::python {
namespace {

// A run as `camcov run` makes it: with the scene's own duration and knowledge settings where it
// has them, unless the parameters say otherwise (sim/scene_parameters.h).
records::RunRecord runWithoutGil(batch::JobSpec job) {
  py::gil_scoped_release free;
  job.scene = batch::readSceneFile(job.sceneFile);  // once: for its settings and the run
  job.parameters = sim::forScene(job.parameters, job.scene->scene, job.sceneFile.string(), false);
  return batch::runJob(job);
}

// A bench's lines, as the command line says them (one line per finished item, as in a log):
// notes and progress on sys.stderr, results on sys.stdout, so a notebook shows them too.
class PythonObserver final : public bench::BenchObserver {
 public:
  void note(const std::string& line) override { write("stderr", line); }
  void report(const std::string& line) override { write("stdout", line); }
  void stretchStarted(std::size_t total, std::size_t alreadyDone) override {
    count_.emplace(total, alreadyDone);
  }
  void itemFinished(const std::string& what) override {
    if (count_) write("stderr", count_->finished(what));
  }
  void stretchDone() override { count_.reset(); }

 private:
  // Never throws into the bench's threads: what Python raises while it writes (Ctrl-C comes
  // out of the stream's write, a closed stream) is kept, the bench stops at its next step,
  // and the call raises it on its way back to Python.
  static void write(const char* stream, const std::string& line) {
    const py::gil_scoped_acquire gil;
    try {
      py::module_::import("sys").attr(stream).attr("write")(line + "\n");
    } catch (py::error_already_set& e) {
      e.restore();
      keepPythonError();
    }
  }
  std::optional<bench::ProgressCount> count_;
};

// Observation.own: each camera's knowledge as Python objects.
py::list ownKnowledgeToList(const PythonObservation& o) {
  py::list cameras;
  for (const control::OwnKnowledge& own : o.own) {
    py::list teammates;
    for (const auto& heard : own.teammates) {
      if (!heard) {
        teammates.append(py::none());
        continue;
      }
      py::dict news;
      news["sent_at"] = heard->sentAt;
      news["pose"] = posesToArray(std::span(&heard->pose, 1))[py::int_(0)];
      news["goal"] = heard->goal
                         ? py::object(posesToArray(std::span(&*heard->goal, 1))[py::int_(0)])
                         : py::none();
      teammates.append(std::move(news));
    }
    py::dict knowledge;
    knowledge["world"] = own.world;
    knowledge["teammates"] = std::move(teammates);
    cameras.append(std::move(knowledge));
  }
  return cameras;
}

void bindObservation(py::module_& m) {
  py::class_<PythonObservation>(m, "Observation",
                                "What a controller sees at step t: the present only. "
                                "observation.world.targets are the targets' polygons now, "
                                "observation.cameras the team's poses, observation.seen what "
                                "each camera sees.")
      .def_readonly("time", &PythonObservation::time, "t, seconds.")
      .def_readonly("world", &PythonObservation::world,
                    "The world at t (a camcov.World: boundary, targets, obstacles).")
      .def_property_readonly(
          "cameras", [](const PythonObservation& o) { return posesToArray(o.cameras); },
          "The cameras' poses (M, 3): x, y in metres, yaw in radians.")
      .def_property_readonly(
          "seen",
          [](const PythonObservation& o) { return segmentsToDict(o.seen, o.cameras.size()); },
          "S(t) for the cameras, as the simulator measured it (see Visibility.segments).")
      .def_property_readonly(
          "terms", [](const PythonObservation& o) { return termsToDict(o.terms); },
          "coverage, utilization, repulsion and reward now (eq. (3)–(8)), a dict of floats.")
      .def_property_readonly("own", &ownKnowledgeToList,
                             "Under limited knowledge (params knowledge.limited), what each "
                             "camera knows on its own, by camera: a dict with 'world' (a "
                             "camcov.World: what it saw or was told) and 'teammates' (by camera: "
                             "None for itself and for one it never heard, else a dict with "
                             "'sent_at' (s), 'pose' (3,) and 'goal' (3,) or None, its latest "
                             "news). With full knowledge an empty list: every camera knows "
                             "`world` and `cameras`.");
}

void bindRun(py::module_& m) {
  py::class_<records::RunRecord>(m, "Run", "One run: its metadata, summary and every step.")
      .def_property_readonly(
          "scene", [](const records::RunRecord& r) { return r.metadata.scene; },
          "The scene's name (its file's stem).")
      .def_property_readonly(
          "method", [](const records::RunRecord& r) { return r.metadata.method; },
          "The method's name, e.g. 'paper'.")
      .def_property_readonly(
          "seed", [](const records::RunRecord& r) { return r.metadata.seed; }, "The run's seed.")
      .def_property_readonly(
          "summary",
          [](const records::RunRecord& r) { return jsonToPython(records::summaryJson(r.summary)); },
          "The results file's summary as a dict: averageCoverage, averageUtilization, "
          "minimum distances, time closer than δ, ...")
      .def_property_readonly(
          "coverage",
          [](const records::RunRecord& r) {
            Array out(static_cast<py::ssize_t>(r.steps.size()));
            for (std::size_t k = 0; k < r.steps.size(); ++k)
              out.mutable_at(k) = r.steps[k].terms.coverage;
            return out;
          },
          "Coverage at every step, (steps,): eq. (3), the fraction of target boundary seen.")
      .def_property_readonly(
          "stem", [](const records::RunRecord& r) { return records::runStem(r.metadata); },
          "<scene>-<method>-seed<N>: the results files' name without extension.")
      .def(
          "write",
          [](const records::RunRecord& r, const std::string& folder) {
            py::gil_scoped_release free;
            std::filesystem::create_directories(folder);
            return records::writeRunFiles(r, folder).string();
          },
          py::arg("folder"),
          "Writes <stem>.json and <stem>.csv as `camcov run` does; returns the JSON's path.");
}

}  // namespace

void bindRuns(py::module_& m) {
  bindObservation(m);
  bindRun(m);
  m.def(
      "methods",
      [] {
        py::list out;
        for (const control::Method& method : control::methods()) {
          py::dict d;
          d["name"] = method.name;
          d["description"] = method.description;
          d["color"] = method.color;
          d["role"] = method.role == control::Role::baseline  ? "baseline"
                      : method.role == control::Role::example ? "example"
                                                              : "method";
          out.append(d);
        }
        return out;
      },
      "The table of methods (C++), as `camcov bench --methods` knows them.");
  m.def(
      "run",
      [](const std::string& sceneFile, const std::string& method, std::uint64_t seed,
         const py::object& params) {
        return runWithoutGil({sceneFile, method, seed, parametersFrom(params)});
      },
      py::arg("scene_file"), py::arg("method") = "paper", py::arg("seed") = 1,
      py::arg("params") = py::none(), "One run of a method of the table, as `camcov run`.");
  m.def(
      "simulate",
      [](const std::string& sceneFile, const py::object& controller, const std::string& method,
         std::uint64_t seed, const py::object& params) {
        // One run, so every make() hands out the same callable.
        const control::Method python = pythonMethod(
            method, py::cpp_function([controller](const py::object&, const py::object&,
                                                  std::uint64_t) { return controller; }));
        return runWithoutGil({sceneFile, method, seed, parametersFrom(params), &python});
      },
      py::arg("scene_file"), py::arg("controller"), py::arg("method") = "python",
      py::arg("seed") = 1, py::arg("params") = py::none(),
      "One run with a Python controller: controller(observation) -> velocities (M, 3), or "
      "(velocities, goals), or (velocities, goals, events) (see docs/python.md). Its results files "
      "are a method's like any other.");
  const bench::BenchRequest defaults;  // the command line's defaults, one place for both
  m.def(
      "bench",
      [](const std::vector<std::string>& scenes, const std::vector<std::string>& methods,
         std::uint64_t seeds, const py::object& duration, const std::string& out,
         const py::object& params, const py::dict& controllers, unsigned jobs,
         const std::string& shard, bool force, const std::string& reference,
         const std::string& videos, const std::string& explorer, bool report,
         std::int64_t optimumBudget) -> py::object {
        std::vector<control::Method> brought;
        for (const auto& [name, factory] : controllers)
          brought.push_back(
              pythonMethod(py::str(name), py::reinterpret_borrow<py::object>(factory)));
        bench::BenchRequest request;
        request.scenes = scenes;
        if (!methods.empty()) request.methods = methods;
        for (const auto& m : brought) {
          if (std::find(request.methods.begin(), request.methods.end(), m.name) ==
              request.methods.end())
            request.methods.push_back(m.name);
        }
        request.seeds = seeds;
        if (!duration.is_none()) {
          request.duration = numberFrom(duration, "duration");
          // as `camcov bench --duration`
          if (!withinRange(request.duration, 0.0, scene::kMaxDuration) || request.duration == 0.0) {
            throw py::value_error(fmt::format("duration = {}: expected a number in {}",
                                              readableNumber(request.duration),
                                              rangeText(0.0, scene::kMaxDuration, false)));
          }
        }
        request.parameters = parametersFrom(params);
        request.shard = shard;
        request.jobs = jobs;
        request.out = out;
        request.force = force;
        request.outputs = {!report, videos, explorer, reference, optimumBudget};
        // What ran it, for batch.json and the report: the script and its arguments.
        request.command = {"python"};
        for (const auto& arg : py::module_::import("sys").attr("argv"))
          request.command.push_back(py::str(arg));
        request.extraMethods = brought;
        PythonObserver observer;
        bench::BenchResult result;
        {
          py::gil_scoped_release free;
          result = bench::runBench(request, observer);
        }
        throwIfInterrupted();  // an error kept while the last lines were written
        if (result.shard) return py::none();
        return jsonToPython(records::summaryToJson(result.summary));
      },
      py::arg("scenes") = defaults.scenes, py::arg("methods") = std::vector<std::string>{},
      py::arg("seeds") = defaults.seeds, py::arg("duration") = py::none(),
      py::arg("out") = defaults.out, py::arg("params") = py::none(),
      py::arg("controllers") = py::dict(), py::arg("jobs") = defaults.jobs,
      py::arg("shard") = defaults.shard, py::arg("force") = defaults.force,
      py::arg("reference") = defaults.outputs.reference,
      py::arg("videos") = defaults.outputs.videos, py::arg("explorer") = defaults.outputs.explorer,
      py::arg("report") = !defaults.outputs.noReport,
      py::arg("optimum_budget") = defaults.outputs.optimumBudget,
      "`camcov bench`, with its options and defaults, and Python controllers beside the table's "
      "methods: controllers maps a method name to factory(scene, params, seed) -> controller "
      "(the factory's `description`, `color` and `version` attributes, if set, name it in the "
      "report and in resumes). Says what `camcov bench` says (sys.stdout, sys.stderr); returns "
      "the summary (None for a shard, summarized by `camcov merge`).");
  m.def(
      "report",
      [](const std::string& folder, const std::string& out) {
        py::gil_scoped_release free;
        const std::filesystem::path file =
            out.empty() ? records::BatchFolder(folder).reportFile() : std::filesystem::path(out);
        reports::writeReport(folder, file);
        return file.string();
      },
      py::arg("folder"), py::arg("out") = "",
      "`camcov report`: the HTML report of a results folder.");
}

}  // namespace camcov::python
