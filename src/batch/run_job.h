#pragma once
// One job of a batch, and `camcov run`: a scene, a method, a seed, the parameters -> a run.
#include <cstdint>
#include <filesystem>
#include <string>

#include "control/methods.h"
#include "params/parameters.h"
#include "records/run_record.h"

namespace camcov::batch {

struct JobSpec {
  std::filesystem::path sceneFile;
  std::string method;  // a name in the table of methods (control/methods.h)
  std::uint64_t seed = 0;
  params::Parameters parameters;
  // The method itself when the caller brings it (BatchRequest::extraMethods); else the name
  // is looked up in the table. Must outlive the job.
  const control::Method* brought = nullptr;
};

// Throws InputError for an unknown method or a bad scene.
records::RunRecord runJob(const JobSpec& job);

}  // namespace camcov::batch
