#include "control/neighbourhood.h"

#include <algorithm>
#include <utility>

namespace camcov::control {

std::vector<std::size_t> neighbourhood(std::span<const geometry::Pose> believed, std::size_t j,
                                       std::size_t size) {
  return neighbourhood(believed, j, size, scene::CameraSet::firstCameras(believed.size()));
}

std::vector<std::size_t> neighbourhood(std::span<const geometry::Pose> believed, std::size_t j,
                                       std::size_t size, const scene::CameraSet& among) {
  std::vector<std::size_t> members;
  for (std::size_t i = 0; i < believed.size(); ++i) {
    if (i == j || among.contains(i)) members.push_back(i);
  }
  if (members.size() <= size) return members;
  const geometry::Vec2 self = believed[j].position();
  // Nearest first, itself at distance 0 before any teammate at the same spot.
  const auto key = [&](std::size_t i) {
    return std::pair{i == j ? -1.0 : geometry::norm2(believed[i].position() - self), i};
  };
  std::partial_sort(members.begin(), members.begin() + static_cast<std::ptrdiff_t>(size),
                    members.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  members.resize(size);
  std::sort(members.begin(), members.end());
  return members;
}

scene::Scene neighbourhoodScene(const scene::Scene& scene, std::span<const std::size_t> members) {
  scene::Scene sub;
  sub.name = scene.name;
  sub.boundary = scene.boundary;
  sub.resolution = scene.resolution;
  for (std::size_t i : members)
    sub.cameras.push_back(scene.cameras[i]);
  return sub;
}

}  // namespace camcov::control
