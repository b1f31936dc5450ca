// How the cost of a run grows with the team and the crowd (docs/scaling.md). For each
// method, the wall time of simulating D seconds (default parameters otherwise) of generated
// scenes (scene/scene_generator.h: 1 x 1 m squares on 2 m loops at 1 m/s), in sweeps over
//   cameras M at a fixed number of targets N,
//   targets N at a fixed M, in a square field of side max(20, 10·√N) m (the crowd's density
//     stays the same; the cameras' share of the field shrinks),
//   and, with --max-v, vertices per target V at the fixed N and M.
// Prints a markdown table of the cost of one simulated second (wall s / simulated s) and the
// real-time factor (its inverse), and fits the exponents of cost ∝ M^a, N^b, V^c by least
// squares on log-log over the points with M, N or V ≥ 4: below that a run's fixed costs bend
// the line. --csv and --svg (log-log, both methods) write the same points. One run per point,
// so pin it to one core and keep the machine quiet:
//   taskset -c 0 build/tests/bench/bench_scaling --csv scaling.csv --svg scaling.svg
// With --scene FILE... it times whole runs of those files instead (the median of --repeat
// runs, on --threads threads), the real-time factor per scene and method:
//   taskset -c 0 build/tests/bench/bench_scaling --scene scenes/large/crowd_100x30.json
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "batch/run_job.h"
#include "control/methods.h"
#include "reports/svg_plot.h"
#include "scene/scene_generator.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/run_threads.h"

namespace camcov {
namespace {

struct Options {
  // Simulated s per point: two periods of the paper's global optimization (T1 = 5 s), so the
  // one at t = 0 weighs about as much as in a long run.
  double duration = 10.0;
  int nFixed = 100;  // targets in the sweeps over M and V
  int mFixed = 8;    // cameras in the sweeps over N and V
  int maxM = 64;
  int maxN = 400;
  int maxV = 0;  // 0: no sweep over V
  std::vector<std::string> methods{"paper", "local"};
  std::uint64_t seed = 1;
  std::string csv;
  std::string svg;
  // Instead of the sweeps: whole runs of these scene files (sim.duration unless --duration is
  // given), each the median of `repeat` runs, on `threads` threads (camcov run --threads).
  std::vector<std::string> scenes;
  int repeat = 3;
  unsigned threads = 1;
};

// What one sweep varies.
enum class Axis { Cameras, Targets, Vertices };

struct Sweep {
  Axis axis;
  std::string symbol;  // "M"
  std::string name;    // "cameras"
  std::vector<int> values;
};

struct Point {
  const Sweep* sweep = nullptr;
  std::string method;
  int cameras = 0, targets = 0, vertices = 0;
  double field = 0.0;      // m, side of the square field
  double simulated = 0.0;  // s
  double wall = 0.0;       // s
  double cost() const { return wall / simulated; }
};

// Points with the swept value at least this enter the fits.
constexpr int kFitFrom = 4;

int swept(const Point& p) {
  switch (p.sweep->axis) {
    case Axis::Cameras:
      return p.cameras;
    case Axis::Targets:
      return p.targets;
    case Axis::Vertices:
      return p.vertices;
  }
  return 0;
}

double fieldSide(int targets) {
  return std::max(20.0, 10.0 * std::sqrt(static_cast<double>(targets)));
}

// Wall seconds of one whole run of `scene` (making the controller is part of it, as in
// `camcov run`).
double timeRun(const scene::Scene& scene, const std::string& method, double duration,
               std::uint64_t seed) {
  records::RunMetadata metadata;
  metadata.scene = scene.name;
  metadata.method = method;
  metadata.seed = seed;
  metadata.parameters.sim.duration = duration;
  const auto start = std::chrono::steady_clock::now();
  const auto controller = control::requireMethod(method).make(scene, metadata.parameters, seed);
  batch::recordRun(scene, metadata, *controller);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  return wall.count();
}

Point measure(const Options& o, const Sweep& sweep, const std::string& method, int cameras,
              int targets, int vertices) {
  scene::GeneratorOptions g;
  g.targets = targets;
  g.cameras = cameras;
  g.vertices = vertices;
  g.fieldWidth = g.fieldHeight = fieldSide(targets);
  g.seed = o.seed;
  const scene::Scene scene = scene::parseScene(scene::generateScene(g).dump(), "scaling.json");
  return {&sweep,   method,       cameras,    targets,
          vertices, g.fieldWidth, o.duration, timeRun(scene, method, o.duration, o.seed)};
}

// Whole runs of scene files: the real-time factor of each method.
int runScenes(const Options& o, bool durationGiven) {
  std::cout << fmt::format(
      "| scene | targets | cameras | method | threads | simulated, s | wall, s (median of {}) | "
      "real-time factor |\n|---|---|---|---|---|---|---|---|\n",
      o.repeat);
  setRunThreads(o.threads);
  for (const std::string& file : o.scenes) {
    const scene::Scene scene = scene::loadScene(file);
    const double duration = durationGiven ? o.duration : params::Parameters{}.sim.duration;
    for (const auto& m : o.methods) {
      std::vector<double> walls;
      for (int r = 0; r < o.repeat; ++r)
        walls.push_back(timeRun(scene, m, duration, o.seed));
      std::sort(walls.begin(), walls.end());
      const double wall = walls[walls.size() / 2];
      std::cout << fmt::format("| {} | {} | {} | {} | {} | {:g} | {:.3f} | {:.1f} |\n", scene.name,
                               scene.targets.size(), scene.cameras.size(), m, o.threads, duration,
                               wall, duration / wall);
    }
  }
  return 0;
}

// The least-squares slope of log(cost) over log(swept value), over the points of one sweep
// and method from kFitFrom on; NaN with fewer than two such points.
double exponent(const std::vector<Point>& points, const Sweep& sweep, const std::string& method) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Point& p : points) {
    if (p.sweep != &sweep || p.method != method || swept(p) < kFitFrom) continue;
    const double x = std::log(swept(p)), y = std::log(p.cost());
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double d = n * sxx - sx * sx;
  return n >= 2 && d > 0 ? (n * sxy - sx * sy) / d : std::nan("");
}

std::string exponentText(double a) {
  // + 0.0: a slope that rounds to zero prints as 0.00, not -0.00.
  return std::isnan(a) ? std::string("—") : fmt::format("{:.2f}", std::round(a * 100) / 100 + 0.0);
}

std::string fitRange(const Sweep& sweep) {
  std::string values;
  for (const int v : sweep.values) {
    if (v >= kFitFrom) values += (values.empty() ? "" : ", ") + std::to_string(v);
  }
  return fmt::format("{} ≥ {} ({})", sweep.symbol, kFitFrom, values);
}

void printSweep(const Options& o, const std::vector<Point>& points, const Sweep& sweep) {
  std::cout << fmt::format("\n## {} {}\n\n", sweep.name, sweep.symbol);
  std::cout << "| method | M | N | V | field, m | wall, s | cost, s per simulated s | real-time "
               "factor |\n|---|---|---|---|---|---|---|---|\n";
  for (const Point& p : points) {
    if (p.sweep != &sweep) continue;
    std::cout << fmt::format("| {} | {} | {} | {} | {:.0f} | {:.4g} | {:.4g} | {:.1f} |\n",
                             p.method, p.cameras, p.targets, p.vertices, p.field, p.wall, p.cost(),
                             1.0 / p.cost());
  }
  std::string fits;
  for (const auto& m : o.methods) {
    fits += fmt::format("{}{} cost ∝ {}^{}", fits.empty() ? "" : ", ", m, sweep.symbol,
                        exponentText(exponent(points, sweep, m)));
  }
  std::cout << fmt::format("\nFitted over {}: {}.\n", fitRange(sweep), fits);
}

void writeCsv(const std::string& file, const std::vector<Point>& points) {
  std::ofstream out(file);
  out << "sweep,method,cameras,targets,vertices,field_m,simulated_s,wall_s,cost,"
         "real_time_factor\n";
  for (const Point& p : points) {
    out << fmt::format("{},{},{},{},{},{},{},{:.6f},{:.6f},{:.4f}\n", p.sweep->name, p.method,
                       p.cameras, p.targets, p.vertices, p.field, p.simulated, p.wall, p.cost(),
                       1.0 / p.cost());
  }
  if (!out) throw InputError(file + ": cannot write");
}

// One log-log chart per sweep, side by side, each method a line in its own colour with its
// fitted exponent in the legend.
void writeSvg(const Options& o, const std::vector<Point>& points,
              const std::vector<Sweep>& sweeps) {
  constexpr double kWidth = 460.0, kHeight = 340.0;
  constexpr double kGap = 48.0;  // between charts: the last tick label reaches past its chart
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const Point& p : points) {
    lo = std::min(lo, p.cost());
    hi = std::max(hi, p.cost());
  }
  std::string charts;
  for (std::size_t i = 0; i < sweeps.size(); ++i) {
    const Sweep& s = sweeps[i];
    reports::ChartSpec spec;
    spec.width = kWidth;
    spec.height = kHeight;
    spec.ariaLabel = "cost against " + s.name;
    spec.x = {fmt::format("{} {} (fitted over {} ≥ {})", s.name, s.symbol, s.symbol, kFitFrom),
              static_cast<double>(s.values.front()), static_cast<double>(s.values.back()), 6, true};
    spec.y = {"wall s per simulated s", lo, hi, 6, true};
    for (const auto& m : o.methods) {
      spec.legend.push_back(
          {fmt::format("{}: ∝ {}^{}", m, s.symbol, exponentText(exponent(points, s, m))),
           control::requireMethod(m).color});
    }
    reports::Chart chart(spec);
    for (const auto& m : o.methods) {
      std::vector<double> xs, ys;
      for (const Point& p : points) {
        if (p.sweep != &s || p.method != m) continue;
        xs.push_back(swept(p));
        ys.push_back(p.cost());
      }
      chart.addLine(xs, ys, control::requireMethod(m).color, 2.0);
    }
    charts += fmt::format("<g transform=\"translate({} 0)\">\n{}</g>\n", (kWidth + kGap) * i,
                          chart.svg());
  }
  const double width = (kWidth + kGap) * sweeps.size();
  std::ofstream out(o.svg);
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {0} {1}\" width=\"{0}\" "
      "height=\"{1}\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" "
      "fill=\"white\"/>\n{2}</svg>\n",
      width, kHeight, charts);
  if (!out) throw InputError(o.svg + ": cannot write");
}

std::vector<int> upTo(std::vector<int> values, int max) {
  std::erase_if(values, [max](int v) { return v > max; });
  return values;
}

int run(const Options& options) {
  for (const auto& m : options.methods)
    control::requireMethod(m);
  std::vector<Sweep> sweeps{
      {Axis::Cameras, "M", "cameras", upTo({1, 2, 4, 8, 16, 32, 64}, options.maxM)},
      {Axis::Targets, "N", "targets", upTo({1, 4, 16, 64, 100, 256, 400}, options.maxN)}};
  if (options.maxV > 0)
    sweeps.push_back({Axis::Vertices, "V", "vertices", upTo({4, 16, 64, 256, 1024}, options.maxV)});
  std::erase_if(sweeps, [](const Sweep& s) { return s.values.empty(); });

  std::cout << fmt::format(
      "# Cost of one simulated second (wall s / simulated s), {} s simulated per point\n\n"
      "Generated scenes, seed {}: 1 x 1 m targets on 2 m square loops at 1 m/s in a square "
      "field of side max(20, 10·√N) m; sweeps over M at N = {}, over N at M = {}{}.\n",
      options.duration, options.seed, options.nFixed, options.mFixed,
      options.maxV > 0 ? fmt::format(", over V at N = {}, M = {}", options.nFixed, options.mFixed)
                       : "");
  std::vector<Point> points;
  for (const Sweep& s : sweeps) {
    for (const auto& m : options.methods) {
      for (const int v : s.values) {
        const int cameras = s.axis == Axis::Cameras ? v : options.mFixed;
        const int targets = s.axis == Axis::Targets ? v : options.nFixed;
        points.push_back(
            measure(options, s, m, cameras, targets, s.axis == Axis::Vertices ? v : 4));
        std::cerr << fmt::format("{} {} = {}: {:.3f} s\n", m, s.symbol, v, points.back().wall);
      }
    }
    printSweep(options, points, s);
  }
  if (!options.csv.empty()) writeCsv(options.csv, points);
  if (!options.svg.empty()) writeSvg(options, points, sweeps);
  return 0;
}

}  // namespace
}  // namespace camcov

int main(int argc, char** argv) {
  camcov::Options options;
  CLI::App app{"Cost of a run against cameras M, targets N and vertices V"};
  bool quick = false;
  app.add_option("--duration", options.duration, "simulated s per point")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--n-fixed", options.nFixed, "targets in the sweeps over M and V")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  app.add_option("--m-fixed", options.mFixed, "cameras in the sweeps over N and V")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--max-m", options.maxM, "largest M of 1, 2, 4, ..., 64")->capture_default_str();
  app.add_option("--max-n", options.maxN, "largest N of 1, 4, 16, 64, 100, 256, 400")
      ->capture_default_str();
  app.add_option("--max-v", options.maxV,
                 "largest V of 4, 16, 64, 256, 1024 (default 0: no sweep over V)")
      ->capture_default_str();
  app.add_option("--methods", options.methods, "methods to measure")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--seed", options.seed, "seed of the scenes and the runs")->capture_default_str();
  app.add_option("--csv", options.csv, "write the points to this CSV file");
  app.add_option("--svg", options.svg, "write the log-log plot to this SVG file");
  app.add_option("--scene", options.scenes,
                 "instead of the sweeps: time whole runs of these scene files (repeatable)");
  app.add_option("--repeat", options.repeat, "runs per scene and method; the median is printed")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  app.add_option("--threads", options.threads, "threads per run, with --scene")
      ->check(CLI::Range(1u, 256u))
      ->capture_default_str();
  app.add_flag("--quick", quick,
               "a small grid for a smoke test, for the options not given: 0.5 s per point, M up "
               "to 8 at N = 8, N up to 16 at M = 2");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    const auto unless = [&app](const char* option, auto& value, auto quickValue) {
      if (app.count(option) == 0) value = quickValue;
    };
    unless("--duration", options.duration, 0.5);
    unless("--n-fixed", options.nFixed, 8);
    unless("--m-fixed", options.mFixed, 2);
    unless("--max-m", options.maxM, 8);
    unless("--max-n", options.maxN, 16);
  }
  try {
    if (!options.scenes.empty()) return camcov::runScenes(options, app.count("--duration") > 0);
    return camcov::run(options);
  } catch (const camcov::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
