#include "batch/run_job.h"

#include <utility>

#include "camcov/version.h"
#include "control/methods.h"
#include "sim/simulator.h"

namespace camcov::batch {

std::shared_ptr<const scene::SceneFile> readSceneFile(const std::filesystem::path& file) {
  return std::make_shared<const scene::SceneFile>(scene::loadSceneFile(file));
}

records::RunRecord runJob(const JobSpec& job) {
  const control::Method& method =
      job.brought != nullptr ? *job.brought : control::requireMethod(job.method);
  // Hashing the bytes again costs a small part of parsing and validating them.
  const bool unchanged =
      job.scene != nullptr && scene::sceneFileHash(job.sceneFile) == job.scene->hash;
  const std::shared_ptr<const scene::SceneFile> file =
      unchanged ? job.scene : readSceneFile(job.sceneFile);
  const scene::Scene& scene = file->scene;

  records::RunMetadata metadata{scene.name, job.sceneFile.string(), file->hash, job.method,
                                job.seed,   job.parameters,         kVersion};
  const auto controller = method.make(scene, job.parameters, job.seed);
  return recordRun(scene, std::move(metadata), *controller);
}

records::RunRecord recordRun(const scene::Scene& scene, records::RunMetadata metadata,
                             control::Controller& controller) {
  records::RunRecord run;
  run.metadata = std::move(metadata);
  records::RunRecorder recorder(run);
  run.summary =
      sim::simulate(scene, run.metadata.parameters, controller, recorder, run.metadata.seed);
  return run;
}

}  // namespace camcov::batch
