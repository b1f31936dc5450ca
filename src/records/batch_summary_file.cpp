#include "records/batch_summary_file.h"

#include <fmt/format.h>

#include <array>
#include <fstream>
#include <limits>
#include <string_view>

#include "records/json_numbers.h"
#include "records/known_keys.h"
#include "util/input_error.h"

namespace camcov::records {

namespace {

nlohmann::json describeJson(const Description& d) {
  return {{"count", d.count}, {"mean", d.mean},     {"sd", d.sd}, {"min", d.min},
          {"q1", d.q1},       {"median", d.median}, {"q3", d.q3}, {"max", d.max}};
}

nlohmann::json comparisonJson(const Comparison& c) {
  nlohmann::json j = {
      {"scene", c.scene},
      {"method", c.method},
      {"winner", c.winner},
      {"pValue", c.pValue},
      {"exactTest", c.exact},
      {"meanCoverageDifference", c.meanDifference},
      {"a12", c.a12},
      {"meanCoverageDifferenceCI",
       {finiteOrNull(c.meanDifferenceCI.low), finiteOrNull(c.meanDifferenceCI.high)}}};
  if (c.seedsNeeded > 0) j["seedsNeeded"] = c.seedsNeeded;
  return j;
}

// A comparison's keys; an entry of "pairs" also names what it is compared with.
constexpr std::array<std::string_view, 9> kComparisonKeys{"scene",      "method",
                                                          "winner",     "pValue",
                                                          "exactTest",  "meanCoverageDifference",
                                                          "a12",        "meanCoverageDifferenceCI",
                                                          "seedsNeeded"};
constexpr std::array<std::string_view, 1> kPairKeys{"against"};

Comparison comparisonFrom(const nlohmann::json& c, bool pair, const std::string& source) {
  if (pair) {
    requireKnownKeys(c, {kComparisonKeys, kPairKeys}, "pairs[]", source);
  } else {
    requireKnownKeys(c, {kComparisonKeys}, "comparisons[]", source);
  }
  Comparison out;
  out.scene = c.at("scene").get<std::string>();
  out.method = c.at("method").get<std::string>();
  out.winner = c.at("winner").get<std::string>();
  out.pValue = c.at("pValue").get<double>();
  out.exact = c.at("exactTest").get<bool>();
  out.meanDifference = c.at("meanCoverageDifference").get<double>();
  // Summaries written before effect sizes and intervals have neither.
  out.a12 = c.value("a12", 0.5);
  if (const auto ci = c.find("meanCoverageDifferenceCI"); ci != c.end()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.meanDifferenceCI = {ci->at(0).is_null() ? nan : ci->at(0).get<double>(),
                            ci->at(1).is_null() ? nan : ci->at(1).get<double>()};
  }
  out.seedsNeeded = c.contains("seedsNeeded")
                        ? wholeNumberFrom<int>(c.at("seedsNeeded"), "seedsNeeded", source)
                        : 0;
  // The verdict its name stands for ("": nothing compared, left as a default-made one).
  out.verdict = out.winner == out.method                    ? Verdict::Better
                : out.winner == "undecided"                 ? Verdict::Undecided
                : out.winner == "tie" || out.winner.empty() ? Verdict::Tie
                                                            : Verdict::Worse;
  return out;
}

Description describedFrom(const nlohmann::json& j, const std::string& source) {
  requireKnownKeys(j, {"count", "mean", "sd", "min", "q1", "median", "q3", "max"},
                   "a description of runs", source);
  return {wholeNumberFrom<int>(j.at("count"), "count", source),
          j.at("mean").get<double>(),
          j.at("sd").get<double>(),
          j.at("min").get<double>(),
          j.at("q1").get<double>(),
          j.at("median").get<double>(),
          j.at("q3").get<double>(),
          j.at("max").get<double>()};
}

nlohmann::json tallyJson(const Tally& t) {
  nlohmann::json j{{"method", t.method},
                   {"wins", t.wins},
                   {"ties", t.ties},
                   {"losses", t.losses},
                   {"undecided", t.undecided}};
  if (!t.against.empty()) j["against"] = t.against;
  return j;
}

Tally tallyFrom(const nlohmann::json& t, const std::string& source) {
  requireKnownKeys(t, {"method", "wins", "ties", "losses", "undecided", "against"}, "a tally",
                   source);
  return {
      t.at("method").get<std::string>(),
      wholeNumberFrom<int>(t.at("wins"), "wins", source),
      wholeNumberFrom<int>(t.at("ties"), "ties", source),
      wholeNumberFrom<int>(t.at("losses"), "losses", source),
      t.value("against", std::string()),
      t.contains("undecided") ? wholeNumberFrom<int>(t.at("undecided"), "undecided", source) : 0};
}

}  // namespace

nlohmann::json summaryToJson(const BatchSummary& summary) {
  nlohmann::json j;
  j["format"] = "camcov-summary/2";
  j["significance"] = kSignificance;
  j["methods"] = nlohmann::json::array();
  for (const auto& m : summary.methods) {
    j["methods"].push_back({{"scene", m.scene},
                            {"method", m.method},
                            {"runs", m.runs},
                            {"failed", m.failed},
                            {"averageCoverage", describeJson(m.coverage)},
                            {"averageUtilization", describeJson(m.utilization)},
                            {"finalCoverage", describeJson(m.finalCoverage)},
                            {"meanObjectCollisionTime", m.meanObjectCollisionTime},
                            {"meanCameraCollisionTime", m.meanCameraCollisionTime},
                            {"runsWithCollision", m.runsWithCollision},
                            {"meanAvoidableContactTime", m.meanAvoidableContactTime},
                            {"meanUnavoidableContactTime", m.meanUnavoidableContactTime},
                            {"runsWithAvoidableContact", m.runsWithAvoidableContact},
                            {"runsWithUnavoidableContact", m.runsWithUnavoidableContact},
                            {"minObjectDistance", finiteOrNull(m.minObjectDistance)},
                            {"minCameraDistance", finiteOrNull(m.minCameraDistance)},
                            {"medianSeed", m.medianSeed},
                            {"bestSeed", m.bestSeed}});
    if (m.weightedCoverage.count > 0)
      j["methods"].back()["averageWeightedCoverage"] = describeJson(m.weightedCoverage);
    if (m.resolutionCoverage.count > 0)
      j["methods"].back()["averageResolutionCoverage"] = describeJson(m.resolutionCoverage);
  }
  j["scenes"] = summary.scenes;
  j["reference"] = summary.reference;
  j["comparisons"] = nlohmann::json::array();
  for (const auto& c : summary.comparisons) {
    j["comparisons"].push_back(comparisonJson(c));
  }
  j["totals"] = nlohmann::json::array();
  for (const auto& t : summary.tallies)
    j["totals"].push_back(tallyJson(t));
  j["pairs"] = nlohmann::json::array();
  for (const auto& p : summary.pairs) {
    nlohmann::json pair = comparisonJson(p.comparison);
    pair["against"] = p.against;
    j["pairs"].push_back(std::move(pair));
  }
  j["pairTotals"] = nlohmann::json::array();
  for (const auto& t : summary.pairTallies)
    j["pairTotals"].push_back(tallyJson(t));
  j["groups"] = nlohmann::json::array();
  for (const auto& g : summary.groups) {
    nlohmann::json group{{"name", g.name},
                         {"scenes", g.scenes},
                         {"meanCoverage", nlohmann::json::array()},
                         {"totals", nlohmann::json::array()},
                         {"pairTotals", nlohmann::json::array()}};
    for (const auto& [method, mean] : g.meanCoverage)
      group["meanCoverage"].push_back({{"method", method}, {"mean", mean}});
    for (const auto& t : g.tallies)
      group["totals"].push_back(tallyJson(t));
    for (const auto& t : g.pairTallies)
      group["pairTotals"].push_back(tallyJson(t));
    j["groups"].push_back(std::move(group));
  }
  j["failures"] = nlohmann::json::array();
  for (const auto& f : summary.failures) {
    j["failures"].push_back(
        {{"scene", f.scene}, {"method", f.method}, {"seed", f.seed}, {"error", f.error}});
  }
  return j;
}

std::string summaryToCsv(const BatchSummary& summary) {
  std::string csv =
      "scene,method,runs,failed,coverage_mean,coverage_sd,coverage_min,coverage_q1,coverage_median,"
      "coverage_q3,coverage_max,utilization_mean,utilization_sd,utilization_min,utilization_q1,"
      "utilization_median,utilization_q3,utilization_max,mean_object_collision_time,"
      "mean_camera_collision_time,runs_with_collision,mean_avoidable_contact_time,"
      "mean_unavoidable_contact_time,runs_with_avoidable_contact,runs_with_unavoidable_contact,"
      "min_object_distance,min_camera_distance,median_seed,best_seed,compared_with,winner,p_"
      "value,a12,mean_difference_ci_low,mean_difference_ci_high\n";
  for (const auto& m : summary.methods) {
    // The reference's own row compares with nothing: its last six cells are empty.
    const Comparison* c = summary.comparison(m.scene, m.method);
    const auto& cv = m.coverage;
    const auto& ut = m.utilization;
    csv += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},"
        "{},{},{},{},{}\n",
        m.scene, m.method, m.runs, m.failed, cv.mean, cv.sd, cv.min, cv.q1, cv.median, cv.q3,
        cv.max, ut.mean, ut.sd, ut.min, ut.q1, ut.median, ut.q3, ut.max, m.meanObjectCollisionTime,
        m.meanCameraCollisionTime, m.runsWithCollision, m.meanAvoidableContactTime,
        m.meanUnavoidableContactTime, m.runsWithAvoidableContact, m.runsWithUnavoidableContact,
        m.minObjectDistance, m.minCameraDistance, m.medianSeed, m.bestSeed,
        c ? summary.reference : "", c ? c->winner : "", c ? fmt::format("{}", c->pValue) : "",
        c ? fmt::format("{}", c->a12) : "", c ? fmt::format("{}", c->meanDifferenceCI.low) : "",
        c ? fmt::format("{}", c->meanDifferenceCI.high) : "");
  }
  return csv;
}

BatchSummary summaryFromJson(const nlohmann::json& j, const std::string& source) {
  try {
    if (j.at("format") != "camcov-summary/2") {
      throw InputError(source + ": not a camcov summary (format camcov-summary/2)");
    }
    requireKnownKeys(j,
                     {"format", "significance", "methods", "scenes", "reference", "comparisons",
                      "totals", "pairs", "pairTotals", "groups", "failures"},
                     "the summary", source);
    BatchSummary s;
    for (const auto& m : j.at("methods")) {
      requireKnownKeys(m,
                       {"scene",
                        "method",
                        "runs",
                        "failed",
                        "averageCoverage",
                        "averageUtilization",
                        "finalCoverage",
                        "averageWeightedCoverage",
                        "averageResolutionCoverage",
                        "meanObjectCollisionTime",
                        "meanCameraCollisionTime",
                        "runsWithCollision",
                        "meanAvoidableContactTime",
                        "meanUnavoidableContactTime",
                        "runsWithAvoidableContact",
                        "runsWithUnavoidableContact",
                        "minObjectDistance",
                        "minCameraDistance",
                        "medianSeed",
                        "bestSeed"},
                       "methods[]", source);
      MethodSummary ms;
      ms.scene = m.at("scene").get<std::string>();
      ms.method = m.at("method").get<std::string>();
      ms.runs = wholeNumberFrom<int>(m.at("runs"), "runs", source);
      ms.failed = wholeNumberFrom<int>(m.at("failed"), "failed", source);
      ms.coverage = describedFrom(m.at("averageCoverage"), source);
      ms.utilization = describedFrom(m.at("averageUtilization"), source);
      if (m.contains("finalCoverage"))
        ms.finalCoverage = describedFrom(m.at("finalCoverage"), source);
      if (m.contains("averageWeightedCoverage"))
        ms.weightedCoverage = describedFrom(m.at("averageWeightedCoverage"), source);
      if (m.contains("averageResolutionCoverage"))
        ms.resolutionCoverage = describedFrom(m.at("averageResolutionCoverage"), source);
      ms.meanObjectCollisionTime = m.at("meanObjectCollisionTime").get<double>();
      ms.meanCameraCollisionTime = m.at("meanCameraCollisionTime").get<double>();
      ms.runsWithCollision =
          wholeNumberFrom<int>(m.at("runsWithCollision"), "runsWithCollision", source);
      ms.meanAvoidableContactTime = m.at("meanAvoidableContactTime").get<double>();
      ms.meanUnavoidableContactTime = m.at("meanUnavoidableContactTime").get<double>();
      ms.runsWithAvoidableContact = wholeNumberFrom<int>(m.at("runsWithAvoidableContact"),
                                                         "runsWithAvoidableContact", source);
      ms.runsWithUnavoidableContact = wholeNumberFrom<int>(m.at("runsWithUnavoidableContact"),
                                                           "runsWithUnavoidableContact", source);
      ms.minObjectDistance = numberOrInfinity(m.at("minObjectDistance"));
      ms.minCameraDistance = numberOrInfinity(m.at("minCameraDistance"));
      ms.medianSeed = wholeNumberFrom<std::uint64_t>(m.at("medianSeed"), "medianSeed", source);
      ms.bestSeed = wholeNumberFrom<std::uint64_t>(m.at("bestSeed"), "bestSeed", source);
      s.methods.push_back(std::move(ms));
    }
    s.scenes = j.at("scenes").get<std::vector<std::string>>();
    s.reference = j.at("reference").get<std::string>();
    for (const auto& c : j.at("comparisons"))
      s.comparisons.push_back(comparisonFrom(c, false, source));
    for (const auto& t : j.at("totals"))
      s.tallies.push_back(tallyFrom(t, source));
    // Summaries written before pairwise verdicts existed have no pairs.
    for (const auto& c : j.value("pairs", nlohmann::json::array()))
      s.pairs.push_back({c.at("against").get<std::string>(), comparisonFrom(c, true, source)});
    for (const auto& t : j.value("pairTotals", nlohmann::json::array()))
      s.pairTallies.push_back(tallyFrom(t, source));
    // Summaries written before scenes had groups have none.
    for (const auto& g : j.value("groups", nlohmann::json::array())) {
      requireKnownKeys(g, {"name", "scenes", "meanCoverage", "totals", "pairTotals"}, "groups[]",
                       source);
      GroupSummary group{g.at("name").get<std::string>(),
                         g.at("scenes").get<std::vector<std::string>>(),
                         {},
                         {},
                         {}};
      for (const auto& m : g.at("meanCoverage")) {
        requireKnownKeys(m, {"method", "mean"}, "groups[].meanCoverage[]", source);
        group.meanCoverage.emplace_back(m.at("method").get<std::string>(),
                                        m.at("mean").get<double>());
      }
      for (const auto& t : g.at("totals"))
        group.tallies.push_back(tallyFrom(t, source));
      for (const auto& t : g.at("pairTotals"))
        group.pairTallies.push_back(tallyFrom(t, source));
      s.groups.push_back(std::move(group));
    }
    for (const auto& f : j.at("failures")) {
      requireKnownKeys(f, {"scene", "method", "seed", "error"}, "failures[]", source);
      s.failures.push_back({f.at("scene").get<std::string>(),
                            f.at("method").get<std::string>(),
                            wholeNumberFrom<std::uint64_t>(f.at("seed"), "seed", source),
                            true,
                            f.at("error").get<std::string>(),
                            {}});
    }
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": malformed summary: " + e.what());
  }
}

BatchSummary loadSummaryFile(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open the batch summary");
  try {
    return summaryFromJson(nlohmann::json::parse(in), file.string());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file.string() + ": invalid JSON: " + e.what());
  }
}

}  // namespace camcov::records
