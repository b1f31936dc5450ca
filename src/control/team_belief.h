#pragma once
// The team as one camera believes it under limited knowledge (docs/method.md, "What a camera
// knows"): itself where it is, a teammate where its last message said, and a teammate it never
// heard where the scene starts it (the scene is shared before the run). One rule for every reader
// of a camera's belief: the decentralized method and the learning environments' known view.
#include <cstddef>
#include <vector>

#include "control/controller.h"
#include "scene/scene.h"

namespace camcov::control {

// Writes camera j's belief of the team's poses into `out` (one per scene camera).
void believedTeam(const scene::Scene& scene, const OwnKnowledge& own, std::size_t j,
                  const geometry::Pose& self, std::vector<geometry::Pose>& out);

}  // namespace camcov::control
