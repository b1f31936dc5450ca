#pragma once
// Moves that improve a whole team's pose, one camera at a time, against the reward at one
// instant, eq. (8): what the offline optimum (offline_optimum.h) and our method's refinement
// of a global candidate (control/paper_controller.h, camcov.refine) are made of. A move is
// taken only if it raises the team's reward and keeps the camera valid (StateValidity).
// Every reward evaluation is counted, and no move starts once the budget is spent.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "planners/state_validity.h"
#include "planners/visibility_sampler.h"
#include "reward/reward_model.h"
#include "util/random.h"

namespace camcov::planners {

class TeamImprovement {
 public:
  // `budget`: reward evaluations in all.
  TeamImprovement(reward::RewardModel& model, const StateValidity& validity, std::int64_t budget)
      : model_(model), validity_(validity), budget_(budget) {}

  std::int64_t evaluations() const { return evaluations_; }
  void spend(std::int64_t evaluations) { evaluations_ += evaluations; }
  bool spent() const { return evaluations_ >= budget_; }

  // Re-placement: `samples` poses of Algorithm 2's kind for camera j (lines 3–9: around a
  // point of ∂T the others leave unseen, anywhere on ∂T if they see it all); the best, if
  // it beats `value` (team's reward, updated). True if camera j moved.
  bool replace(std::vector<geometry::Pose>& team, std::size_t j, double& value, int samples,
               Random& random);
  // Pattern search on camera j's x, y and γ, the steps halving from 1 m and 0.2 rad while no
  // move helps, down to 1 mm and 0.001 rad. True if camera j moved.
  bool refine(std::vector<geometry::Pose>& team, std::size_t j, double& value);
  // refine() for every camera in `movable`, in turn, passes until one finds
  // nothing or the budget is spent.
  bool refineAll(
      std::vector<geometry::Pose>& team, double& value,
      const scene::CameraSet& movable = scene::CameraSet::firstCameras(scene::kMaxCameras));

 private:
  double reward(std::span<const geometry::Pose> team) {
    ++evaluations_;
    return model_.reward(team);
  }

  reward::RewardModel& model_;
  const StateValidity& validity_;
  std::int64_t budget_;
  std::int64_t evaluations_ = 0;
  VisibilitySampler sampler_;
};

}  // namespace camcov::planners
