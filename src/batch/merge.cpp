#include "batch/merge.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>

#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "records/run_files.h"
#include "util/input_error.h"

namespace camcov::batch {

namespace fs = std::filesystem;

namespace {

// The files of a source's runs/ to copy, each checked first: a damaged run is named in its
// source folder before anything is copied. A run's JSON comes after its CSV: a run counts as
// finished when its JSON exists, so a killed merge resumes like a killed batch.
std::vector<fs::path> checkedRunFiles(const records::BatchFolder& source) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(source.runsDir(), ec)) {
    if (records::isTemporaryFile(entry.path())) continue;
    if (entry.path().extension() == ".json" && entry.path().stem().extension() != ".error")
      records::loadRunFile(entry.path());  // InputError naming the file if it is damaged
    files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return std::pair(a.extension() == ".json", a) < std::pair(b.extension() == ".json", b);
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

}  // namespace

records::BatchManifest mergeFolders(const std::vector<std::string>& inputs,
                                    const records::BatchFolder& target,
                                    const std::vector<std::string>& command) {
  // Everything is read and checked before anything is written.
  target.refuseForeignContent();
  std::optional<records::BatchManifest> manifest;
  std::map<std::string, records::JobTiming> timings;
  std::vector<std::pair<fs::path, fs::path>> copies;  // from, to
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
    }
    for (const auto& [stem, t] : source.readTimings())
      timings[stem] = t;
    if (fs::exists(target.runsDir()) && fs::equivalent(source.runsDir(), target.runsDir()))
      continue;
    for (const fs::path& file : checkedRunFiles(source))
      copies.emplace_back(file, target.runsDir() / file.filename());
  }
  if (!manifest) throw InputError("merge: no folders to combine");
  for (const auto& [from, to] : copies)
    records::copyFileAtomically(from, to);
  manifest->command = command;
  target.writeManifest(*manifest);
  target.writeTimings(timings);
  return *manifest;
}

}  // namespace camcov::batch
