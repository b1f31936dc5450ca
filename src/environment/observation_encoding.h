#pragma once
// An episode's present instant as the fixed-size array of floats the learning environments
// observe. The layout, sizes and bounds are control/observation_encoding.h's (a method may
// observe the same floats); here the episode supplies the instant.
#include <cstddef>
#include <span>

#include "control/observation_encoding.h"
#include "environment/episode.h"
#include "reward/metrics.h"

namespace camcov::environment {

using control::cameraColumns;
using control::EncodingSizes;
using control::kLengthBound;
using control::kPositionBound;
using control::kRateBound;
using control::kRewardBound;
using control::observationBounds;
using control::requireFits;
using control::TargetSlots;
using control::View;

// Writes the episode's present instant into `out` (size sizes.size()); `camera` is the
// camera whose view it is for View::own and View::known. std::invalid_argument if the scene
// does not fit.
void encodeObservation(const Episode& episode, const EncodingSizes& sizes, View view,
                       std::size_t camera, std::span<float> out);

// Camera j's own terms of the reward, as if it were alone: eq. (3) over what it sees, eq. (5)
// with M = 1, eq. (6) against the objects and the other cameras, and eq. (8) of those; in the
// true world, as the run is scored (Episode::scored), also under limited knowledge.
reward::RewardTerms ownTerms(const Episode& episode, std::size_t camera);

}  // namespace camcov::environment
