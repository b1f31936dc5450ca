// Runs: the built-in methods (camcov.run), a Python controller (camcov.simulate), batches
// with both (camcov.bench) and reports, all through the same stages as the CLI, so their
// files are the CLI's to the byte. The GIL is let go while C++ works.
#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <thread>

#include "batch/batch_plan.h"
#include "batch/batch_runner.h"
#include "batch/run_job.h"
#include "camcov/version.h"
#include "cli/bench_outputs.h"
#include "python/bindings.h"
#include "python/numpy_arrays.h"
#include "python/python_controller.h"
#include "python/python_scene.h"
#include "records/run_files.h"
#include "reports/report_builder.h"

namespace camcov::python {
namespace {

records::RunRecord runWithoutGil(const batch::JobSpec& job) {
  py::gil_scoped_release free;
  return batch::runJob(job);
}

// A batch's progress: nothing on the way (a notebook has no progress line) but what was
// reused from the folder, as the CLI says it, on sys.stderr.
class Quiet final : public batch::BatchObserver {
 public:
  explicit Quiet(std::string folder) : folder_(std::move(folder)) {}
  void resuming(const batch::Resumption& r) override {
    if (r.alreadyDone == 0) return;
    const py::gil_scoped_acquire gil;
    py::module_::import("sys").attr("stderr").attr("write")(batch::describeResumption(r, folder_) +
                                                            "\n");
  }
  void finished(const batch::BatchJob&, const records::JobOutcome&) override {}

 private:
  std::string folder_;
};

void bindObservation(py::module_& m) {
  py::class_<PythonObservation>(m, "Observation",
                                "What a controller sees at step t: the present only.")
      .def_readonly("time", &PythonObservation::time)
      .def_readonly("world", &PythonObservation::world)
      .def_property_readonly(
          "cameras", [](const PythonObservation& o) { return posesToArray(o.cameras); },
          "The cameras' poses (M, 3): x, y, yaw.")
      .def_property_readonly(
          "seen", [](const PythonObservation& o) { return segmentsToDict(o.seen); },
          "S(t) for the cameras, as the simulator measured it (see Visibility.segments).")
      .def_property_readonly("terms",
                             [](const PythonObservation& o) { return termsToDict(o.terms); });
}

void bindRun(py::module_& m) {
  py::class_<records::RunRecord>(m, "Run", "One run: its metadata, summary and every step.")
      .def_property_readonly("scene", [](const records::RunRecord& r) { return r.metadata.scene; })
      .def_property_readonly("method",
                             [](const records::RunRecord& r) { return r.metadata.method; })
      .def_property_readonly("seed", [](const records::RunRecord& r) { return r.metadata.seed; })
      .def_property_readonly("summary",
                             [](const records::RunRecord& r) {
                               return jsonToPython(records::runToJson(r)["summary"]);
                             })
      .def_property_readonly("coverage",
                             [](const records::RunRecord& r) {
                               Array out(static_cast<py::ssize_t>(r.steps.size()));
                               for (std::size_t k = 0; k < r.steps.size(); ++k)
                                 out.mutable_at(k) = r.steps[k].terms.coverage;
                               return out;
                             })
      .def_property_readonly(
          "stem", [](const records::RunRecord& r) { return records::runStem(r.metadata); })
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
      "(velocities, goals), or (velocities, goals, events) (see the README). Its results files "
      "are a method's like any other.");
  m.def(
      "bench",
      [](const std::vector<std::string>& scenes, const std::vector<std::string>& methods,
         std::uint64_t seeds, const std::string& out, const py::object& params,
         const py::dict& controllers, unsigned jobs, const std::string& reference,
         const std::string& videos, const std::string& explorer, bool report, bool force) {
        std::vector<control::Method> brought;
        for (const auto& [name, factory] : controllers)
          brought.push_back(
              pythonMethod(py::str(name), py::reinterpret_borrow<py::object>(factory)));
        std::vector<std::string> names = methods;
        if (names.empty()) names = control::defaultMethods();
        for (const auto& m : brought) {
          if (std::find(names.begin(), names.end(), m.name) == names.end()) names.push_back(m.name);
        }
        cli::BenchOutputOptions outputs;
        outputs.noReport = !report;
        outputs.videos = videos;
        outputs.explorer = explorer;
        outputs.reference = reference;
        outputs.check();
        outputs.referenceAmong(names);
        // What ran it, for batch.json and the report: the script and its arguments.
        std::vector<std::string> command{"python"};
        for (const auto& arg : py::module_::import("sys").attr("argv"))
          command.push_back(py::str(arg));
        batch::BatchRequest request{scenes, names,   seeds,  parametersFrom(params),
                                    {},     command, brought};
        batch::BatchPlan plan = batch::planBatch(request, kVersion);
        const records::BatchFolder folder(out);
        {
          py::gil_scoped_release free;
          batch::prepareFolder(folder, plan.manifest, force);
          const unsigned workers =
              jobs > 0 ? jobs : std::max(1u, std::thread::hardware_concurrency());
          Quiet quiet(out);
          const batch::BatchRun run = batch::runBatch(plan.jobs, folder, workers, quiet);
          cli::writeBenchOutputs(folder, plan.manifest, run.outcomes, outputs, workers);
        }
        return jsonToPython(nlohmann::json::parse(std::ifstream(folder.root() / "summary.json")));
      },
      py::arg("scenes"), py::arg("methods") = std::vector<std::string>{}, py::arg("seeds") = 5,
      py::arg("out") = "bench-results", py::arg("params") = py::none(),
      py::arg("controllers") = py::dict(), py::arg("jobs") = 0, py::arg("reference") = "",
      py::arg("videos") = "none", py::arg("explorer") = "median", py::arg("report") = true,
      py::arg("force") = false,
      "`camcov bench` with Python controllers beside the table's methods: controllers maps a "
      "method name to factory(scene, params, seed) -> controller; jobs = 0 is every core. "
      "Returns the summary.");
  m.def(
      "report",
      [](const std::string& folder, const std::string& out) {
        py::gil_scoped_release free;
        const std::filesystem::path file = out.empty() ? folder + "/report.html" : out;
        reports::writeReport(folder, file);
        return file.string();
      },
      py::arg("folder"), py::arg("out") = "",
      "`camcov report`: the HTML report of a results folder.");
}

}  // namespace camcov::python
