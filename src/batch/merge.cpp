#include "batch/merge.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "records/run_files.h"
#include "util/input_error.h"

namespace camcov::batch {

namespace fs = std::filesystem;

namespace {

// A file of a source's runs/ to copy; a run's metadata, read when it was checked.
struct RunFileEntry {
  fs::path path;
  std::optional<records::RunMetadata> run;  // for a run's JSON (not its CSV or a failure)
};

// The files of a source's runs/ to copy, each checked first: a damaged run is named in its
// source folder before anything is copied. A run's JSON comes after its CSV: a run counts as
// finished when its JSON exists, so a killed merge resumes like a killed batch.
std::vector<RunFileEntry> checkedRunFiles(const records::BatchFolder& source) {
  std::vector<RunFileEntry> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(source.runsDir(), ec)) {
    if (records::isTemporaryFile(entry.path())) continue;
    RunFileEntry file{entry.path(), std::nullopt};
    if (entry.path().extension() == ".json" && entry.path().stem().extension() != ".error") {
      const records::RunRecord run = records::loadRunFile(entry.path());  // InputError if damaged
      if (!records::runCsvIsWhole(run, entry.path())) {
        throw InputError(entry.path().string() +
                         ": its CSV is missing or cut short (the machine stopped while the batch "
                         "ran?); run the batch there again (camcov bench resumes it)");
      }
      file.run = run.metadata;
    }
    files.push_back(std::move(file));
  }
  std::sort(files.begin(), files.end(), [](const RunFileEntry& a, const RunFileEntry& b) {
    return std::pair(a.path.extension() == ".json", a.path) <
           std::pair(b.path.extension() == ".json", b.path);
  });
  return files;
}

// The manifests agree on what made the results: the parameters and each method's code.
void requireSameMaking(const records::BatchManifest& m, const records::BatchManifest& first,
                       const std::string& input, const std::string& firstInput) {
  if (params::toJson(m.parameters) != params::toJson(first.parameters))
    throw InputError(input + ": made with other parameters than " + firstInput);
  for (const auto& [method, identity] : m.methodIdentities) {
    const auto there = first.methodIdentities.find(method);
    if (there != first.methodIdentities.end() && there->second != identity) {
      throw InputError(fmt::format("{}: its {} results were made by other code ({}) than {}'s ({})",
                                   input, method, identity, firstInput, there->second));
    }
  }
}

// What a run file holds matches the merged batch's plan: its name is its job's, of a scene the
// batch holds (the same file, by hash), a method and seed it ran, with its parameters; so that
// a run renamed from another scene or another batch cannot pass for one of this batch's.
void requireRunOfPlan(const fs::path& file, const records::RunMetadata& m,
                      const records::BatchManifest& manifest) {
  const auto scene = std::find_if(manifest.scenes.begin(), manifest.scenes.end(),
                                  [&](const records::SceneEntry& s) { return s.name == m.scene; });
  std::string wrong;
  if (file.stem().string() != records::runStem(m)) {
    wrong = "its name is not its job's (" + records::runStem(m) + ")";
  } else if (scene == manifest.scenes.end() || scene->hash != m.sceneHash) {
    wrong = "its scene " + m.scene + " is not one the batch ran (or the file changed since)";
  } else if (std::find(manifest.methods.begin(), manifest.methods.end(), m.method) ==
                 manifest.methods.end() ||
             m.seed < 1 || m.seed > manifest.seeds) {
    wrong = fmt::format("method {} seed {} is not a job of the batch", m.method, m.seed);
  } else if (params::toJson(m.parameters) != params::toJson(manifest.parameters)) {
    wrong = "it was made with other parameters";
  }
  if (!wrong.empty()) throw InputError(file.string() + ": not a run of this batch: " + wrong);
}

// Every job of the merged plan (scene × method × seed) has a run or a recorded failure among
// `stems`: a missing shard, a shard of another split or a deleted run is named, not merged into
// a summary of fewer runs than it says.
void requireEveryJob(const records::BatchManifest& manifest, const std::set<std::string>& stems) {
  std::vector<std::string> missing;
  std::size_t jobs = 0;
  for (const records::SceneEntry& scene : manifest.scenes) {
    for (const std::string& method : manifest.methods) {
      for (std::uint64_t seed = 1; seed <= manifest.seeds; ++seed, ++jobs) {
        const std::string stem = records::runStem(scene.name, method, seed);
        if (!stems.contains(stem) && !stems.contains(stem + ".error")) missing.push_back(stem);
      }
    }
  }
  if (missing.empty()) return;
  throw InputError(fmt::format(
      "merge: {} of {} jobs have no run in any folder given (first: {}): a shard or a run is "
      "missing; run the batch there again (camcov bench resumes it) or merge every shard",
      missing.size(), jobs, missing.front()));
}

}  // namespace

records::BatchManifest mergeFolders(const std::vector<std::string>& inputs,
                                    const records::BatchFolder& target,
                                    const std::vector<std::string>& command) {
  // Everything is read and checked before anything is written.
  target.refuseForeignContent();
  std::optional<records::BatchManifest> manifest;
  std::map<std::string, records::JobTiming> timings;
  std::vector<std::pair<fs::path, fs::path>> copies;  // from, to
  std::vector<RunFileEntry> runs;                     // every input's run and failure files
  for (const auto& input : inputs) {
    const records::BatchFolder source(input);
    const auto m = source.readManifest();
    if (!m) throw InputError(input + ": not a camcov bench folder (no batch.json)");
    if (!manifest) {
      manifest = m;
    } else {
      requireSameMaking(*m, *manifest, input, inputs.front());
      for (const auto& scene : m->scenes) {
        const bool known = std::any_of(manifest->scenes.begin(), manifest->scenes.end(),
                                       [&](const auto& s) { return s.name == scene.name; });
        if (!known) manifest->scenes.push_back(scene);
      }
      for (const auto& [method, identity] : m->methodIdentities)
        manifest->methodIdentities.emplace(method, identity);
      // The merged plan is every folder's: each of their jobs must then have its run.
      for (const std::string& method : m->methods) {
        if (std::find(manifest->methods.begin(), manifest->methods.end(), method) ==
            manifest->methods.end())
          manifest->methods.push_back(method);
      }
      manifest->seeds = std::max(manifest->seeds, m->seeds);
      for (const auto& [method, look] : m->methodLooks)
        manifest->methodLooks.emplace(method, look);
    }
    for (const auto& [stem, t] : source.readTimings())
      timings[stem] = t;
    std::vector<RunFileEntry> files = checkedRunFiles(source);
    const bool inPlace =
        fs::exists(target.runsDir()) && fs::equivalent(source.runsDir(), target.runsDir());
    for (RunFileEntry& file : files) {
      if (!inPlace) copies.emplace_back(file.path, target.runsDir() / file.path.filename());
      if (file.path.extension() == ".json") runs.push_back(std::move(file));
    }
  }
  if (!manifest) throw InputError("merge: no folders to combine");
  std::set<std::string> stems;
  for (const RunFileEntry& file : runs) {
    if (file.run) requireRunOfPlan(file.path, *file.run, *manifest);
    stems.insert(file.path.stem().string());
  }
  requireEveryJob(*manifest, stems);
  for (const auto& [from, to] : copies)
    records::copyFileAtomically(from, to);
  manifest->command = command;
  target.writeManifest(*manifest);
  target.writeTimings(timings);
  return *manifest;
}

}  // namespace camcov::batch
