#include "records/run_files.h"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <string_view>
#include <utility>

#include "util/input_error.h"
#include "util/input_file.h"

#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "records/json_numbers.h"
#include "records/known_keys.h"
#include "records/pretty_json.h"
#include "scene/scene_validation.h"
#include "util/readable_number.h"

namespace camcov::records {
namespace {

nlohmann::json pose(const geometry::Pose& p) {
  return nlohmann::json::array({p.x, p.y, p.yaw});
}

geometry::Pose poseFrom(const nlohmann::json& v) {
  return {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>()};
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The latest time a run may record, s: far past any scene's duration (scene::kMaxDuration).
constexpr double kMaxRecordedTime = 1e9;

// The columns of a run file's "series" the reader knows (runJsonText writes them; a column it
// wrote that is not here would be refused on reading, as the round-trip tests would show): one
// value a step in every run; one value a step where the scene asks for it (weighted targets, a
// resolution, targets that come and go, limited knowledge); a list a camera.
constexpr std::array<std::string_view, 11> kStepSeries{"time",
                                                       "coverage",
                                                       "utilization",
                                                       "repulsion",
                                                       "reward",
                                                       "minObjectDistance",
                                                       "minCameraDistance",
                                                       "minObjectDistanceInStep",
                                                       "minCameraDistanceInStep",
                                                       "avoidableContactTime",
                                                       "unavoidableContactTime"};
constexpr std::array<std::string_view, 4> kOptionalStepSeries{
    "weightedCoverage", "resolutionCoverage", "targetsPresent", "heard"};
constexpr std::array<std::string_view, 2> kCameraSeries{"cameras", "goals"};

// The series of a results file, checked as they are read, so that a file edited by hand or
// cut short is refused with the column and step named instead of drawing, encoding or
// summarizing numbers no run can produce: every column one entry a step, every entry a finite
// number in its range.
class SeriesReader {
 public:
  SeriesReader(const nlohmann::json& series, const std::string& source)
      : series_(series), source_(source) {}

  // series[name], an array; its length is checked against series.time's where it is read.
  // Found once a name: a file holds a dozen columns and reads each at every step.
  const nlohmann::json& column(const char* name) const {
    for (const auto& [known, c] : columns_) {
      if (known == name) return *c;
    }
    const nlohmann::json& c = series_.at(name);
    if (!c.is_array()) throw InputError(fmt::format("{}: series.{} is not a list", source_, name));
    columns_.emplace_back(name, &c);
    return c;
  }
  // Entry k of column `name`, whatever it holds (the column one entry a step).
  const nlohmann::json& entryOf(const char* name, std::size_t k) const {
    return entry(column(name), k, name);
  }
  double number(const char* name, std::size_t k, double lo, double hi) const {
    return within(entry(column(name), k, name), lo, hi,
                  [&] { return fmt::format("series.{}[{}]", name, k); });
  }
  // A distance: a number ≥ 0, or null for none (infinity: no pair of cameras).
  double distance(const char* name, std::size_t k) const {
    const nlohmann::json& v = entry(column(name), k, name);
    return v.is_null()
               ? kInfinity
               : within(v, 0.0, kInfinity, [&] { return fmt::format("series.{}[{}]", name, k); });
  }
  // [x, y, yaw] of camera c at step k of series.cameras or series.goals.
  geometry::Pose pose(const nlohmann::json& perCamera, const char* name, std::size_t c,
                      std::size_t k) const {
    const auto where = [&](const char* part = "") {
      return fmt::format("series.{}[{}][{}]{}", name, c, k, part);
    };
    if (!perCamera.is_array() || k >= perCamera.size())
      throw InputError(fmt::format("{}: {} is missing", source_, where()));
    const nlohmann::json& p = perCamera[k];
    if (!p.is_array() || p.size() != 3)
      throw InputError(fmt::format("{}: {} is not a pose [x, y, yaw]", source_, where()));
    return {
        within(p[0], -scene::kMaxCoordinate, scene::kMaxCoordinate, [&] { return where("[0]"); }),
        within(p[1], -scene::kMaxCoordinate, scene::kMaxCoordinate, [&] { return where("[1]"); }),
        within(p[2], -kMaxYaw, kMaxYaw, [&] { return where("[2]"); })};
  }

 private:
  // rad: a camera's yaw is wrapped to [-π, π], a goal's as its method gives it, within what a
  // scene may write (scene::kMaxYawDegrees).
  static constexpr double kMaxYaw = scene::kMaxYawDegrees * 3.141592653589793 / 180.0;

  const nlohmann::json& entry(const nlohmann::json& column, std::size_t k, const char* name) const {
    const std::size_t steps = this->column("time").size();
    if (column.size() != steps) {
      throw InputError(fmt::format("{}: series.{} has {} entries for {} steps", source_, name,
                                   column.size(), steps));
    }
    return column[k];
  }
  // `where` names the value, worked out only for the message of a value refused.
  template <typename Where>
  double within(const nlohmann::json& v, double lo, double hi, const Where& where) const {
    if (!v.is_number()) throw InputError(fmt::format("{}: {} is not a number", source_, where()));
    const double x = v.get<double>();
    if (!(x >= lo && x <= hi)) {
      throw InputError(
          fmt::format("{}: {} = {} lies outside [{}, {}], where every run's values "
                      "lie",
                      source_, where(), x, lo, hi));
    }
    return x;
  }

  const nlohmann::json& series_;
  const std::string& source_;
  mutable std::vector<std::pair<const char*, const nlohmann::json*>> columns_;
};

// The summary's average coverage is its series' (eq. (4) by the trapezoid rule over the
// intervals with targets at both ends, as the simulator takes it): a summary edited by hand, or
// series edited without it, is refused rather than reported.
void requireSummaryOfSeries(const RunRecord& run, const std::string& source) {
  const double dt = run.metadata.parameters.sim.dt;
  double integral = 0.0;
  int measured = 0;
  for (std::size_t k = 1; k < run.steps.size(); ++k) {
    const StepRow &before = run.steps[k - 1], &now = run.steps[k];
    if (before.targetsPresent == 0 || now.targetsPresent == 0) continue;
    integral += 0.5 * (before.terms.coverage + now.terms.coverage) * dt;
    ++measured;
  }
  const double average = measured > 0 ? integral / (measured * dt) : 0.0;
  if (std::abs(average - run.summary.averageCoverage) > 1e-9) {
    throw InputError(
        fmt::format("{}: summary.averageCoverage = {} is not its series' average "
                    "coverage ({})",
                    source, run.summary.averageCoverage, average));
  }
}

sim::RunSummary summaryFrom(const nlohmann::json& j, const std::string& source) {
  requireKnownKeys(j,
                   {"steps",
                    "duration",
                    "averageCoverage",
                    "averageUtilization",
                    "averageReward",
                    "finalCoverage",
                    "minObjectDistance",
                    "minCameraDistance",
                    "objectCollisionTime",
                    "cameraCollisionTime",
                    "avoidableContactTime",
                    "unavoidableContactTime",
                    "avoidableContacts",
                    "unavoidableContacts",
                    "boundaryClamps",
                    "stepsWithoutTargets",
                    "averageWeightedCoverage",
                    "finalWeightedCoverage",
                    "averageResolutionCoverage",
                    "finalResolutionCoverage",
                    "messages"},
                   "summary", source);
  sim::RunSummary s;
  s.steps = wholeNumberFrom<int>(j.at("steps"), "steps", source);
  s.duration = j.at("duration").get<double>();
  s.averageCoverage = j.at("averageCoverage").get<double>();
  s.averageUtilization = j.at("averageUtilization").get<double>();
  s.averageReward = j.at("averageReward").get<double>();
  // Runs written before final coverage was recorded lack it: NaN, which the summary leaves out.
  s.finalCoverage = j.contains("finalCoverage") ? j.at("finalCoverage").get<double>()
                                                : std::numeric_limits<double>::quiet_NaN();
  s.minObjectDistance = numberOrInfinity(j.at("minObjectDistance"));
  s.minCameraDistance = numberOrInfinity(j.at("minCameraDistance"));
  s.objectCollisionTime = j.at("objectCollisionTime").get<double>();
  s.cameraCollisionTime = j.at("cameraCollisionTime").get<double>();
  s.avoidableContactTime = j.at("avoidableContactTime").get<double>();
  s.unavoidableContactTime = j.at("unavoidableContactTime").get<double>();
  s.avoidableContacts =
      wholeNumberFrom<int>(j.at("avoidableContacts"), "avoidableContacts", source);
  s.unavoidableContacts =
      wholeNumberFrom<int>(j.at("unavoidableContacts"), "unavoidableContacts", source);
  s.boundaryClamps = wholeNumberFrom<int>(j.at("boundaryClamps"), "boundaryClamps", source);
  s.stepsWithoutTargets =
      j.contains("stepsWithoutTargets")
          ? wholeNumberFrom<int>(j.at("stepsWithoutTargets"), "stepsWithoutTargets", source)
          : 0;
  if (j.contains("averageWeightedCoverage"))
    s.averageWeightedCoverage = j.at("averageWeightedCoverage").get<double>();
  if (j.contains("finalWeightedCoverage"))
    s.finalWeightedCoverage = j.at("finalWeightedCoverage").get<double>();
  if (j.contains("averageResolutionCoverage"))
    s.averageResolutionCoverage = j.at("averageResolutionCoverage").get<double>();
  if (j.contains("finalResolutionCoverage"))
    s.finalResolutionCoverage = j.at("finalResolutionCoverage").get<double>();
  if (j.contains("messages")) {
    const nlohmann::json& m = j.at("messages");
    s.messages = sim::MessageCounts{wholeNumberFrom<int>(m.at("sent"), "sent", source),
                                    wholeNumberFrom<int>(m.at("delivered"), "delivered", source),
                                    wholeNumberFrom<int>(m.at("lost"), "lost", source)};
  }
  return s;
}

// A run's CSV, beside its JSON file.
std::filesystem::path csvFileOf(std::filesystem::path jsonFile) {
  return jsonFile.replace_extension(".csv");
}

}  // namespace

nlohmann::json summaryJson(const sim::RunSummary& s) {
  nlohmann::json j = {{"steps", s.steps},
                      {"duration", s.duration},
                      {"averageCoverage", s.averageCoverage},
                      {"averageUtilization", s.averageUtilization},
                      {"averageReward", s.averageReward},
                      {"minObjectDistance", finiteOrNull(s.minObjectDistance)},
                      {"minCameraDistance", finiteOrNull(s.minCameraDistance)},
                      {"objectCollisionTime", s.objectCollisionTime},
                      {"cameraCollisionTime", s.cameraCollisionTime},
                      {"avoidableContactTime", s.avoidableContactTime},
                      {"unavoidableContactTime", s.unavoidableContactTime},
                      {"avoidableContacts", s.avoidableContacts},
                      {"unavoidableContacts", s.unavoidableContacts},
                      {"boundaryClamps", s.boundaryClamps}};
  // A run read from a file written before final coverage was recorded has none: it stays out.
  if (!std::isnan(s.finalCoverage)) j["finalCoverage"] = s.finalCoverage;
  // Only recorded tracks leave a scene empty; other runs keep their bytes.
  if (s.stepsWithoutTargets > 0) j["stepsWithoutTargets"] = s.stepsWithoutTargets;
  // Only weighted scenes have weighted coverage; the same.
  if (s.averageWeightedCoverage) j["averageWeightedCoverage"] = *s.averageWeightedCoverage;
  if (s.finalWeightedCoverage) j["finalWeightedCoverage"] = *s.finalWeightedCoverage;
  // Only scenes with a resolution have resolution coverage; the same.
  if (s.averageResolutionCoverage) j["averageResolutionCoverage"] = *s.averageResolutionCoverage;
  if (s.finalResolutionCoverage) j["finalResolutionCoverage"] = *s.finalResolutionCoverage;
  // Only runs under limited knowledge send messages; the same.
  if (s.messages) {
    j["messages"] = {{"sent", s.messages->sent},
                     {"delivered", s.messages->delivered},
                     {"lost", s.messages->lost}};
  }
  return j;
}

std::string runStem(const std::string& scene, const std::string& method, std::uint64_t seed) {
  return fmt::format("{}-{}-seed{}", scene, method, seed);
}

std::string runStem(const RunMetadata& m) {
  return runStem(m.scene, m.method, m.seed);
}

std::optional<std::string> sceneOfStem(const std::string& stem,
                                       const std::vector<std::string>& methods) {
  const auto seed = stem.rfind("-seed");
  if (seed == std::string::npos || seed + 5 == stem.size() ||
      !std::all_of(stem.begin() + static_cast<std::ptrdiff_t>(seed) + 5, stem.end(),
                   [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  const std::string_view sceneAndMethod = std::string_view(stem).substr(0, seed);
  std::optional<std::string> scene;
  std::size_t longest = 0;
  for (const std::string& method : methods) {
    const std::string ending = "-" + method;
    if (method.size() > longest && sceneAndMethod.size() > ending.size() &&
        sceneAndMethod.ends_with(ending)) {
      longest = method.size();
      scene = std::string(sceneAndMethod.substr(0, sceneAndMethod.size() - ending.size()));
    }
  }
  return scene;
}

std::string runJsonText(const RunRecord& run) {
  const RunMetadata& m = run.metadata;
  std::string text;
  PrettyJson w(text);
  w.beginObject();

  w.key("events");
  w.beginArray();
  for (const auto& e : run.events) {
    nlohmann::json event = {
        {"time", e.time}, {"kind", e.kind}, {"camera", e.camera}, {"detail", e.detail}};
    if (!e.reason.empty()) event["reason"] = e.reason;
    if (!e.path.empty()) {
      event["path"] = nlohmann::json::array();
      for (const auto& p : e.path)
        event["path"].push_back(pose(p));
    }
    w.value(event);
  }
  w.endArray();
  w.key("format");
  w.value(kRunFormat);
  w.key("method");
  w.value(m.method);
  w.key("parameters");
  w.value(params::toJson(m.parameters));
  w.key("scene");
  w.value({{"name", m.scene}, {"file", m.sceneFile}, {"hash", hashText(m.sceneHash)}});
  w.key("seed");
  w.value(m.seed);

  // The time series, column by column; poses as [x, y, yaw (rad)]. Written straight from the
  // steps, in the order of their names (as a JSON object keeps them).
  using Column = std::pair<std::string_view, std::function<void()>>;
  std::vector<Column> columns;
  const auto numbers = [&](std::string_view name, auto of) {
    columns.emplace_back(name, [&w, &run, of] {
      w.beginArray();
      for (const StepRow& row : run.steps)
        w.number(of(row));
      w.endArray();
    });
  };
  // Distances that are undefined (no object, a single camera) are infinite, written as null.
  numbers("time", [](const StepRow& r) { return r.time; });
  numbers("coverage", [](const StepRow& r) { return r.terms.coverage; });
  numbers("utilization", [](const StepRow& r) { return r.terms.utilization; });
  numbers("repulsion", [](const StepRow& r) { return r.terms.repulsion; });
  numbers("reward", [](const StepRow& r) { return r.terms.reward; });
  numbers("minObjectDistance", [](const StepRow& r) { return r.minObjectDistance; });
  numbers("minCameraDistance", [](const StepRow& r) { return r.minCameraDistance; });
  numbers("minObjectDistanceInStep", [](const StepRow& r) { return r.minObjectDistanceInStep; });
  numbers("minCameraDistanceInStep", [](const StepRow& r) { return r.minCameraDistanceInStep; });
  numbers("avoidableContactTime", [](const StepRow& r) { return r.avoidableContactTime; });
  numbers("unavoidableContactTime", [](const StepRow& r) { return r.unavoidableContactTime; });
  // Weighted scenes' runs (RunSummary::averageWeightedCoverage) record weighted coverage too.
  if (run.summary.averageWeightedCoverage)
    numbers("weightedCoverage", [](const StepRow& r) { return r.terms.weightedCoverage; });
  // Runs of scenes with a resolution (RunSummary::averageResolutionCoverage) record it too.
  if (run.summary.averageResolutionCoverage)
    numbers("resolutionCoverage", [](const StepRow& r) { return r.resolutionCoverage; });
  // Scenes whose targets come and go (recorded tracks) say how many are present at each step.
  if (!run.steps.empty() && run.steps.front().targetsPresent >= 0) {
    columns.emplace_back("targetsPresent", [&w, &run] {
      w.beginArray();
      for (const StepRow& row : run.steps)
        w.integer(row.targetsPresent);
      w.endArray();
    });
  }
  // Runs under limited knowledge (RunSummary::messages) say who heard whom at each step:
  // [from, to, sent at].
  if (run.summary.messages) {
    columns.emplace_back("heard", [&w, &run] {
      w.beginArray();
      for (const StepRow& row : run.steps) {
        w.beginArray();
        for (const sim::Hearing& h : row.heard) {
          w.beginArray();
          w.integer(h.from);
          w.integer(h.to);
          w.number(h.sentAt);
          w.endArray();
        }
        w.endArray();
      }
      w.endArray();
    });
  }
  const std::size_t cameras = run.steps.empty() ? 0 : run.steps.front().cameras.size();
  const auto posesOf = [&](std::string_view name, auto poseAt) {
    columns.emplace_back(name, [&w, &run, cameras, poseAt] {
      w.beginArray();
      for (std::size_t c = 0; c < cameras; ++c) {
        w.beginArray();
        for (const StepRow& row : run.steps) {
          const std::optional<geometry::Pose> p = poseAt(row, c);
          if (!p) {
            w.null();
            continue;
          }
          w.beginArray();
          w.number(p->x);
          w.number(p->y);
          w.number(p->yaw);
          w.endArray();
        }
        w.endArray();
      }
      w.endArray();
    });
  };
  posesOf("cameras", [](const StepRow& r, std::size_t c) -> std::optional<geometry::Pose> {
    return r.cameras[c];
  });
  posesOf("goals", [](const StepRow& r, std::size_t c) { return r.goals[c]; });
  std::sort(columns.begin(), columns.end(),
            [](const Column& a, const Column& b) { return a.first < b.first; });
  w.key("series");
  w.beginObject();
  for (const auto& [name, write] : columns) {
    w.key(name);
    write();
  }
  w.endObject();

  w.key("summary");
  w.value(summaryJson(run.summary));
  w.key("tool");
  w.value({{"name", "camcov"}, {"version", m.toolVersion}});
  w.endObject();
  text += '\n';
  return text;
}

nlohmann::json runToJson(const RunRecord& run) {
  return nlohmann::json::parse(runJsonText(run));
}

RunRecord runFromJson(const nlohmann::json& j, const std::string& source) {
  try {
    if (j.at("format") != kRunFormat) {
      throw InputError(source + ": not a " + std::string(kRunFormat) + " results file");
    }
    RunRecord run;
    RunMetadata& m = run.metadata;
    m.scene = j.at("scene").at("name").get<std::string>();
    m.sceneFile = j.at("scene").at("file").get<std::string>();
    m.sceneHash = hashFrom(j.at("scene").at("hash"), "scene.hash", source);
    m.method = j.at("method").get<std::string>();
    m.seed = wholeNumberFrom<std::uint64_t>(j.at("seed"), "seed", source);
    m.parameters = params::fromJson(j.at("parameters"), source);
    m.toolVersion = j.at("tool").at("version").get<std::string>();
    requireKnownKeys(
        j,
        {"format", "tool", "scene", "method", "seed", "parameters", "summary", "series", "events"},
        "the run file", source);
    requireKnownKeys(j.at("scene"), {"name", "file", "hash"}, "scene", source);
    requireKnownKeys(j.at("tool"), {"name", "version"}, "tool", source);
    run.summary = summaryFrom(j.at("summary"), source);

    const nlohmann::json& series = j.at("series");
    requireKnownKeys(series, {kStepSeries, kOptionalStepSeries, kCameraSeries}, "series", source);
    const SeriesReader read(series, source);
    const auto& time = read.column("time");
    const std::size_t steps = time.size();
    if (steps == 0 || static_cast<std::size_t>(run.summary.steps) != steps) {
      throw InputError(fmt::format("{}: the summary says {} steps, series.time holds {}", source,
                                   run.summary.steps, steps));
    }
    const auto& cameras = series.at("cameras");
    const auto& goals = series.at("goals");
    if (!cameras.is_array() || !goals.is_array() || goals.size() != cameras.size())
      throw InputError(source + ": series.cameras and series.goals need one list per camera");
    // Fractions, with the last bits a sum of lengths or angles may round to past 1.
    const auto fraction = [&](const char* name, std::size_t k) {
      return read.number(name, k, 0.0, 1.0 + 1e-9);
    };
    const bool weighted = series.contains("weightedCoverage"),
               resolution = series.contains("resolutionCoverage"),
               presence = series.contains("targetsPresent"), heard = series.contains("heard");
    for (std::size_t k = 0; k < steps; ++k) {
      StepRow row;
      row.time = read.number("time", k, 0.0, kMaxRecordedTime);
      if (k > 0 && !(row.time > run.steps.back().time)) {
        throw InputError(
            fmt::format("{}: series.time[{}] = {} does not come after the step "
                        "before it ({}): a run's times increase",
                        source, k, row.time, run.steps.back().time));
      }
      row.terms.coverage = fraction("coverage", k);
      // Recorded for weighted scenes only; elsewhere the two are one.
      row.terms.weightedCoverage = weighted ? fraction("weightedCoverage", k) : row.terms.coverage;
      if (resolution) row.resolutionCoverage = fraction("resolutionCoverage", k);
      row.terms.utilization = fraction("utilization", k);
      row.terms.repulsion = read.number("repulsion", k, 0.0, kInfinity);
      row.terms.reward = read.number("reward", k, -kInfinity, kInfinity);
      row.minObjectDistance = read.distance("minObjectDistance", k);
      row.minCameraDistance = read.distance("minCameraDistance", k);
      row.minObjectDistanceInStep = read.distance("minObjectDistanceInStep", k);
      row.minCameraDistanceInStep = read.distance("minCameraDistanceInStep", k);
      row.avoidableContactTime = read.number("avoidableContactTime", k, 0.0, kMaxRecordedTime);
      row.unavoidableContactTime = read.number("unavoidableContactTime", k, 0.0, kMaxRecordedTime);
      if (presence)
        row.targetsPresent = static_cast<int>(read.number("targetsPresent", k, 0.0, 1e9));
      if (heard) {
        for (const auto& h : read.entryOf("heard", k)) {
          const sim::Hearing hearing{wholeNumberFrom<int>(h.at(0), "series.heard[][0]", source),
                                     wholeNumberFrom<int>(h.at(1), "series.heard[][1]", source),
                                     h.at(2).get<double>()};
          if (hearing.from < 0 || hearing.to < 0 ||
              hearing.from >= static_cast<int>(cameras.size()) ||
              hearing.to >= static_cast<int>(cameras.size()) || !(hearing.sentAt <= row.time))
            throw InputError(
                fmt::format("{}: series.heard[{}] names a camera or a time the run "
                            "does not have",
                            source, k));
          row.heard.push_back(hearing);
        }
      }
      for (std::size_t c = 0; c < cameras.size(); ++c) {
        row.cameras.push_back(read.pose(cameras.at(c), "cameras", c, k));
        const auto& g = goals.at(c);
        if (!g.is_array() || g.size() != steps)
          throw InputError(fmt::format("{}: series.goals[{}] needs one entry a step", source, c));
        row.goals.push_back(g.at(k).is_null() ? std::nullopt
                                              : std::optional(read.pose(g, "goals", c, k)));
      }
      run.steps.push_back(std::move(row));
    }
    requireSummaryOfSeries(run, source);
    const double lastTime = run.steps.back().time;
    const int cameraCount = static_cast<int>(cameras.size());
    for (const auto& e : j.at("events")) {
      const double at = e.at("time").get<double>();
      const int camera = wholeNumberFrom<int>(e.at("camera"), "camera", source);
      if (!(at >= 0.0 && at <= lastTime) || camera < -1 || camera >= cameraCount) {
        throw InputError(fmt::format(
            "{}: an event at {} s of camera {} lies outside the run "
            "(0 to {} s, cameras 0 to {}, -1 for none)",
            source, roundedNumber(at), camera, roundedNumber(lastTime), cameraCount - 1));
      }
      control::ControlEvent event{at,     e.at("kind").get<std::string>(),
                                  camera, e.at("detail").get<std::string>(),
                                  {},     e.value("reason", std::string())};
      if (e.contains("path")) {
        for (const auto& p : e.at("path")) {
          event.path.push_back(poseFrom(p));
          if (!std::isfinite(event.path.back().x) || !std::isfinite(event.path.back().y) ||
              std::abs(event.path.back().x) > scene::kMaxCoordinate ||
              std::abs(event.path.back().y) > scene::kMaxCoordinate)
            throw InputError(source + ": an event's path leaves every scene's coordinates");
        }
      }
      run.events.push_back(std::move(event));
    }
    return run;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": malformed results file: " + e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(source + ": malformed results file: " + e.what());
  }
}

RunRecord loadRunFile(const std::filesystem::path& file) {
  const std::string text = readWholeFile(file);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": invalid JSON: " + e.what());
  }
  return runFromJson(j, file.string());
}

std::string runToCsv(const RunRecord& run) {
  // fmt's own buffer, which its formatting writes straight into, the rows' formats compiled.
  fmt::memory_buffer csv;
  const auto out = std::back_inserter(csv);
  fmt::format_to(out,
                 "time,coverage,utilization,repulsion,reward,min_object_distance,"
                 "min_camera_distance,min_object_distance_in_step,min_camera_distance_in_step,"
                 "avoidable_contact_time,unavoidable_contact_time");
  const bool weighted = run.summary.averageWeightedCoverage.has_value();
  if (weighted) fmt::format_to(out, ",weighted_coverage");
  const bool resolution = run.summary.averageResolutionCoverage.has_value();
  if (resolution) fmt::format_to(out, ",resolution_coverage");
  const std::size_t cameras = run.steps.empty() ? 0 : run.steps.front().cameras.size();
  for (std::size_t c = 0; c < cameras; ++c)
    fmt::format_to(out, ",cam{0}_x,cam{0}_y,cam{0}_yaw", c);
  csv.push_back('\n');
  for (const StepRow& row : run.steps) {
    fmt::format_to(out, FMT_COMPILE("{},{},{},{},{},{},{},{},{},{},{}"), row.time,
                   row.terms.coverage, row.terms.utilization, row.terms.repulsion, row.terms.reward,
                   row.minObjectDistance, row.minCameraDistance, row.minObjectDistanceInStep,
                   row.minCameraDistanceInStep, row.avoidableContactTime,
                   row.unavoidableContactTime);
    if (weighted) fmt::format_to(out, FMT_COMPILE(",{}"), row.terms.weightedCoverage);
    if (resolution) fmt::format_to(out, FMT_COMPILE(",{}"), row.resolutionCoverage);
    for (const auto& p : row.cameras)
      fmt::format_to(out, FMT_COMPILE(",{},{},{}"), p.x, p.y, p.yaw);
    csv.push_back('\n');
  }
  return fmt::to_string(csv);
}

std::filesystem::path writeRunFiles(const RunRecord& run, const std::filesystem::path& folder,
                                    Durability durability) {
  const auto json = folder / (runStem(run.metadata) + ".json");
  // The CSV first: a run counts as finished when its JSON exists (resume looks for it).
  writeFileAtomically(csvFileOf(json), runToCsv(run), durability);
  writeFileAtomically(json, runJsonText(run), durability);
  return json;
}

bool runCsvIsWhole(const RunRecord& run, const std::filesystem::path& jsonFile) {
  std::ifstream in(csvFileOf(jsonFile), std::ios::binary);
  if (!in) return false;
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return !text.empty() && text.back() == '\n' &&
         static_cast<std::size_t>(std::ranges::count(text, '\n')) == run.steps.size() + 1;
}

}  // namespace camcov::records
