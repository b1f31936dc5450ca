#include "batch/batch_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>

#include "control/methods.h"
#include "params/parameter_table.h"
#include "records/run_files.h"
#include "scene/scene_families.h"
#include "scene/scene_loader.h"
#include "sim/scene_parameters.h"
#include "util/code_identity.h"
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

// What makes a method's results: this build's code for the methods compiled into it, the
// fingerprint a brought method carries otherwise.
std::string identityOf(const control::Method* brought) {
  if (brought != nullptr && !brought->identity.empty()) return brought->identity;
  return std::string("c++ ") + codeIdentity();
}

// A scene that is not drawn from a family is grouped under its folder's name, with as many of
// the folder's parents as tell two folders of the same name apart ("a/scenes", "b/scenes").
void nameFolderGroups(std::vector<records::SceneEntry>& scenes,
                      const std::vector<fs::path>& folderOf) {
  std::vector<fs::path> folders;
  for (const fs::path& f : folderOf) {
    if (!f.empty() && std::find(folders.begin(), folders.end(), f) == folders.end())
      folders.push_back(f);
  }
  // The last `depth` parts of a folder's path.
  const auto tail = [](const fs::path& folder, std::size_t depth) {
    std::vector<fs::path> parts(folder.begin(), folder.end());
    fs::path out;
    for (std::size_t i = parts.size() - std::min(depth, parts.size()); i < parts.size(); ++i)
      out /= parts[i];
    return out.relative_path().empty() ? out : out.relative_path();
  };
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    if (folderOf[k].empty()) continue;
    std::size_t depth = 1;
    const auto clashes = [&] {
      return std::any_of(folders.begin(), folders.end(), [&](const fs::path& other) {
        return other != folderOf[k] && tail(other, depth) == tail(folderOf[k], depth);
      });
    };
    const auto parts =
        static_cast<std::size_t>(std::distance(folderOf[k].begin(), folderOf[k].end()));
    while (clashes() && depth < parts)
      ++depth;
    scenes[k].group = tail(folderOf[k], depth).generic_string();
  }
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
  if (r.methods.empty()) throw InputError("--methods: name at least one method, e.g. paper,local");
  std::vector<const control::Method*> brought;  // per name in r.methods; nullptr: the table's
  for (std::size_t m = 0; m < r.methods.size(); ++m) {
    // Two jobs of one name would race for one results file.
    if (std::find(r.methods.begin(), r.methods.begin() + m, r.methods[m]) !=
        r.methods.begin() + m) {
      throw InputError("--methods: " + r.methods[m] + " is named twice");
    }
    brought.push_back(broughtMethod(r.methods[m], r.extraMethods));
  }
  if (r.seeds == 0 || r.seeds > kMaxSeeds) {
    throw InputError("--seeds " + std::to_string(r.seeds) + ": expected 1 to " +
                     std::to_string(kMaxSeeds));
  }
  BatchPlan plan;
  plan.manifest.toolVersion = toolVersion;
  plan.manifest.parameters = r.parameters;
  plan.manifest.methods = r.methods;
  plan.manifest.seeds = r.seeds;
  plan.manifest.command = r.command;
  for (std::size_t m = 0; m < r.methods.size(); ++m) {
    plan.manifest.methodIdentities[r.methods[m]] = identityOf(brought[m]);
    if (brought[m] != nullptr)
      plan.manifest.methodLooks[r.methods[m]] = {brought[m]->description, brought[m]->color};
  }
  std::vector<fs::path> folderOf;  // per scene not drawn from a family, its folder; else empty
  // Per scene: with its own duration and knowledge settings, if any.
  std::vector<params::Parameters> runParameters;
  // Per scene: its file as read here, which every job of it runs (one copy per scene).
  std::vector<std::shared_ptr<const scene::SceneFile>> loaded;
  for (const fs::path& file : sceneFiles(r.scenes)) {
    const scene::SceneFile& s = *loaded.emplace_back(readSceneFile(file));
    runParameters.push_back(sim::forScene(r.parameters, s.scene, file.string(), r.durationGiven));
    const std::string& family = s.scene.family;
    plan.manifest.scenes.push_back({s.scene.name, file.string(), s.hash, family});
    folderOf.push_back(!family.empty() ? fs::path()
                                       : fs::absolute(file).lexically_normal().parent_path());
  }
  nameFolderGroups(plan.manifest.scenes, folderOf);
  const std::uint64_t total = plan.manifest.scenes.size() * r.methods.size() * r.seeds;
  if (total > kMaxJobs) {
    throw InputError(fmt::format(
        "{} scenes x {} methods x {} seeds = {} jobs: at most {} fit in one batch; split it "
        "with --shard or fewer --seeds",
        plan.manifest.scenes.size(), r.methods.size(), r.seeds, total, kMaxJobs));
  }
  plan.jobs.reserve(total / r.shard.count + 1);
  std::size_t i = 0;
  for (std::size_t s = 0; s < plan.manifest.scenes.size(); ++s) {
    const auto& entry = plan.manifest.scenes[s];
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
      const std::string& method = r.methods[m];
      for (std::uint64_t seed = 1; seed <= r.seeds; ++seed, ++i) {
        if (i % r.shard.count != r.shard.index) continue;
        plan.jobs.push_back({{entry.file, method, seed, runParameters[s], brought[m], loaded[s]},
                             entry.name,
                             entry.hash,
                             records::runStem(entry.name, method, seed)});
      }
    }
  }
  plan.totalJobs = i;
  return plan;
}

std::vector<std::string> methodsMadeByOtherCode(const records::BatchManifest& previous,
                                                const records::BatchManifest& now) {
  std::vector<std::string> changed;
  for (const std::string& method : now.methods) {
    const auto was = previous.methodIdentities.find(method);
    if (was != previous.methodIdentities.end()) {
      if (was->second != now.methodIdentities.at(method)) changed.push_back(method);
    } else if (previous.methodIdentities.empty() ||
               std::find(previous.methods.begin(), previous.methods.end(), method) !=
                   previous.methods.end()) {
      changed.push_back(method);  // ran before identities were recorded: unknown code
    }
  }
  return changed;
}

void prepareFolder(const records::BatchFolder& folder, records::BatchManifest& manifest,
                   bool force) {
  folder.refuseForeignContent();
  if (const auto previous = folder.readManifest()) {
    if (params::toJson(previous->parameters) != params::toJson(manifest.parameters) && !force) {
      throw InputError(folder.root().string() +
                       " holds results made with other parameters; use another --out, "
                       "or --force to run those jobs again with the new ones");
    }
    const std::vector<std::string> changed = methodsMadeByOtherCode(*previous, manifest);
    if (!changed.empty() && !force) {
      std::string list;
      for (const std::string& m : changed) {
        const auto was = previous->methodIdentities.find(m);
        list += fmt::format("{}{} ({} then, {} now)", list.empty() ? "" : "; ", m,
                            was == previous->methodIdentities.end() ? "unrecorded" : was->second,
                            manifest.methodIdentities.at(m));
      }
      throw InputError(folder.root().string() + " holds results of methods whose code has " +
                       "changed since: " + list +
                       "; use another --out, or --force to run their jobs again");
    }
    for (const std::string& m : changed)
      folder.removeJobsOf(m);
    // The folder keeps saying which code made the results of methods this batch leaves alone.
    for (const auto& [method, identity] : previous->methodIdentities)
      manifest.methodIdentities.emplace(method, identity);
  }
  folder.removeStaleTemporaries();
  folder.writeManifest(manifest);
}

}  // namespace camcov::batch
