#include "records/run_files.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "util/input_error.h"
#include "util/input_file.h"

#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "records/json_numbers.h"

namespace camcov::records {
namespace {

nlohmann::json pose(const geometry::Pose& p) {
  return nlohmann::json::array({p.x, p.y, p.yaw});
}

geometry::Pose poseFrom(const nlohmann::json& v) {
  return {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>()};
}

sim::RunSummary summaryFrom(const nlohmann::json& j) {
  sim::RunSummary s;
  s.steps = j.at("steps").get<int>();
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
  s.avoidableContacts = j.at("avoidableContacts").get<int>();
  s.unavoidableContacts = j.at("unavoidableContacts").get<int>();
  s.boundaryClamps = j.at("boundaryClamps").get<int>();
  s.stepsWithoutTargets = j.value("stepsWithoutTargets", 0);
  if (j.contains("averageWeightedCoverage"))
    s.averageWeightedCoverage = j.at("averageWeightedCoverage").get<double>();
  if (j.contains("finalWeightedCoverage"))
    s.finalWeightedCoverage = j.at("finalWeightedCoverage").get<double>();
  if (j.contains("messages")) {
    const nlohmann::json& m = j.at("messages");
    s.messages = sim::MessageCounts{m.at("sent").get<int>(), m.at("delivered").get<int>(),
                                    m.at("lost").get<int>()};
  }
  return s;
}

}  // namespace

nlohmann::json summaryJson(const sim::RunSummary& s) {
  nlohmann::json j = {{"steps", s.steps},
                      {"duration", s.duration},
                      {"averageCoverage", s.averageCoverage},
                      {"averageUtilization", s.averageUtilization},
                      {"averageReward", s.averageReward},
                      {"finalCoverage", s.finalCoverage},
                      {"minObjectDistance", finiteOrNull(s.minObjectDistance)},
                      {"minCameraDistance", finiteOrNull(s.minCameraDistance)},
                      {"objectCollisionTime", s.objectCollisionTime},
                      {"cameraCollisionTime", s.cameraCollisionTime},
                      {"avoidableContactTime", s.avoidableContactTime},
                      {"unavoidableContactTime", s.unavoidableContactTime},
                      {"avoidableContacts", s.avoidableContacts},
                      {"unavoidableContacts", s.unavoidableContacts},
                      {"boundaryClamps", s.boundaryClamps}};
  // Only recorded tracks leave a scene empty; other runs keep their bytes.
  if (s.stepsWithoutTargets > 0) j["stepsWithoutTargets"] = s.stepsWithoutTargets;
  // Only weighted scenes have weighted coverage; the same.
  if (s.averageWeightedCoverage) j["averageWeightedCoverage"] = *s.averageWeightedCoverage;
  if (s.finalWeightedCoverage) j["finalWeightedCoverage"] = *s.finalWeightedCoverage;
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

nlohmann::json runToJson(const RunRecord& run) {
  const RunMetadata& m = run.metadata;
  nlohmann::json j;
  j["format"] = kRunFormat;
  j["tool"] = {{"name", "camcov"}, {"version", m.toolVersion}};
  j["scene"] = {
      {"name", m.scene}, {"file", m.sceneFile}, {"hash", fmt::format("{:016x}", m.sceneHash)}};
  j["method"] = m.method;
  j["seed"] = m.seed;
  j["parameters"] = params::toJson(m.parameters);
  j["summary"] = summaryJson(run.summary);

  // The time series, column by column; poses as [x, y, yaw (rad)].
  nlohmann::json series;
  for (const char* key :
       {"time", "coverage", "utilization", "repulsion", "reward", "minObjectDistance",
        "minCameraDistance", "minObjectDistanceInStep", "minCameraDistanceInStep",
        "avoidableContactTime", "unavoidableContactTime"}) {
    series[key] = nlohmann::json::array();
  }
  const std::size_t cameras = run.steps.empty() ? 0 : run.steps.front().cameras.size();
  nlohmann::json poses = nlohmann::json::array(), goals = nlohmann::json::array();
  for (std::size_t c = 0; c < cameras; ++c) {
    poses.push_back(nlohmann::json::array());
    goals.push_back(nlohmann::json::array());
  }
  for (const StepRow& row : run.steps) {
    series["time"].push_back(row.time);
    series["coverage"].push_back(row.terms.coverage);
    series["utilization"].push_back(row.terms.utilization);
    series["repulsion"].push_back(row.terms.repulsion);
    series["reward"].push_back(row.terms.reward);
    series["minObjectDistance"].push_back(finiteOrNull(row.minObjectDistance));
    series["minCameraDistance"].push_back(finiteOrNull(row.minCameraDistance));
    series["minObjectDistanceInStep"].push_back(finiteOrNull(row.minObjectDistanceInStep));
    series["minCameraDistanceInStep"].push_back(finiteOrNull(row.minCameraDistanceInStep));
    series["avoidableContactTime"].push_back(row.avoidableContactTime);
    series["unavoidableContactTime"].push_back(row.unavoidableContactTime);
    for (std::size_t c = 0; c < cameras; ++c) {
      poses[c].push_back(pose(row.cameras[c]));
      goals[c].push_back(row.goals[c] ? pose(*row.goals[c]) : nlohmann::json());
    }
  }
  // Weighted scenes' runs (RunSummary::averageWeightedCoverage) record weighted coverage too.
  if (run.summary.averageWeightedCoverage) {
    series["weightedCoverage"] = nlohmann::json::array();
    for (const StepRow& row : run.steps)
      series["weightedCoverage"].push_back(row.terms.weightedCoverage);
  }
  // Scenes whose targets come and go (recorded tracks) say how many are present at each step.
  if (!run.steps.empty() && run.steps.front().targetsPresent >= 0) {
    series["targetsPresent"] = nlohmann::json::array();
    for (const StepRow& row : run.steps)
      series["targetsPresent"].push_back(row.targetsPresent);
  }
  // Runs under limited knowledge (RunSummary::messages) say who heard whom at each step:
  // [from, to, sent at].
  if (run.summary.messages) {
    series["heard"] = nlohmann::json::array();
    for (const StepRow& row : run.steps) {
      nlohmann::json step = nlohmann::json::array();
      for (const sim::Hearing& h : row.heard)
        step.push_back({h.from, h.to, h.sentAt});
      series["heard"].push_back(std::move(step));
    }
  }
  series["cameras"] = std::move(poses);
  series["goals"] = std::move(goals);
  j["series"] = std::move(series);

  j["events"] = nlohmann::json::array();
  for (const auto& e : run.events) {
    nlohmann::json event = {
        {"time", e.time}, {"kind", e.kind}, {"camera", e.camera}, {"detail", e.detail}};
    if (!e.reason.empty()) event["reason"] = e.reason;
    if (!e.path.empty()) {
      event["path"] = nlohmann::json::array();
      for (const auto& p : e.path)
        event["path"].push_back(pose(p));
    }
    j["events"].push_back(std::move(event));
  }
  return j;
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
    m.sceneHash = std::stoull(j.at("scene").at("hash").get<std::string>(), nullptr, 16);
    m.method = j.at("method").get<std::string>();
    m.seed = j.at("seed").get<std::uint64_t>();
    m.parameters = params::fromJson(j.at("parameters"), source);
    m.toolVersion = j.at("tool").at("version").get<std::string>();
    run.summary = summaryFrom(j.at("summary"));

    const nlohmann::json& series = j.at("series");
    const auto& time = series.at("time");
    const auto& cameras = series.at("cameras");
    const auto& goals = series.at("goals");
    for (std::size_t k = 0; k < time.size(); ++k) {
      StepRow row;
      row.time = time.at(k).get<double>();
      row.terms.coverage = series.at("coverage").at(k).get<double>();
      // Recorded for weighted scenes only; elsewhere the two are one.
      row.terms.weightedCoverage = series.contains("weightedCoverage")
                                       ? series.at("weightedCoverage").at(k).get<double>()
                                       : row.terms.coverage;
      row.terms.utilization = series.at("utilization").at(k).get<double>();
      row.terms.repulsion = series.at("repulsion").at(k).get<double>();
      row.terms.reward = series.at("reward").at(k).get<double>();
      row.minObjectDistance = numberOrInfinity(series.at("minObjectDistance").at(k));
      row.minCameraDistance = numberOrInfinity(series.at("minCameraDistance").at(k));
      row.minObjectDistanceInStep = numberOrInfinity(series.at("minObjectDistanceInStep").at(k));
      row.minCameraDistanceInStep = numberOrInfinity(series.at("minCameraDistanceInStep").at(k));
      row.avoidableContactTime = series.at("avoidableContactTime").at(k).get<double>();
      row.unavoidableContactTime = series.at("unavoidableContactTime").at(k).get<double>();
      if (series.contains("targetsPresent"))
        row.targetsPresent = series.at("targetsPresent").at(k).get<int>();
      if (series.contains("heard")) {
        for (const auto& h : series.at("heard").at(k))
          row.heard.push_back({h.at(0).get<int>(), h.at(1).get<int>(), h.at(2).get<double>()});
      }
      for (std::size_t c = 0; c < cameras.size(); ++c) {
        row.cameras.push_back(poseFrom(cameras.at(c).at(k)));
        const auto& g = goals.at(c).at(k);
        row.goals.push_back(g.is_null() ? std::nullopt : std::optional(poseFrom(g)));
      }
      run.steps.push_back(std::move(row));
    }
    for (const auto& e : j.at("events")) {
      control::ControlEvent event{e.at("time").get<double>(),
                                  e.at("kind").get<std::string>(),
                                  e.at("camera").get<int>(),
                                  e.at("detail").get<std::string>(),
                                  {},
                                  e.value("reason", std::string())};
      if (e.contains("path")) {
        for (const auto& p : e.at("path"))
          event.path.push_back(poseFrom(p));
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
  std::string csv =
      "time,coverage,utilization,repulsion,reward,min_object_distance,min_camera_distance,"
      "min_object_distance_in_step,min_camera_distance_in_step,avoidable_contact_time,"
      "unavoidable_contact_time";
  const bool weighted = run.summary.averageWeightedCoverage.has_value();
  if (weighted) csv += ",weighted_coverage";
  const std::size_t cameras = run.steps.empty() ? 0 : run.steps.front().cameras.size();
  for (std::size_t c = 0; c < cameras; ++c)
    csv += fmt::format(",cam{0}_x,cam{0}_y,cam{0}_yaw", c);
  csv += '\n';
  for (const StepRow& row : run.steps) {
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{}", row.time, row.terms.coverage,
                       row.terms.utilization, row.terms.repulsion, row.terms.reward,
                       row.minObjectDistance, row.minCameraDistance, row.minObjectDistanceInStep,
                       row.minCameraDistanceInStep, row.avoidableContactTime,
                       row.unavoidableContactTime);
    if (weighted) csv += fmt::format(",{}", row.terms.weightedCoverage);
    for (const auto& p : row.cameras)
      csv += fmt::format(",{},{},{}", p.x, p.y, p.yaw);
    csv += '\n';
  }
  return csv;
}

std::filesystem::path writeRunFiles(const RunRecord& run, const std::filesystem::path& folder) {
  const std::string stem = runStem(run.metadata);
  const auto json = folder / (stem + ".json");
  // The CSV first: a run counts as finished when its JSON exists (resume looks for it).
  writeFileAtomically(folder / (stem + ".csv"), runToCsv(run));
  writeFileAtomically(json, runToJson(run).dump(1) + "\n");
  return json;
}

}  // namespace camcov::records
