#pragma once
// One job of a batch, and `camcov run`: a scene, a method, a seed, the parameters -> a run.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "control/methods.h"
#include "params/parameters.h"
#include "records/run_record.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace camcov::batch {

struct JobSpec {
  std::filesystem::path sceneFile;
  std::string method;  // a name in the table of methods (control/methods.h)
  std::uint64_t seed = 0;
  params::Parameters parameters;
  // The method itself when the caller brings it (BatchRequest::extraMethods); else the name
  // is looked up in the table. Must outlive the job.
  const control::Method* brought = nullptr;
  // The scene file as the caller already read and validated it, shared and never changed: a
  // batch's plan reads each file once for all its jobs. runJob runs it while `sceneFile` still
  // holds the bytes of its hash, and reads the file itself when it is null or the file changed
  // since (edited, or broken, during a long batch: the job runs or fails as the file is now).
  std::shared_ptr<const scene::SceneFile> scene = nullptr;
};

// Reads and validates a scene file once, to be shared by the jobs (and the caller) that use it.
std::shared_ptr<const scene::SceneFile> readSceneFile(const std::filesystem::path& file);

// Throws InputError for an unknown method or a bad scene.
records::RunRecord runJob(const JobSpec& job);

// Simulates `scene` with `controller` (made with metadata.parameters and metadata.seed) and
// records every step: what runJob and the benchmark programs do.
records::RunRecord recordRun(const scene::Scene& scene, records::RunMetadata metadata,
                             control::Controller& controller);

}  // namespace camcov::batch
