#pragma once
// One job of a batch, and `camcov run`: a scene, a method, a seed, the parameters -> a run.
#include <cstdint>
#include <filesystem>
#include <string>

#include "control/methods.h"
#include "params/parameters.h"
#include "records/run_record.h"
#include "scene/scene.h"

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

// Simulates `scene` with `controller` (made with metadata.parameters and metadata.seed) and
// records every step: what runJob and the benchmark programs do.
records::RunRecord recordRun(const scene::Scene& scene, records::RunMetadata metadata,
                             control::Controller& controller);

}  // namespace camcov::batch
