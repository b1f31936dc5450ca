#pragma once
// One job of a batch, and `camcov run`: a scene, a method, a seed, the parameters -> a run.
#include <cstdint>
#include <filesystem>
#include <string>

#include "params/parameters.h"
#include "records/run_record.h"

namespace camcov::batch {

struct JobSpec {
  std::filesystem::path sceneFile;
  std::string method;  // a name in the table of methods (control/methods.h)
  std::uint64_t seed = 0;
  params::Parameters parameters;
};

// Throws InputError for an unknown method or a bad scene.
records::RunRecord runJob(const JobSpec& job);

}  // namespace camcov::batch
