#include "batch/batch_plan.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "control/methods.h"
#include "params/parameter_table.h"
#include "records/run_files.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/natural_order.h"

namespace camcov::batch {
namespace {

namespace fs = std::filesystem;

// Folders contribute their *.json files in natural name order; files are taken as given.
std::vector<fs::path> sceneFiles(const std::vector<std::string>& inputs) {
  std::vector<fs::path> files;
  for (const auto& input : inputs) {
    if (fs::is_directory(input)) {
      std::vector<fs::path> found;
      for (const auto& e : fs::directory_iterator(input)) {
        if (e.path().extension() == ".json") found.push_back(e.path());
      }
      std::sort(found.begin(), found.end(), [](const fs::path& a, const fs::path& b) {
        return naturalLess(a.filename().string(), b.filename().string());
      });
      if (found.empty()) throw InputError(input + ": no scene files (*.json) in this folder");
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::exists(input)) {
      files.emplace_back(input);
    } else {
      throw InputError(input + ": no such scene file or folder");
    }
  }
  return files;
}

// The method `name` that the caller brought, or nullptr when it is the table's; InputError
// (naming every known method) when it is neither.
const control::Method* broughtMethod(const std::string& name,
                                     std::span<const control::Method> extra) {
  for (const control::Method& m : extra) {
    if (m.name == name) return &m;
  }
  control::requireMethod(name, extra);
  return nullptr;
}

}  // namespace

Shard parseShard(const std::string& text) {
  if (text.empty()) return {};
  std::size_t k = 0, n = 0;
  char slash = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> k >> slash >> n) || slash != '/' || (in >> rest) || n == 0 || k == 0 || k > n) {
    throw InputError("--shard " + text + ": expected K/N with 1 <= K <= N");
  }
  return {k - 1, n};
}

BatchPlan planBatch(const BatchRequest& r, const std::string& toolVersion) {
  if (r.methods.empty()) throw InputError("--methods: name at least one method");
  std::vector<const control::Method*> brought;  // per name in r.methods; nullptr: the table's
  for (const auto& m : r.methods)
    brought.push_back(broughtMethod(m, r.extraMethods));
  if (r.seeds == 0) throw InputError("--seeds must be at least 1");
  BatchPlan plan;
  plan.manifest = {toolVersion, r.parameters, r.methods, r.seeds, {}, r.command};
  for (const fs::path& file : sceneFiles(r.scenes)) {
    const scene::SceneFile s = scene::loadSceneFile(file);
    plan.manifest.scenes.push_back({s.scene.name, file.string(), s.hash});
  }
  std::size_t i = 0;
  for (const auto& entry : plan.manifest.scenes) {
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
      const std::string& method = r.methods[m];
      for (std::uint64_t seed = 1; seed <= r.seeds; ++seed, ++i) {
        if (i % r.shard.count != r.shard.index) continue;
        plan.jobs.push_back({{entry.file, method, seed, r.parameters, brought[m]},
                             entry.name,
                             entry.hash,
                             records::runStem(entry.name, method, seed)});
      }
    }
  }
  plan.totalJobs = i;
  return plan;
}

void prepareFolder(const records::BatchFolder& folder, const records::BatchManifest& manifest,
                   bool force) {
  if (const auto previous = folder.readManifest()) {
    if (params::toJson(previous->parameters) != params::toJson(manifest.parameters) && !force) {
      throw InputError(folder.root().string() +
                       " holds results made with other parameters; use another --out, "
                       "or --force to run those jobs again with the new ones");
    }
  }
  folder.removeStaleTemporaries();
  folder.writeManifest(manifest);
}

}  // namespace camcov::batch
