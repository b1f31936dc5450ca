#include "cli/run_job.h"

#include <memory>
#include <utility>

#include "camcov/version.h"
#include "control/local_controller.h"
#include "control/paper_controller.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace camcov::cli {

void requireKnownMethod(const std::string& method) {
  if (method != "paper" && method != "local") {
    throw InputError("unknown method '" + method + "' (known: paper, local)");
  }
}

records::RunRecord runJob(const JobSpec& job) {
  requireKnownMethod(job.method);
  const scene::SceneFile file = scene::loadSceneFile(job.sceneFile);
  const scene::Scene& scene = file.scene;

  records::RunMetadata metadata{scene.name, job.sceneFile.string(), file.hash, job.method,
                                job.seed,   job.parameters,         kVersion};
  std::unique_ptr<control::Controller> controller;
  if (job.method == "paper") {
    controller = std::make_unique<control::PaperController>(scene, job.parameters, job.seed);
  } else {
    controller = std::make_unique<control::LocalController>(scene, job.parameters);
  }
  return records::recordRun(scene, std::move(metadata), *controller);
}

}  // namespace camcov::cli
