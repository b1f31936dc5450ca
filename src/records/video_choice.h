#pragma once
// Which runs of a batch become videos (`camcov bench --videos`). A report reader wants to see
// what a typical run of each method looks like on each scene, so the default is the
// median-seed run of every (scene, method): not a lucky or an unlucky one.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "records/batch_summary.h"

namespace camcov::records {

enum class VideoChoice {
  None,    // no videos
  Median,  // per (scene, method): MethodSummary::medianSeed
  Best,    // per (scene, method): MethodSummary::bestSeed
  All,     // every finished run
};

// "none", "median", "best" or "all"; InputError naming `option` (the one it was given as,
// "--videos" or "--explorer") otherwise.
VideoChoice parseVideoChoice(const std::string& text, const std::string& option);

struct VideoRun {
  std::string scene;
  std::string method;
  std::uint64_t seed = 0;
  friend bool operator==(const VideoRun&, const VideoRun&) = default;
};

// The chosen runs, in the summary's (scene, method) order and by seed within one; failed jobs
// are never chosen. `summary` is summarize(outcomes, reference).
std::vector<VideoRun> chooseVideoRuns(const BatchSummary& summary,
                                      std::span<const JobOutcome> outcomes, VideoChoice choice);

}  // namespace camcov::records
