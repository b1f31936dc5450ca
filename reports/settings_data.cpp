#include "reports/settings_data.h"
#include "control/methods.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "params/parameter_table.h"
#include "records/batch_folder.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/natural_order.h"

namespace camcov::reports {
namespace {

namespace fs = std::filesystem;

Setting readSetting(const fs::path& folder, const fs::path& reportDir) {
  const records::BatchFolder batch(folder);
  auto manifest = batch.readManifest();
  if (!manifest) {
    throw InputError(folder.string() + ": not a camcov results folder (no batch.json)");
  }
  Setting s;
  s.folder = folder;
  fs::path path = fs::absolute(folder).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();  // "out/"
  s.name = path.filename().string();
  s.manifest = std::move(*manifest);
  for (const records::JobOutcome& job : batch.allJobs()) {
    SettingRuns& runs = s.runs[job.scene][job.method];
    if (job.failed) {
      ++runs.failed;
      continue;
    }
    runs.averageCoverage.push_back(job.summary.averageCoverage);
    runs.averageUtilization.push_back(job.summary.averageUtilization);
  }
  if (const fs::path report = records::BatchFolder(folder).reportFile(); fs::exists(report))
    s.reportUrl = relativeUrl(report, reportDir);
  return s;
}

// Two settings with the same folder name (".../a/merged", ".../b/merged") are told apart by
// the paths as given.
void disambiguateNames(std::vector<Setting>& settings, const std::vector<fs::path>& folders) {
  std::map<std::string, int> count;
  for (const auto& s : settings)
    ++count[s.name];
  for (std::size_t i = 0; i < settings.size(); ++i) {
    if (count[settings[i].name] > 1) settings[i].name = folders[i].string();
  }
}

std::vector<DifferingParameter> differingParameters(const std::vector<Setting>& settings) {
  std::vector<DifferingParameter> out;
  for (const params::ParamField& f : params::parameterTable()) {
    // Our extensions have no symbol in the paper: their key names them.
    DifferingParameter d{f.key, *f.symbol != '\0' ? f.symbol : f.key, {}};
    for (const auto& s : settings)
      d.values.push_back(params::formatValue(f, f.get(s.manifest.parameters)));
    if (std::adjacent_find(d.values.begin(), d.values.end(), std::not_equal_to<>()) !=
        d.values.end()) {
      out.push_back(std::move(d));
    }
  }
  return out;
}

std::string listed(const std::vector<std::string>& items) {
  return items.empty() ? "none" : join(items, ", ");
}

// What else differs between the settings, each as one sentence: a column of the report is
// only a fair comparison when these are empty.
std::vector<std::string> otherDifferences(const std::vector<Setting>& settings) {
  std::vector<std::string> notes;
  const Setting& first = settings.front();
  for (std::size_t i = 1; i < settings.size(); ++i) {
    const Setting& s = settings[i];
    if (s.manifest.toolVersion != first.manifest.toolVersion) {
      notes.push_back(fmt::format("{} was run by camcov {}, {} by camcov {}.", first.name,
                                  first.manifest.toolVersion, s.name, s.manifest.toolVersion));
    }
    if (s.manifest.methods != first.manifest.methods) {
      notes.push_back(fmt::format("{} ran the methods {}, {} ran {}.", first.name,
                                  listed(first.manifest.methods), s.name,
                                  listed(s.manifest.methods)));
    }
    if (s.manifest.seeds != first.manifest.seeds) {
      notes.push_back(fmt::format("{} ran seeds 1–{}, {} seeds 1–{}.", first.name,
                                  first.manifest.seeds, s.name, s.manifest.seeds));
    }
    std::vector<std::string> onlyFirst, onlyHere, changed;
    for (const auto& a : first.manifest.scenes) {
      const auto b = std::find_if(s.manifest.scenes.begin(), s.manifest.scenes.end(),
                                  [&](const records::SceneEntry& e) { return e.name == a.name; });
      if (b == s.manifest.scenes.end()) {
        onlyFirst.push_back(a.name);
      } else if (b->hash != a.hash) {
        changed.push_back(a.name);
      }
    }
    for (const auto& b : s.manifest.scenes) {
      if (std::none_of(first.manifest.scenes.begin(), first.manifest.scenes.end(),
                       [&](const records::SceneEntry& e) { return e.name == b.name; })) {
        onlyHere.push_back(b.name);
      }
    }
    if (!onlyFirst.empty() || !onlyHere.empty()) {
      notes.push_back(fmt::format("Scenes only in {}: {}; only in {}: {}.", first.name,
                                  listed(onlyFirst), s.name, listed(onlyHere)));
    }
    if (!changed.empty()) {
      notes.push_back(fmt::format(
          "The scene files of {} differ between {} and {} (another hash): their columns compare "
          "different scenes.",
          join(changed, ", "), first.name, s.name));
    }
  }
  return notes;
}

SceneGroup groupOf(const std::string& name, const std::vector<Setting>& settings) {
  for (const auto& s : settings) {
    for (const auto& entry : s.manifest.scenes) {
      if (entry.name != name || !fs::exists(entry.file)) continue;
      try {
        const scene::SceneFile file = scene::loadSceneFile(entry.file);
        return sceneGroup(name, &file.scene);
      } catch (const InputError&) {
        // An unreadable file says nothing about the scene; try another setting's.
      }
    }
  }
  return sceneGroup(name, nullptr);
}

}  // namespace

std::vector<fs::path> resultsFoldersIn(const fs::path& root) {
  std::vector<fs::path> folders;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(root, ec)) {
    if (entry.is_directory() && records::BatchFolder::holdsBatch(entry.path())) {
      folders.push_back(entry.path());
    }
  }
  if (folders.empty()) {
    throw InputError(root.string() +
                     ": not a camcov results folder (no batch.json), and no folder in it is one");
  }
  std::sort(folders.begin(), folders.end(), [](const fs::path& a, const fs::path& b) {
    return naturalLess(a.filename().string(), b.filename().string());
  });
  return folders;
}

SettingsData loadSettingsData(const std::vector<fs::path>& folders, const std::string& reference,
                              const fs::path& reportFile) {
  if (folders.empty()) throw InputError("no results folder given");
  SettingsData data;
  for (const auto& folder : folders)
    data.settings.push_back(readSetting(folder, reportFile.parent_path()));
  disambiguateNames(data.settings, folders);
  if (!reference.empty()) {
    const auto it = std::find_if(data.settings.begin(), data.settings.end(), [&](const Setting& s) {
      return s.name == reference || s.folder.string() == reference;
    });
    if (it == data.settings.end()) {
      std::vector<std::string> names;
      for (const auto& s : data.settings)
        names.push_back(s.name);
      throw InputError(fmt::format("--reference-setting {}: not one of the settings ({})",
                                   reference, join(names, ", ")));
    }
    data.reference = static_cast<std::size_t>(it - data.settings.begin());
  }
  data.parameters = differingParameters(data.settings);
  for (std::size_t i = 0; i < data.settings.size(); ++i) {
    std::vector<std::string> parts;
    for (const auto& d : data.parameters)
      parts.push_back(d.symbol + "=" + d.values[i]);
    data.settings[i].label = parts.empty() ? data.settings[i].name : join(parts, " ");
  }
  data.notes = otherDifferences(data.settings);
  std::set<std::string> scenes, methods;
  for (const auto& s : data.settings) {
    for (const auto& [scene, byMethod] : s.runs) {
      scenes.insert(scene);
      for (const auto& [method, runs] : byMethod)
        methods.insert(method);
    }
  }
  data.scenes.assign(scenes.begin(), scenes.end());
  std::sort(data.scenes.begin(), data.scenes.end(),
            [](const std::string& a, const std::string& b) { return naturalLess(a, b); });
  for (const auto& scene : data.scenes)
    data.groups[scene] = groupOf(scene, data.settings);
  data.methods = control::inMethodOrder({methods.begin(), methods.end()});
  return data;
}

}  // namespace camcov::reports
