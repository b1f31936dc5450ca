#include "reports/report_data.h"

#include "control/event_kind.h"

#include <algorithm>

#include "kinematics/object_overlaps.h"
#include "records/batch_summary_file.h"
#include "records/run_files.h"
#include "reports/markup.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/natural_order.h"

namespace camcov::reports {
namespace {

namespace fs = std::filesystem;

bool startsWith(const std::string& s, std::string_view prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

// Widens [min, max] at every step by one more seed's values; the band is as long as the
// shortest run.
void foldRange(SeriesBand& band, const std::vector<double>& values, bool first) {
  if (first) {
    band.min = band.max = values;
    return;
  }
  const std::size_t n = std::min(band.min.size(), values.size());
  band.min.resize(n);
  band.max.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    band.min[k] = std::min(band.min[k], values[k]);
    band.max[k] = std::max(band.max[k], values[k]);
  }
}

bool isContact(const control::ControlEvent& e) {
  const control::EventMark mark = control::markOf(e);
  return mark == control::EventMark::AvoidableContact ||
         mark == control::EventMark::UnavoidableContact;
}

MethodRuns loadMethodRuns(const records::BatchFolder& folder, const std::string& scene,
                          const std::string& method, std::uint64_t seeds,
                          std::uint64_t medianSeed) {
  MethodRuns runs;
  runs.medianSeed = medianSeed;
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    records::RunMetadata id;
    id.scene = scene;
    id.method = method;
    id.seed = seed;
    const fs::path file = folder.runFile(records::runStem(id));
    if (!fs::exists(file)) continue;  // failed, or not run by this shard
    records::RunRecord run = records::loadRunFile(file);
    runs.averageCoverage.push_back(run.summary.averageCoverage);
    runs.averageUtilization.push_back(run.summary.averageUtilization);
    std::vector<double> coverage, utilization;
    for (const auto& step : run.steps) {
      coverage.push_back(step.terms.coverage);
      utilization.push_back(step.terms.utilization);
    }
    for (const auto& e : run.events) {
      if (isContact(e)) runs.contacts.emplace_back(seed, e);
    }
    const bool first = runs.averageCoverage.size() == 1;
    foldRange(runs.coverage, coverage, first);
    foldRange(runs.utilization, utilization, first);
    if (seed == medianSeed) {
      for (const auto& step : run.steps)
        runs.time.push_back(step.time);
      runs.coverage.median = std::move(coverage);
      runs.utilization.median = std::move(utilization);
      runs.events = std::move(run.events);
      for (const auto& step : run.steps) {
        if (step.targetsPresent >= 0) runs.targetsPresent.push_back(step.targetsPresent);
      }
      for (auto& e : runs.events)
        e.path.clear();
    }
  }
  return runs;
}

void loadScene(const records::SceneEntry& entry, const params::SimParams& run, SceneData& data) {
  if (!fs::exists(entry.file)) {
    data.sceneNote =
        "scene file " + entry.file + " not found (batch.json names it as given to camcov bench)";
    return;
  }
  try {
    scene::SceneFile file = scene::loadSceneFile(entry.file);
    data.scene = std::move(file.scene);
    data.warnings = data.scene->warnings;
    for (const auto& o : kinematics::findObjectOverlaps(*data.scene, run.duration, run.dt))
      data.warnings.push_back(kinematics::describeOverlap(o));
    if (file.hash != entry.hash)
      data.sceneNote = entry.file + " changed since the batch ran; drawn as it is now";
  } catch (const InputError& e) {
    data.sceneNote = e.what();
  }
}

// The offline optimum the bench searched for this scene, if any and if it was made from the
// scene file the runs were (an unreadable one is left out: it is a reference, not a result).
std::optional<records::OptimumFile> findOptimum(const records::BatchFolder& folder,
                                                const records::SceneEntry& entry) {
  const fs::path file = folder.optimumFile(entry.name);
  if (!fs::exists(file)) return std::nullopt;
  try {
    records::OptimumFile optimum = records::loadOptimumFile(file);
    if (optimum.sceneHash == entry.hash) return optimum;
  } catch (const InputError&) {
  }
  return std::nullopt;
}

std::vector<std::string> findVideos(const fs::path& resultsDir, const fs::path& reportDir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry :
       fs::directory_iterator(records::BatchFolder(resultsDir).videosDir(), ec)) {
    if (entry.is_regular_file() && entry.path().extension() == ".mp4") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return naturalLess(a.filename().string(), b.filename().string());
  });
  std::vector<std::string> urls;
  for (const auto& f : files)
    urls.push_back(relativeUrl(f, reportDir));
  return urls;
}

}  // namespace

SceneGroup sceneGroup(const std::string& name, const scene::Scene* scene) {
  if (startsWith(name, "static")) return SceneGroup::Static;
  if (startsWith(name, "dynamic")) return SceneGroup::Dynamic;
  if (scene == nullptr) return SceneGroup::Other;
  if (scene->hasPresenceWindows()) return SceneGroup::Recorded;
  return scene->holdsStill() ? SceneGroup::Static : SceneGroup::Dynamic;
}

const char* groupName(SceneGroup group) {
  switch (group) {
    case SceneGroup::Static:
      return "static";
    case SceneGroup::Dynamic:
      return "dynamic";
    case SceneGroup::Recorded:
      return "recorded";
    case SceneGroup::Other:
      break;
  }
  return "other";
}

const char* groupTitle(SceneGroup group) {
  switch (group) {
    case SceneGroup::Static:
      return "Static scenes";
    case SceneGroup::Dynamic:
      return "Dynamic scenes";
    case SceneGroup::Recorded:
      return "Recorded people";
    case SceneGroup::Other:
      break;
  }
  return "Other scenes";
}

ReportData loadReportData(const fs::path& resultsDir, const fs::path& reportFile) {
  const records::BatchFolder folder(resultsDir);
  auto manifest = folder.readManifest();
  if (!manifest) {
    throw InputError(resultsDir.string() + ": not a camcov results folder (no batch.json)");
  }
  ReportData data;
  data.manifest = std::move(*manifest);
  data.summary = records::loadSummaryFile(folder.summaryFile());
  data.timings = folder.readTimings();
  for (const std::string& name : data.summary.scenes) {
    SceneData scene;
    scene.name = name;
    const auto entry = std::find_if(data.manifest.scenes.begin(), data.manifest.scenes.end(),
                                    [&](const records::SceneEntry& e) { return e.name == name; });
    if (entry != data.manifest.scenes.end()) {
      loadScene(*entry, data.manifest.parameters.sim, scene);
      scene.optimum = findOptimum(folder, *entry);
    } else {
      scene.sceneNote = "not listed in batch.json";
    }
    scene.group = sceneGroup(scene.name, scene.scene ? &*scene.scene : nullptr);
    if (const fs::path page = folder.explorerPage(name); fs::exists(page)) {
      scene.explorerUrl = relativeUrl(page, reportFile.parent_path());
    }
    for (const auto& m : data.summary.methods) {
      if (m.scene != scene.name || m.runs == 0) continue;
      scene.methods[m.method] =
          loadMethodRuns(folder, scene.name, m.method, data.manifest.seeds, m.medianSeed);
    }
    data.scenes.push_back(std::move(scene));
  }
  data.videos = findVideos(resultsDir, reportFile.parent_path());
  return data;
}

}  // namespace camcov::reports
