#include "planners/global_optimizer.h"

#include <limits>

#include "planners/visibility_sampler.h"

namespace camcov::planners {

std::optional<GlobalResult> optimizeGlobally(reward::RewardModel& model,
                                             const StateValidity& validity, std::size_t cameras,
                                             int samplesPerCamera, Random& random) {
  GlobalResult result;
  // Line 1: with no camera placed, all of ∂T is invisible.
  model.evaluate(result.poses);
  std::vector<visibility::Segment> invisible;
  VisibilitySampler sampler;
  for (std::size_t j = 0; j < cameras; ++j) {
    invisible.clear();
    for (const auto& s : model.segments()) {
      if (s.visibleBy == 0) invisible.push_back(s);
    }
    // Line 3: q1 on what is still invisible (everything seen already: anywhere on ∂T).
    auto q1 = samplePointOnSegments(invisible, random);
    if (!q1) q1 = samplePointOnSegments(model.segments(), random);
    if (!q1 || !sampler.focus(model, *q1)) return std::nullopt;  // line 6
    double best = -std::numeric_limits<double>::infinity();
    std::optional<geometry::Pose> bestPose;
    result.poses.emplace_back();
    for (int k = 0; k < samplesPerCamera; ++k) {                             // lines 5-11
      const auto pose = sampler.sample(random, validity, model.halfFov(j));  // lines 7-9
      if (!pose) continue;
      result.poses.back() = *pose;
      const double r = model.reward(result.poses);  // line 10
      if (r > best) {
        best = r;
        bestPose = pose;
      }
    }
    if (!bestPose) return std::nullopt;
    result.poses.back() = *bestPose;                      // line 12
    result.reward = model.evaluate(result.poses).reward;  // line 13: updates S
  }
  return result;
}

}  // namespace camcov::planners
