#include "records/optimum_file.h"

#include <fstream>

#include "params/parameter_table.h"
#include "records/json_numbers.h"
#include "records/known_keys.h"
#include "util/input_error.h"

namespace camcov::records {

nlohmann::json optimumToJson(const OptimumFile& f) {
  const planners::OptimumResult& r = f.result;
  nlohmann::json poses = nlohmann::json::array();
  for (const auto& p : r.poses)
    poses.push_back({{"x", p.x}, {"y", p.y}, {"yaw_deg", geometry::radToDeg(p.yaw)}});
  nlohmann::json curve = nlohmann::json::array();
  for (const auto& step : r.curve) {
    curve.push_back(
        {{"evaluations", step.evaluations}, {"reward", step.reward}, {"coverage", step.coverage}});
  }
  return {{"format", kOptimumFormat},
          {"note",
           "the best team pose a random, local search found: a reference, not a proof of "
           "optimality; the curve shows how the best grew with the budget"},
          {"scene", {{"name", f.scene}, {"file", f.sceneFile}, {"hash", hashText(f.sceneHash)}}},
          {"time", f.time},
          {"seed", f.seed},
          {"budget", f.budget},
          {"parameters", params::toJson(f.parameters)},
          {"best",
           {{"poses", poses},
            {"coverage", r.terms.coverage},
            {"utilization", r.terms.utilization},
            {"repulsion", r.terms.repulsion},
            {"reward", r.terms.reward}}},
          {"found", {{"round", r.foundInRound}, {"by", r.foundBy}, {"evaluations", r.foundAt}}},
          {"travelTime", finiteOrNull(f.travelTime)},
          {"rounds", r.rounds},
          {"evaluations", r.evaluations},
          {"curve", curve}};
}

OptimumFile optimumFromJson(const nlohmann::json& j, const std::string& source) {
  try {
    if (j.at("format") != kOptimumFormat) {
      throw InputError(source + ": not a camcov optimum (format " + std::string(kOptimumFormat) +
                       ")");
    }
    OptimumFile f;
    f.scene = j.at("scene").at("name").get<std::string>();
    f.sceneFile = j.at("scene").at("file").get<std::string>();
    // Sixteen hexadecimal digits, as in run files and batch.json; files written before that
    // hold a JSON number, which readers in JavaScript or Python round past 2^53.
    const nlohmann::json& hash = j.at("scene").at("hash");
    f.sceneHash = hash.is_string() ? hashFrom(hash, "scene.hash", source)
                                   : wholeNumberFrom<std::uint64_t>(hash, "scene.hash", source);
    f.time = j.at("time").get<double>();
    f.seed = wholeNumberFrom<std::uint64_t>(j.at("seed"), "seed", source);
    f.budget = wholeNumberFrom<std::int64_t>(j.at("budget"), "budget", source);
    f.parameters = params::fromJson(j.at("parameters"), source);
    planners::OptimumResult& r = f.result;
    const auto& best = j.at("best");
    for (const auto& p : best.at("poses")) {
      r.poses.push_back({p.at("x").get<double>(), p.at("y").get<double>(),
                         geometry::degToRad(p.at("yaw_deg").get<double>())});
    }
    r.terms.coverage = best.at("coverage").get<double>();
    r.terms.utilization = best.at("utilization").get<double>();
    r.terms.repulsion = best.at("repulsion").get<double>();
    r.terms.reward = best.at("reward").get<double>();
    r.foundInRound = wholeNumberFrom<int>(j.at("found").at("round"), "found.round", source);
    r.foundBy = j.at("found").at("by").get<std::string>();
    r.foundAt =
        wholeNumberFrom<std::int64_t>(j.at("found").at("evaluations"), "found.evaluations", source);
    r.rounds = wholeNumberFrom<int>(j.at("rounds"), "rounds", source);
    r.evaluations = wholeNumberFrom<std::int64_t>(j.at("evaluations"), "evaluations", source);
    if (const auto t = j.find("travelTime"); t != j.end() && t->is_number())
      f.travelTime = t->get<double>();
    for (const auto& step : j.at("curve")) {
      r.curve.push_back(
          {wholeNumberFrom<std::int64_t>(step.at("evaluations"), "evaluations", source),
           step.at("reward").get<double>(), step.at("coverage").get<double>()});
    }
    return f;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": malformed optimum: " + e.what());
  }
}

OptimumFile loadOptimumFile(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open the optimum file");
  try {
    return optimumFromJson(nlohmann::json::parse(in), file.string());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file.string() + ": invalid JSON: " + e.what());
  }
}

}  // namespace camcov::records
