#include "batch/run_job.h"

#include <utility>

#include "camcov/version.h"
#include "control/methods.h"
#include "scene/scene_loader.h"
#include "sim/simulator.h"

namespace camcov::batch {

records::RunRecord runJob(const JobSpec& job) {
  const control::Method& method =
      job.brought != nullptr ? *job.brought : control::requireMethod(job.method);
  const scene::SceneFile file = scene::loadSceneFile(job.sceneFile);
  const scene::Scene& scene = file.scene;

  records::RunMetadata metadata{scene.name, job.sceneFile.string(), file.hash, job.method,
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
