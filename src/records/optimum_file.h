#pragma once
// The offline optimum of a scene at one instant (planners/offline_optimum.h) as a
// results file: `camcov optimum -o` writes one, `camcov bench` one per scene that holds still
// (optimum/<scene>.json), and the report reads them to set each method's final coverage
// against it.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "params/parameters.h"
#include "planners/offline_optimum.h"

namespace camcov::records {

inline constexpr std::string_view kOptimumFormat = "camcov-optimum/1";

// What the search was asked, with its result: the file's content.
struct OptimumFile {
  std::string scene;      // name
  std::string sceneFile;  // as given
  std::uint64_t sceneHash = 0;
  double time = 0.0;  // s, the instant
  std::uint64_t seed = 0;
  std::int64_t budget = 0;  // reward evaluations
  params::Parameters parameters;
  planners::OptimumResult result;
  // s: how long the team needs from its start to these poses, section V-B's estimate (each
  // camera assigned a pose by the Hungarian method; obstacles ignored, so a lower bound where
  // they are in the way). NaN in files written before it was recorded.
  double travelTime = std::numeric_limits<double>::quiet_NaN();
};

nlohmann::json optimumToJson(const OptimumFile& file);
// InputError naming `source` for anything but an optimum file of this format.
OptimumFile optimumFromJson(const nlohmann::json& j, const std::string& source);
OptimumFile loadOptimumFile(const std::filesystem::path& file);

}  // namespace camcov::records
