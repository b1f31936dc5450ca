#include "batch/merge.h"

#include <algorithm>
#include <map>
#include <optional>

#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "util/input_error.h"

namespace camcov::batch {

namespace fs = std::filesystem;

records::BatchManifest mergeFolders(const std::vector<std::string>& inputs,
                                    const records::BatchFolder& target,
                                    const std::vector<std::string>& command) {
  std::optional<records::BatchManifest> manifest;
  std::map<std::string, records::JobTiming> timings;
  for (const auto& input : inputs) {
    const records::BatchFolder source(input);
    const auto m = source.readManifest();
    if (!m) throw InputError(input + ": not a camcov bench folder (no batch.json)");
    if (!manifest) {
      manifest = m;
    } else {
      if (params::toJson(m->parameters) != params::toJson(manifest->parameters)) {
        throw InputError(input + ": made with other parameters than " + inputs.front());
      }
      for (const auto& scene : m->scenes) {
        const bool known = std::any_of(manifest->scenes.begin(), manifest->scenes.end(),
                                       [&](const auto& s) { return s.name == scene.name; });
        if (!known) manifest->scenes.push_back(scene);
      }
    }
    for (const auto& [stem, t] : source.readTimings())
      timings[stem] = t;
    if (fs::exists(target.runsDir()) && fs::equivalent(source.runsDir(), target.runsDir()))
      continue;
    // Each file whole or not at all, and a run's JSON after its CSV: a run counts as finished
    // when its JSON exists, so a killed merge resumes like a killed batch.
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(source.runsDir())) {
      if (!records::isTemporaryFile(entry.path())) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
      return std::pair(a.extension() == ".json", a) < std::pair(b.extension() == ".json", b);
    });
    for (const fs::path& file : files)
      records::copyFileAtomically(file, target.runsDir() / file.filename());
  }
  if (!manifest) throw InputError("merge: no folders to combine");
  manifest->command = command;
  target.writeManifest(*manifest);
  target.writeTimings(timings);
  return *manifest;
}

}  // namespace camcov::batch
