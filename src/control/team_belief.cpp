#include "control/team_belief.h"

namespace camcov::control {

void believedTeam(const scene::Scene& scene, const OwnKnowledge& own, std::size_t j,
                  const geometry::Pose& self, std::vector<geometry::Pose>& out) {
  out.resize(scene.cameras.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& heard = i < own.teammates.size() ? own.teammates[i] : std::nullopt;
    out[i] = i == j ? self : heard ? heard->pose : scene.cameras[i].initial;
  }
}

}  // namespace camcov::control
