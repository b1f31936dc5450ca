#pragma once
// The part of the team one camera of camcov-dec plans for (docs/method.md, "Decentralized
// teams"): itself and at most N - 1 teammates (camcov.neighbours), the nearest to it as it
// believes them to be. Cameras farther apart see less of the same things and get in each
// other's way less, so a camera's plan is made for those near it, and its work per step grows
// with N, not with the team. A team of at most N is one neighbourhood: every camera plans for all.
#include <cstddef>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "scene/camera_set.h"
#include "scene/scene.h"

namespace camcov::control {

// The indices of camera j's neighbourhood in increasing order, j among them: the `size` - 1
// teammates nearest to believed[j] (ties to the lower index), or the whole team where it has
// at most `size` cameras.
std::vector<std::size_t> neighbourhood(std::span<const geometry::Pose> believed, std::size_t j,
                                       std::size_t size);
// The same among j and the teammates in `among` only (camcov.heardOnly: those it has heard of).
std::vector<std::size_t> neighbourhood(std::span<const geometry::Pose> believed, std::size_t j,
                                       std::size_t size, const scene::CameraSet& among);

// The scene as a neighbourhood plans in it: the room, the resolution required and the members'
// cameras (in `members` order); no targets or obstacles, which a planner reads from what it
// knows of the world, never from the scene.
scene::Scene neighbourhoodScene(const scene::Scene& scene, std::span<const std::size_t> members);

}  // namespace camcov::control
