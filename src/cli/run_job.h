#pragma once
// One job of a batch, and `camcov run`: a scene, a method, a seed, the parameters -> a run.
#include <cstdint>
#include <filesystem>
#include <string>

#include "params/parameters.h"
#include "records/run_record.h"

namespace camcov::cli {

struct JobSpec {
  std::filesystem::path sceneFile;
  std::string method;  // "paper" (section V) or "local" (the baseline)
  std::uint64_t seed = 0;
  params::Parameters parameters;
};

// Throws InputError for an unknown method or a bad scene.
records::RunRecord runJob(const JobSpec& job);
void requireKnownMethod(const std::string& method);

}  // namespace camcov::cli
