#pragma once
// Everything the report shows, read from a results folder (src/records/batch_folder.h): the
// manifest, the summary, the timings, each scene's file, and per scene and method what the
// figures need of the runs: every seed's average coverage and utilization (Fig. 4), the
// median-seed run's time series and events plus the band over all seeds (Fig. 5). Runs are
// read one at a time and folded, so a large batch does not sit in memory.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "control/controller.h"
#include "records/batch_folder.h"
#include "records/batch_summary.h"
#include "records/optimum_file.h"
#include "scene/scene.h"

namespace camcov::reports {

// One metric over time: the median-seed run's values and the range over every seed.
struct SeriesBand {
  std::vector<double> median;
  std::vector<double> min;
  std::vector<double> max;
};

struct MethodRuns {
  std::uint64_t medianSeed = 0;
  std::vector<double> averageCoverage;  // one per finished seed, eq. (4)
  std::vector<double> averageUtilization;
  std::vector<double> time;  // the median-seed run's steps, s
  SeriesBand coverage;
  SeriesBand utilization;
  std::vector<control::ControlEvent> events;  // of the median-seed run, paths dropped
  std::vector<int> targetsPresent;  // of the median-seed run; empty unless targets come and go
  // The start of every contact closer than δ in any seed ("avoidable-contact" and
  // "unavoidable-contact" events), with its seed: rare, and each one worth seeing.
  std::vector<std::pair<std::uint64_t, control::ControlEvent>> contacts;
};

// Recorded: people from recorded tracks, who come and go (scene::Track).
enum class SceneGroup { Static, Dynamic, Recorded, Other };
inline constexpr SceneGroup kSceneGroups[] = {SceneGroup::Static, SceneGroup::Dynamic,
                                              SceneGroup::Recorded,
                                              SceneGroup::Other};  // in report order

struct SceneData {
  std::string name;
  SceneGroup group = SceneGroup::Other;
  std::optional<scene::Scene> scene;  // empty if its file cannot be read any more
  std::string sceneNote;              // why the scene is missing, or that its file changed
  // What the loader warned of, then objects that pass through each other during the run
  // (sampled every step; kinematics/object_overlaps.h).
  std::vector<std::string> warnings;
  std::map<std::string, MethodRuns> methods;  // by method name
  std::string explorerUrl;  // explore/<scene>.html relative to the report; empty if none
  // optimum/<scene>.json when it was made from the scene the batch ran.
  std::optional<records::OptimumFile> optimum;
};

struct ReportData {
  records::BatchManifest manifest;
  records::BatchSummary summary;
  std::map<std::string, records::JobTiming> timings;
  std::vector<SceneData> scenes;    // one per summary.scenes[i] (natural order)
  std::vector<std::string> videos;  // relative URLs of videos/*.mp4, natural order
};

// The published benchmark's names say it ("static7", "dynamic9"); other scenes are Recorded
// when their targets come and go, static when nothing in them moves, turns or deforms, and
// Other when unreadable.
SceneGroup sceneGroup(const std::string& name, const scene::Scene* scene);
const char* groupName(SceneGroup group);   // "static", for attributes
const char* groupTitle(SceneGroup group);  // "Static scenes", for headings

// Reads `resultsDir`; `reportFile` is where the report will be written, for relative URLs.
// Throws InputError if the folder has no batch.json or summary.json.
ReportData loadReportData(const std::filesystem::path& resultsDir,
                          const std::filesystem::path& reportFile);

}  // namespace camcov::reports
