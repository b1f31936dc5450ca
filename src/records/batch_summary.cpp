#include "records/batch_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

#include "records/json_numbers.h"
#include "util/input_error.h"
#include "util/natural_order.h"

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

Comparison comparisonFrom(const nlohmann::json& c) {
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
  out.seedsNeeded = c.value("seedsNeeded", 0);
  // The verdict its name stands for ("": nothing compared, left as a default-made one).
  out.verdict = out.winner == out.method                    ? Verdict::Better
                : out.winner == "undecided"                 ? Verdict::Undecided
                : out.winner == "tie" || out.winner.empty() ? Verdict::Tie
                                                            : Verdict::Worse;
  return out;
}

Description describedFrom(const nlohmann::json& j) {
  return {j.at("count").get<int>(),  j.at("mean").get<double>(), j.at("sd").get<double>(),
          j.at("min").get<double>(), j.at("q1").get<double>(),   j.at("median").get<double>(),
          j.at("q3").get<double>(),  j.at("max").get<double>()};
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

Tally tallyFrom(const nlohmann::json& t) {
  return {t.at("method").get<std::string>(), t.at("wins").get<int>(),
          t.at("ties").get<int>(),           t.at("losses").get<int>(),
          t.value("against", std::string()), t.value("undecided", 0)};
}

// The summary's tallies again, scene group by scene group: the same comparisons, counted
// per group, and each method's mean coverage there. One pass over each list.
std::vector<GroupSummary> groupScenes(const BatchSummary& summary,
                                      const std::map<std::string, std::string>& groupOf) {
  std::vector<GroupSummary> groups;
  std::map<std::string, std::size_t> indexOf;  // scene to its group's index
  for (const std::string& scene : summary.scenes) {
    const auto it = groupOf.find(scene);
    if (it == groupOf.end() || it->second.empty()) continue;
    const auto g = std::find_if(groups.begin(), groups.end(),
                                [&](const GroupSummary& x) { return x.name == it->second; });
    indexOf[scene] = static_cast<std::size_t>(g - groups.begin());
    if (g == groups.end()) {
      groups.push_back({it->second, {}, {}, summary.tallies, summary.pairTallies});
      for (auto* tallies : {&groups.back().tallies, &groups.back().pairTallies}) {
        for (Tally& t : *tallies)
          t.wins = t.ties = t.losses = t.undecided = 0;
      }
    }
    groups[indexOf[scene]].scenes.push_back(scene);
  }
  const auto groupOfScene = [&](const std::string& scene) -> GroupSummary* {
    const auto it = indexOf.find(scene);
    return it == indexOf.end() ? nullptr : &groups[it->second];
  };
  // Means by method name; the tables look them up by name.
  std::vector<std::map<std::string, std::pair<double, int>>> sums(groups.size());
  for (const MethodSummary& m : summary.methods) {
    if (m.coverage.count == 0) continue;
    if (GroupSummary* g = groupOfScene(m.scene)) {
      auto& [sum, n] = sums[static_cast<std::size_t>(g - groups.data())][m.method];
      sum += m.coverage.mean;
      ++n;
    }
  }
  for (std::size_t k = 0; k < groups.size(); ++k) {
    for (const auto& [method, sum] : sums[k])
      groups[k].meanCoverage.emplace_back(method, sum.first / sum.second);
  }
  const auto tallyOf = [](std::vector<Tally>& tallies, const std::string& method,
                          const std::string& against) {
    return std::find_if(tallies.begin(), tallies.end(), [&](const Tally& t) {
      return t.method == method && (against.empty() || t.against == against);
    });
  };
  for (const Comparison& c : summary.comparisons) {
    GroupSummary* g = groupOfScene(c.scene);
    if (g == nullptr) continue;
    if (auto t = tallyOf(g->tallies, c.method, ""); t != g->tallies.end())
      count(*t, c, summary.reference);
  }
  for (const PairComparison& p : summary.pairs) {
    GroupSummary* g = groupOfScene(p.comparison.scene);
    if (g == nullptr) continue;
    if (auto t = tallyOf(g->pairTallies, p.comparison.method, p.against); t != g->pairTallies.end())
      count(*t, p.comparison, p.against);
  }
  return groups;
}

// Scenes in natural order ("dynamic2" before "dynamic10"), then methods by name.
struct SceneMethodLess {
  bool operator()(const std::pair<std::string, std::string>& a,
                  const std::pair<std::string, std::string>& b) const {
    if (a.first != b.first) return naturalLess(a.first, b.first);
    return a.second < b.second;
  }
};
struct NaturalLess {
  bool operator()(const std::string& a, const std::string& b) const { return naturalLess(a, b); }
};
// Scene -> method -> every run's average coverage, in seed order.
using CoverageByScene =
    std::map<std::string, std::map<std::string, std::vector<double>>, NaturalLess>;

// One method on one scene, over its jobs (in seed order): counts, distributions, safety and
// which seeds are the median and the best.
MethodSummary summarizeMethod(const std::string& scene, const std::string& method,
                              std::span<const JobOutcome* const> jobs,
                              std::vector<double>& coverage) {
  MethodSummary m;
  m.scene = scene;
  m.method = method;
  m.minObjectDistance = m.minCameraDistance = std::numeric_limits<double>::infinity();
  std::vector<double> utilization, finalCoverage, weightedCoverage, resolutionCoverage;
  std::vector<std::pair<double, std::uint64_t>> bySeed;
  for (const JobOutcome* job : jobs) {
    if (job->failed) {
      ++m.failed;
      continue;
    }
    const sim::RunSummary& s = job->summary;
    ++m.runs;
    coverage.push_back(s.averageCoverage);
    utilization.push_back(s.averageUtilization);
    if (!std::isnan(s.finalCoverage)) finalCoverage.push_back(s.finalCoverage);
    if (s.averageWeightedCoverage) weightedCoverage.push_back(*s.averageWeightedCoverage);
    if (s.averageResolutionCoverage) resolutionCoverage.push_back(*s.averageResolutionCoverage);
    bySeed.push_back({s.averageCoverage, job->seed});
    m.meanObjectCollisionTime += s.objectCollisionTime;
    m.meanCameraCollisionTime += s.cameraCollisionTime;
    if (s.objectCollisionTime > 0.0 || s.cameraCollisionTime > 0.0) ++m.runsWithCollision;
    m.meanAvoidableContactTime += s.avoidableContactTime;
    m.meanUnavoidableContactTime += s.unavoidableContactTime;
    if (s.avoidableContactTime > 0.0) ++m.runsWithAvoidableContact;
    if (s.unavoidableContactTime > 0.0) ++m.runsWithUnavoidableContact;
    m.minObjectDistance = std::min(m.minObjectDistance, s.minObjectDistance);
    m.minCameraDistance = std::min(m.minCameraDistance, s.minCameraDistance);
  }
  if (m.runs > 0) {
    m.meanObjectCollisionTime /= m.runs;
    m.meanCameraCollisionTime /= m.runs;
    m.meanAvoidableContactTime /= m.runs;
    m.meanUnavoidableContactTime /= m.runs;
    std::sort(bySeed.begin(), bySeed.end());
    m.medianSeed = bySeed[(bySeed.size() - 1) / 2].second;
    m.bestSeed = std::find_if(bySeed.begin(), bySeed.end(), [&](const auto& run) {
                   return run.first == bySeed.back().first;
                 })->second;
  }
  m.coverage = describe(coverage);
  m.utilization = describe(utilization);
  m.finalCoverage = describe(finalCoverage);
  m.weightedCoverage = describe(weightedCoverage);
  m.resolutionCoverage = describe(resolutionCoverage);
  return m;
}

// One method against another on one scene, counted in `tally`.
Comparison compareOnScene(const std::string& scene, const std::string& method,
                          const std::string& against, const std::vector<double>& runs,
                          const std::vector<double>* others, Tally& tally) {
  Comparison c;
  c.scene = scene;
  c.method = method;
  if (others == nullptr || others->empty() || runs.empty()) return c;
  const RunsComparison r = compareRuns(runs, *others);
  static_cast<RunsComparison&>(c) = r;
  tally.method = method;
  c.winner = r.verdict == Verdict::Undecided ? "undecided"
             : r.verdict == Verdict::Tie     ? "tie"
             : r.verdict == Verdict::Better  ? method
                                             : against;
  count(tally, c, against);
  return c;
}

// A method's place in the listing order `order`: its position there, else after, by name.
std::pair<std::size_t, std::string_view> placeIn(std::span<const std::string> order,
                                                 const std::string& method) {
  return {static_cast<std::size_t>(std::find(order.begin(), order.end(), method) - order.begin()),
          method};
}

// Every scene's comparisons against the reference and between every other pair of methods,
// and their tallies, into `summary`; methods ranked by their place in `order`.
void compareMethods(const CoverageByScene& coverageByScene, const std::string& reference,
                    std::span<const std::string> order, BatchSummary& summary) {
  const auto rank = [&order](const std::string& m) { return placeIn(order, m); };
  std::map<std::string, Tally> tallies;
  std::map<std::pair<std::string, std::string>, Tally> pairTallies;
  for (const auto& [scene, coverageOfScene] : coverageByScene) {
    summary.scenes.push_back(scene);
    const auto& byMethod = coverageOfScene;  // a name a lambda may capture (clang 14)
    const auto runsOf = [&byMethod](const std::string& m) {
      const auto it = byMethod.find(m);
      return it == byMethod.end() ? nullptr : &it->second;
    };
    std::vector<std::string> others;
    for (const auto& [method, coverage] : byMethod) {
      if (method != reference) others.push_back(method);
    }
    std::sort(others.begin(), others.end(),
              [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
    for (const std::string& method : others) {
      summary.comparisons.push_back(compareOnScene(scene, method, reference, *runsOf(method),
                                                   runsOf(reference), tallies[method]));
    }
    for (std::size_t i = 0; i < others.size(); ++i) {
      for (std::size_t k = i + 1; k < others.size(); ++k) {
        const std::string &against = others[i], &method = others[k];
        Tally& t = pairTallies[{method, against}];
        t.against = against;
        summary.pairs.push_back(
            {against, compareOnScene(scene, method, against, *runsOf(method), runsOf(against), t)});
      }
    }
  }
  for (auto& [method, t] : tallies) {
    if (!t.method.empty()) summary.tallies.push_back(std::move(t));
  }
  for (auto& [key, t] : pairTallies) {
    if (!t.method.empty()) summary.pairTallies.push_back(std::move(t));
  }
  std::sort(summary.tallies.begin(), summary.tallies.end(),
            [&](const Tally& a, const Tally& b) { return rank(a.method) < rank(b.method); });
  std::sort(summary.pairTallies.begin(), summary.pairTallies.end(),
            [&](const Tally& a, const Tally& b) {
              return std::make_pair(rank(a.against), rank(a.method)) <
                     std::make_pair(rank(b.against), rank(b.method));
            });
}

}  // namespace

BatchSummary summarize(std::vector<JobOutcome> outcomes, const std::string& reference,
                       std::span<const std::string> order,
                       const std::map<std::string, std::string>& groupOf) {
  std::sort(outcomes.begin(), outcomes.end(), [](const JobOutcome& a, const JobOutcome& b) {
    if (a.scene != b.scene) return naturalLess(a.scene, b.scene);
    return std::tie(a.method, a.seed) < std::tie(b.method, b.seed);
  });
  BatchSummary summary;
  std::map<std::pair<std::string, std::string>, std::vector<const JobOutcome*>, SceneMethodLess>
      jobsOf;
  for (const auto& o : outcomes) {
    if (o.failed) summary.failures.push_back(o);
    jobsOf[{o.scene, o.method}].push_back(&o);
  }
  CoverageByScene coverageByScene;
  for (const auto& [key, jobs] : jobsOf) {
    std::vector<double>& coverage = coverageByScene[key.first][key.second];
    summary.methods.push_back(summarizeMethod(key.first, key.second, jobs, coverage));
  }
  // Each scene's rows in the listing order (jobsOf holds them by method name).
  std::stable_sort(summary.methods.begin(), summary.methods.end(),
                   [&order](const MethodSummary& a, const MethodSummary& b) {
                     if (a.scene != b.scene) return naturalLess(a.scene, b.scene);
                     return placeIn(order, a.method) < placeIn(order, b.method);
                   });
  summary.reference = reference;
  compareMethods(coverageByScene, reference, order, summary);
  summary.groups = groupScenes(summary, groupOf);
  return summary;
}

int seedsToReachSignificance() {
  int n = 1;
  while (smallestPValue(n, n) >= kSignificance)
    ++n;
  return n;
}

std::string verdictRuleText() {
  return fmt::format(
      "two-sided Mann-Whitney U test over seeds; a method wins when p < {}, the means differ by "
      "at least {} and its runs are the larger by the test (A12 > 0.5), else a tie; undecided "
      "where the seeds are too few for any p to reach {}",
      kSignificance, kPracticalDifference, kSignificance);
}

RunsComparison compareRuns(std::span<const double> runs, std::span<const double> reference) {
  const MannWhitney test = mannWhitneyU(runs, reference);
  RunsComparison c;
  c.pValue = test.pValue;
  c.exact = test.exact;
  c.meanDifference = describe(runs).mean - describe(reference).mean;
  c.a12 = varghaDelaneyA12(runs, reference);
  c.meanDifferenceCI = welchInterval(runs, reference);
  const int n1 = static_cast<int>(runs.size()), n2 = static_cast<int>(reference.size());
  if (smallestPValue(n1, n2) >= kSignificance) {
    c.verdict = Verdict::Undecided;
    c.seedsNeeded = seedsToReachSignificance();
  } else if (c.pValue < kSignificance && std::abs(c.meanDifference) >= kPracticalDifference &&
             (c.meanDifference > 0.0) == (c.a12 > 0.5)) {
    c.verdict = c.meanDifference > 0.0 ? Verdict::Better : Verdict::Worse;
  }
  return c;
}

void count(Tally& tally, const Comparison& c, const std::string& against) {
  tally.wins += c.winner == c.method;
  tally.ties += c.winner == "tie";
  tally.losses += c.winner == against;
  tally.undecided += c.winner == "undecided";
}

std::string verdictText(const Comparison& c) {
  if (c.winner.empty()) return "-";
  // "needs ≥ 4 seeds", not "(4 seeds)": read as the seeds that were run.
  if (c.seedsNeeded > 0) return fmt::format("{}: needs ≥ {} seeds", c.winner, c.seedsNeeded);
  return fmt::format("{} (p {:.3g})", c.winner, c.pValue);
}

const Comparison* BatchSummary::comparison(const std::string& scene,
                                           const std::string& method) const {
  for (const Comparison& c : comparisons) {
    if (c.scene == scene && c.method == method) return &c;
  }
  return nullptr;
}

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
    BatchSummary s;
    for (const auto& m : j.at("methods")) {
      MethodSummary ms;
      ms.scene = m.at("scene").get<std::string>();
      ms.method = m.at("method").get<std::string>();
      ms.runs = m.at("runs").get<int>();
      ms.failed = m.at("failed").get<int>();
      ms.coverage = describedFrom(m.at("averageCoverage"));
      ms.utilization = describedFrom(m.at("averageUtilization"));
      if (m.contains("finalCoverage")) ms.finalCoverage = describedFrom(m.at("finalCoverage"));
      if (m.contains("averageWeightedCoverage"))
        ms.weightedCoverage = describedFrom(m.at("averageWeightedCoverage"));
      if (m.contains("averageResolutionCoverage"))
        ms.resolutionCoverage = describedFrom(m.at("averageResolutionCoverage"));
      ms.meanObjectCollisionTime = m.at("meanObjectCollisionTime").get<double>();
      ms.meanCameraCollisionTime = m.at("meanCameraCollisionTime").get<double>();
      ms.runsWithCollision = m.at("runsWithCollision").get<int>();
      ms.meanAvoidableContactTime = m.at("meanAvoidableContactTime").get<double>();
      ms.meanUnavoidableContactTime = m.at("meanUnavoidableContactTime").get<double>();
      ms.runsWithAvoidableContact = m.at("runsWithAvoidableContact").get<int>();
      ms.runsWithUnavoidableContact = m.at("runsWithUnavoidableContact").get<int>();
      ms.minObjectDistance = numberOrInfinity(m.at("minObjectDistance"));
      ms.minCameraDistance = numberOrInfinity(m.at("minCameraDistance"));
      ms.medianSeed = m.at("medianSeed").get<std::uint64_t>();
      ms.bestSeed = m.at("bestSeed").get<std::uint64_t>();
      s.methods.push_back(std::move(ms));
    }
    s.scenes = j.at("scenes").get<std::vector<std::string>>();
    s.reference = j.at("reference").get<std::string>();
    for (const auto& c : j.at("comparisons"))
      s.comparisons.push_back(comparisonFrom(c));
    for (const auto& t : j.at("totals"))
      s.tallies.push_back(tallyFrom(t));
    // Summaries written before pairwise verdicts existed have no pairs.
    for (const auto& c : j.value("pairs", nlohmann::json::array()))
      s.pairs.push_back({c.at("against").get<std::string>(), comparisonFrom(c)});
    for (const auto& t : j.value("pairTotals", nlohmann::json::array()))
      s.pairTallies.push_back(tallyFrom(t));
    // Summaries written before scenes had groups have none.
    for (const auto& g : j.value("groups", nlohmann::json::array())) {
      GroupSummary group{g.at("name").get<std::string>(),
                         g.at("scenes").get<std::vector<std::string>>(),
                         {},
                         {},
                         {}};
      for (const auto& m : g.at("meanCoverage"))
        group.meanCoverage.emplace_back(m.at("method").get<std::string>(),
                                        m.at("mean").get<double>());
      for (const auto& t : g.at("totals"))
        group.tallies.push_back(tallyFrom(t));
      for (const auto& t : g.at("pairTotals"))
        group.pairTallies.push_back(tallyFrom(t));
      s.groups.push_back(std::move(group));
    }
    for (const auto& f : j.at("failures")) {
      s.failures.push_back({f.at("scene").get<std::string>(),
                            f.at("method").get<std::string>(),
                            f.at("seed").get<std::uint64_t>(),
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
