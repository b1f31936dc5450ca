#include "planners/global_optimizer.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>

#include "planners/visibility_sampler.h"
#include "reward/added_camera_bound.h"
#include "util/worker_pool.h"

namespace camcov::planners {

std::optional<GlobalResult> optimizeGlobally(reward::RewardModel& model,
                                             const StateValidity& validity, std::size_t cameras,
                                             int samplesPerCamera, Random& random,
                                             std::span<reward::RewardModel> helpers) {
  GlobalResult result;
  // Line 1: with no camera placed, all of ∂T is invisible.
  reward::RewardTerms placed = model.evaluate(result.poses);
  std::vector<geometry::Pose> samples;
  std::vector<double> bounds, scores, terms;
  std::vector<std::size_t> order;
  reward::AddedCameraBound bound;
  VisibilitySampler sampler;
  for (std::size_t j = 0; j < cameras; ++j) {
    // Line 3: q1 on what is still invisible (everything seen already: anywhere on ∂T).
    if (!sampler.focusOnUnseen(model, random)) return std::nullopt;  // line 6
    // Lines 5, 7–9: the K samples, drawn in order from the run's generator.
    samples.clear();
    for (int k = 0; k < samplesPerCamera; ++k) {
      if (const auto pose = sampler.sample(random, validity, model.lens(j))) {
        samples.push_back(*pose);
      }
    }
    if (samples.empty()) return std::nullopt;
    // Line 10: each scored with the cameras placed before it, highest bound first, so that the
    // samples that cannot beat a score already taken are never swept (added_camera_bound.h):
    // the cheap bound orders them and ends the scoring, the tighter one skips a sample. The
    // shares of the models take the next sample of that order in turn and share the best
    // score: which samples go unswept then depends on their timing, the first best does not
    // (neither it nor any sample scoring as much can be skipped).
    // Where the reward counts resolution, a sample may resolve what the team only sees: no
    // bound holds, and every sample is scored.
    using Precision = reward::AddedCameraBound::Precision;
    const bool bounded = !model.countsResolution();
    if (bounded) bound.prepare(model, result.poses, placed);
    bounds.resize(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k)
      bounds[k] = bounded ? bound.of(samples[k], Precision::Coarse, terms)
                          : std::numeric_limits<double>::infinity();
    order.resize(samples.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return bounds[a] > bounds[b]; });
    scores.assign(samples.size(), -std::numeric_limits<double>::infinity());
    std::atomic<std::size_t> next{0};
    std::atomic<double> bestScore{-std::numeric_limits<double>::infinity()};
    const std::size_t shares = 1 + helpers.size();
    forEachOnWorkers(shares, static_cast<unsigned>(shares), [&](std::size_t share) {
      reward::RewardModel& scorer = share == 0 ? model : helpers[share - 1];
      std::vector<geometry::Pose> team = result.poses;
      team.emplace_back();
      std::vector<double> shareTerms;
      for (std::size_t i = next++; i < order.size(); i = next++) {
        const std::size_t k = order[i];
        double best = bestScore.load(std::memory_order_relaxed);
        if (reward::AddedCameraBound::cannotBeat(bounds[k], best)) break;
        if (bounded && reward::AddedCameraBound::cannotBeat(
                           bound.of(samples[k], Precision::Fine, shareTerms), best))
          continue;
        team.back() = samples[k];
        scores[k] = scorer.reward(team);
        while (scores[k] > best &&
               !bestScore.compare_exchange_weak(best, scores[k], std::memory_order_relaxed)) {
        }
      }
    });
    // Lines 10–11: the first best (a sample left unscored scores below it).
    std::size_t best = 0;
    for (std::size_t k = 1; k < samples.size(); ++k) {
      if (scores[k] > scores[best]) best = k;
    }
    result.poses.push_back(samples[best]);  // line 12
    placed = model.evaluate(result.poses);  // line 13: updates S
    result.reward = placed.reward;
  }
  return result;
}

}  // namespace camcov::planners
