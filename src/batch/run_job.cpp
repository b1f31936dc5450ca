#include "batch/run_job.h"

#include <utility>

#include "camcov/version.h"
#include "control/methods.h"
#include "scene/scene_loader.h"

namespace camcov::batch {

records::RunRecord runJob(const JobSpec& job) {
  const control::Method& method =
      job.brought != nullptr ? *job.brought : control::requireMethod(job.method);
  const scene::SceneFile file = scene::loadSceneFile(job.sceneFile);
  const scene::Scene& scene = file.scene;

  records::RunMetadata metadata{scene.name, job.sceneFile.string(), file.hash, job.method,
                                job.seed,   job.parameters,         kVersion};
  const auto controller = method.make(scene, job.parameters, job.seed);
  return records::recordRun(scene, std::move(metadata), *controller);
}

}  // namespace camcov::batch
