#include "sim/scene_parameters.h"

#include <string_view>

#include "params/parameter_table.h"
#include "sim/run_length.h"

namespace camcov::sim {

params::Parameters forScene(params::Parameters p, const scene::Scene& scene,
                            const std::string& sceneFile, bool durationGiven) {
  p = withRunLength(p, scene.duration, durationGiven);
  if (scene.knowledgeSettings.is_null()) return p;
  const params::Parameters defaults;
  const params::Parameters fromScene =
      params::fromJson(scene.knowledgeSettings, sceneFile, defaults);
  for (const params::ParamField& f : params::parameterTable()) {
    const std::string_view key = f.key;
    if (!key.starts_with("knowledge.") && !key.starts_with("comms.")) continue;
    if (f.get(p) == f.get(defaults)) f.set(p, f.get(fromScene));
  }
  return p;
}

}  // namespace camcov::sim
