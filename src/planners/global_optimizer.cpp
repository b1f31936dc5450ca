#include "planners/global_optimizer.h"

#include "planners/visibility_sampler.h"
#include "util/worker_pool.h"

namespace camcov::planners {

std::optional<GlobalResult> optimizeGlobally(reward::RewardModel& model,
                                             const StateValidity& validity, std::size_t cameras,
                                             int samplesPerCamera, Random& random,
                                             std::span<reward::RewardModel> helpers) {
  GlobalResult result;
  // Line 1: with no camera placed, all of ∂T is invisible.
  model.evaluate(result.poses);
  std::vector<geometry::Pose> samples;
  std::vector<double> scores;
  VisibilitySampler sampler;
  for (std::size_t j = 0; j < cameras; ++j) {
    // Line 3: q1 on what is still invisible (everything seen already: anywhere on ∂T).
    if (!sampler.focusOnUnseen(model, random)) return std::nullopt;  // line 6
    // Lines 5, 7–9: the K samples, drawn in order from the run's generator.
    samples.clear();
    for (int k = 0; k < samplesPerCamera; ++k) {
      if (const auto pose = sampler.sample(random, validity, model.halfFov(j))) {
        samples.push_back(*pose);
      }
    }
    if (samples.empty()) return std::nullopt;
    // Line 10: each scored with the cameras placed before it, in one share per model.
    scores.resize(samples.size());
    const std::size_t shares = 1 + helpers.size();
    forEachOnWorkers(shares, static_cast<unsigned>(shares), [&](std::size_t share) {
      reward::RewardModel& scorer = share == 0 ? model : helpers[share - 1];
      std::vector<geometry::Pose> team = result.poses;
      team.emplace_back();
      for (std::size_t k = share * samples.size() / shares;
           k < (share + 1) * samples.size() / shares; ++k) {
        team.back() = samples[k];
        scores[k] = scorer.reward(team);
      }
    });
    // Lines 10–11: the first best.
    std::size_t best = 0;
    for (std::size_t k = 1; k < samples.size(); ++k) {
      if (scores[k] > scores[best]) best = k;
    }
    result.poses.push_back(samples[best]);                // line 12
    result.reward = model.evaluate(result.poses).reward;  // line 13: updates S
  }
  return result;
}

}  // namespace camcov::planners
