#include "environment/observation_encoding.h"

#include <stdexcept>
#include <string>

#include "scene/camera.h"

namespace camcov::environment {

void encodeObservation(const Episode& episode, const EncodingSizes& sizes, View view,
                       std::size_t camera, std::span<float> out) {
  control::encodeObservation(episode.scene(), episode.params(), episode.observation(), sizes, view,
                             camera, out);
}

reward::RewardTerms ownTerms(const Episode& episode, std::size_t camera) {
  const control::Observation o = episode.scored();  // a reward: the true world's
  const scene::Scene& scene = episode.scene();
  if (camera >= scene.cameras.size())
    throw std::invalid_argument("ownTerms: no camera " + std::to_string(camera));
  return reward::termsAlone(o.world, o.seen, o.cameras, scene::lenses(scene), camera,
                            episode.params().reward);
}

}  // namespace camcov::environment
