#include "records/video_choice.h"

#include <algorithm>

#include "util/input_error.h"

namespace camcov::records {

VideoChoice parseVideoChoice(const std::string& text, const std::string& option) {
  if (text == "none") return VideoChoice::None;
  if (text == "median") return VideoChoice::Median;
  if (text == "best") return VideoChoice::Best;
  if (text == "all") return VideoChoice::All;
  throw InputError(option + " " + text + ": expected none, median, best or all");
}

std::vector<VideoRun> chooseVideoRuns(const BatchSummary& summary,
                                      std::span<const JobOutcome> outcomes, VideoChoice choice) {
  std::vector<VideoRun> chosen;
  if (choice == VideoChoice::None) return chosen;
  for (const MethodSummary& m : summary.methods) {
    if (m.runs == 0) continue;
    if (choice != VideoChoice::All) {
      chosen.push_back(
          {m.scene, m.method, choice == VideoChoice::Best ? m.bestSeed : m.medianSeed});
      continue;
    }
    const std::size_t first = chosen.size();
    for (const JobOutcome& job : outcomes) {
      if (!job.failed && job.scene == m.scene && job.method == m.method) {
        chosen.push_back({job.scene, job.method, job.seed});
      }
    }
    std::sort(chosen.begin() + first, chosen.end(),
              [](const VideoRun& a, const VideoRun& b) { return a.seed < b.seed; });
  }
  return chosen;
}

}  // namespace camcov::records
