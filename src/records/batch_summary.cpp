#include "records/batch_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <tuple>

#include "util/natural_order.h"

namespace camcov::records {

namespace {

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

const Comparison* BatchSummary::comparison(const std::string& scene,
                                           const std::string& method) const {
  for (const Comparison& c : comparisons) {
    if (c.scene == scene && c.method == method) return &c;
  }
  return nullptr;
}

}  // namespace camcov::records
