#pragma once
// The offline optimum of a scene file at one instant (planners/offline_optimum.h):
// what `camcov optimum` computes, and `camcov bench` for every scene that holds still.
#include <cstdint>
#include <filesystem>

#include "params/parameters.h"
#include "records/optimum_file.h"
#include "scene/scene_loader.h"

namespace camcov::batch {

// Searches with `budget` reward evaluations, K (the parameters') samples per camera and
// round, from `seed`. InputError for a bad scene, or if no valid pose was found for every
// camera.
records::OptimumFile searchSceneOptimum(const std::filesystem::path& sceneFile,
                                        const params::Parameters& parameters, double time,
                                        std::int64_t budget, std::uint64_t seed);
// The same for a scene already read from `sceneFile`.
records::OptimumFile searchSceneOptimum(const scene::SceneFile& file,
                                        const std::filesystem::path& sceneFile,
                                        const params::Parameters& parameters, double time,
                                        std::int64_t budget, std::uint64_t seed);

// The search a bench makes for a scene that holds still: at t = 0 from seed 1.
inline constexpr std::uint64_t kBenchOptimumSeed = 1;

}  // namespace camcov::batch
